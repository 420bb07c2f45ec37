// Stokes vectors through one interface (docs/optics.md, "Polarisation"): the frame rotation, the Mueller
// matrices of the Fresnel amplitudes against the electric field itself, and the closed forms: Brewster's
// angle, the phase of total internal reflection, the Fresnel rhomb, normal incidence, power conservation.
#include "optics/Fresnel.hpp"
#include "optics/Polarisation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

namespace dropscope {
namespace {

using Complex = std::complex<double>;
using Field = Eigen::Matrix<Complex, 3, 1>;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// A unit vector perpendicular to d.
Eigen::Vector3d across(const Direction& d) { return d.vector().unitOrthogonal(); }

// The Stokes vector of a complex field E (perpendicular to k) in the frame with parallel axis `reference`,
// straight from the definitions (Bohren and Huffman 2.84): no rotation formula involved.
StokesVector stokesOfField(const Field& e, const Eigen::Vector3d& reference, const Direction& k) {
    const Eigen::Vector3d perpendicular = reference.cross(k.vector());
    const Complex par = e.dot(reference.cast<Complex>());  // Eigen's dot conjugates its first argument...
    const Complex perp = e.dot(perpendicular.cast<Complex>());
    const Complex ePar = std::conj(par);  // ...so conjugate back: the component E . reference
    const Complex ePerp = std::conj(perp);
    return {std::norm(ePar) + std::norm(ePerp), std::norm(ePar) - std::norm(ePerp),
            2.0 * (ePar * std::conj(ePerp)).real(), -2.0 * (ePar * std::conj(ePerp)).imag()};
}

// A fully polarised field along k with Stokes parameters of the given azimuth and ellipticity in the frame
// of `reference`: E = cos(chi) e(psi) + i sin(chi) e(psi + 90 deg), e(a) = cos a ref + sin a (ref x k).
Field fieldOf(double psi, double chi, const Eigen::Vector3d& reference, const Direction& k) {
    const Eigen::Vector3d perpendicular = reference.cross(k.vector());
    const Eigen::Vector3d major = std::cos(psi) * reference + std::sin(psi) * perpendicular;
    const Eigen::Vector3d minor = -std::sin(psi) * reference + std::cos(psi) * perpendicular;
    return major.cast<Complex>() * std::cos(chi) + minor.cast<Complex>() * Complex(0.0, -std::sin(chi));
}

void expectStokesNear(const StokesVector& actual, const StokesVector& expected, double tolerance) {
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(actual[k], expected[k], tolerance) << "component " << k;
}

TEST(StokesFrame, TurningTheAxesTurnsQAndUByTwiceTheAngle) {
    const Direction k(0, 0, 1);
    const Polarisation light{{1.0, 0.6, 0.0, 0.3}, Eigen::Vector3d::UnitX()};  // 60 % polarised along x
    // The perpendicular axis x cross z = -y: light along x seen from the frame of -y (or +y) is Q = -0.6.
    expectStokesNear(stokesInFrame(light, k, Eigen::Vector3d::UnitY()), {1.0, -0.6, 0.0, 0.3}, 1e-15);
    expectStokesNear(stokesInFrame(light, k, -Eigen::Vector3d::UnitX()), {1.0, 0.6, 0.0, 0.3}, 1e-15);
    // 45 degrees towards the perpendicular axis: all of Q becomes U, with the sign of sin 2psi.
    const Eigen::Vector3d diagonal = (Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).normalized();
    expectStokesNear(stokesInFrame(light, k, diagonal), {1.0, 0.0, -0.6, 0.3}, 1e-15);
}

TEST(StokesFrame, AgreesWithTheFieldInAnyFrame) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Direction k(unit(random), unit(random), unit(random));
        const Eigen::Vector3d a = across(k);
        const Eigen::Vector3d b = (a + 0.7 * unit(random) * a.cross(k.vector())).normalized();
        const Field e = fieldOf(3.0 * unit(random), 0.7 * unit(random), a, k);
        const Polarisation light{stokesOfField(e, a, k), a};
        expectStokesNear(stokesInFrame(light, k, b), stokesOfField(e, b, k), 1e-14);
        EXPECT_NEAR(degreeOfLinearPolarisation(stokesInFrame(light, k, b)), degreeOfLinearPolarisation(light.stokes),
                    1e-14);
    }
}

// An interface between n1 and n2 with normal N = +z, crossed from below by a ray in the plane of k and N
// turned by `azimuth` about z, at angle `incidence`; the light's frame is an arbitrary axis across k.
struct Crossing {
    Direction incident, normal, reflected, transmitted;
    double cosIncidence;
    FresnelAmplitudes amplitudes;
};

Crossing crossing(double incidence, double azimuth, double n1, double n2) {
    const Eigen::Vector3d side(std::cos(azimuth), std::sin(azimuth), 0.0);
    Crossing c;
    c.incident = Direction(std::sin(incidence) * side + std::cos(incidence) * Eigen::Vector3d::UnitZ());
    c.normal = Direction(0, 0, 1);
    c.reflected = Direction(std::sin(incidence) * side - std::cos(incidence) * Eigen::Vector3d::UnitZ());
    c.cosIncidence = std::cos(incidence);
    c.amplitudes = fresnelAmplitudes(c.cosIncidence, n1, n2);
    const double sinT = n1 / n2 * std::sin(incidence);
    if (sinT < 1.0) c.transmitted = Direction(sinT * side + std::sqrt(1 - sinT * sinT) * Eigen::Vector3d::UnitZ());
    return c;
}

// The reflected and transmitted fields by the Fresnel amplitudes on the field itself: s = k x N, each beam's
// p = k x s, E_s and E_p scaled by r or t (the convention of docs/optics.md, derived there).
Field reflectedField(const Field& e, const Crossing& c) {
    const Eigen::Vector3d s = c.incident.vector().cross(c.normal.vector()).normalized();
    const Complex es = e.dot(s.cast<Complex>());  // conjugated: E . s is its conjugate; both real axes
    const Complex ep = e.dot(c.incident.vector().cross(s).cast<Complex>());
    return s.cast<Complex>() * (c.amplitudes.rs * std::conj(es)) +
           c.reflected.vector().cross(s).cast<Complex>() * (c.amplitudes.rp * std::conj(ep));
}

Field transmittedField(const Field& e, const Crossing& c) {
    const Eigen::Vector3d s = c.incident.vector().cross(c.normal.vector()).normalized();
    const Complex es = e.dot(s.cast<Complex>());
    const Complex ep = e.dot(c.incident.vector().cross(s).cast<Complex>());
    return s.cast<Complex>() * (c.amplitudes.ts * std::conj(es)) +
           c.transmitted.vector().cross(s).cast<Complex>() * (c.amplitudes.tp * std::conj(ep));
}

TEST(InterfaceStokes, MuellerMatricesAgreeWithTheFresnelFieldsInEveryFrame) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [n1, n2] : {std::pair{1.0, 1.3337}, std::pair{1.5, 1.0}, std::pair{1.3337, 1.5}}) {
        for (int trial = 0; trial < 300; ++trial) {
            const Crossing c = crossing(radians(89.0 * unit(random)), 6.3 * unit(random), n1, n2);
            const Eigen::Vector3d frame =
                Eigen::AngleAxisd(6.3 * unit(random), c.incident.vector()) * across(c.incident);
            const Field e = fieldOf(6.3 * unit(random), 1.5 * unit(random) - 0.75, frame, c.incident);
            const Polarisation light{stokesOfField(e, frame, c.incident), frame};
            const PlaneOfIncidence plane = planeOfIncidence(light, c.incident, c.normal);
            const Polarisation reflected = reflectedPolarisation(plane, c.amplitudes, c.reflected);
            expectStokesNear(reflected.stokes, stokesOfField(reflectedField(e, c), reflected.reference, c.reflected),
                             1e-13);
            EXPECT_NEAR(polarisedReflectance(plane, c.amplitudes), reflected.stokes[0] / light.stokes[0], 1e-14);
            if (c.amplitudes.totalInternalReflection) continue;
            const Polarisation transmitted = transmittedPolarisation(plane, c.amplitudes, c.transmitted);
            // The power: |E_t|^2 times n2 cos(theta_t) / (n1 cos(theta_i)).
            StokesVector expected = stokesOfField(transmittedField(e, c), transmitted.reference, c.transmitted);
            expected *= c.amplitudes.transmittedPower;
            expectStokesNear(transmitted.stokes, expected, 1e-13);
        }
    }
}

TEST(InterfaceStokes, EveryStateKeepsItsPowerBetweenTheTwoBeams) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const auto& [n1, n2] : {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}, std::pair{1.0, 2.4}}) {
        for (int trial = 0; trial < 2000; ++trial) {
            const Crossing c = crossing(radians(90.0 * std::abs(unit(random))), 3.2 * unit(random), n1, n2);
            StokesVector stokes(1.0, unit(random), unit(random), unit(random));
            stokes.tail<3>() *= std::abs(unit(random)) / stokes.tail<3>().norm();  // any degree of polarisation
            const Polarisation light{stokes, across(c.incident)};
            const PlaneOfIncidence plane = planeOfIncidence(light, c.incident, c.normal);
            const StokesVector r = reflectedPolarisation(plane, c.amplitudes, c.reflected).stokes;
            const double transmitted = c.amplitudes.totalInternalReflection
                                           ? 0.0
                                           : transmittedPolarisation(plane, c.amplitudes, c.transmitted).stokes[0];
            EXPECT_NEAR(r[0] + transmitted, 1.0, 1e-14);
            EXPECT_LE(degreeOfPolarisation(r), 1.0 + 1e-12);  // physical states stay physical
        }
    }
}

TEST(InterfaceStokes, AtBrewstersAngleTheReflectedLightIsPureS) {
    const double n1 = 1.0, n2 = 1.5;
    const Crossing c = crossing(std::atan(n2 / n1), 0.4, n1, n2);
    const Polarisation light{unpolarisedStokes(), across(c.incident)};
    const PlaneOfIncidence plane = planeOfIncidence(light, c.incident, c.normal);
    const Polarisation reflected = reflectedPolarisation(plane, c.amplitudes, c.reflected);
    // The reference is the reflected beam's p axis: pure s is Q = -I.
    EXPECT_NEAR(reflected.stokes[1] / reflected.stokes[0], -1.0, 1e-13);
    EXPECT_NEAR(degreeOfLinearPolarisation(reflected.stokes), 1.0, 1e-13);
    EXPECT_NEAR(reflected.stokes[0], 0.5 * fresnelReflectance(c.cosIncidence, n1, n2).s, 1e-15);
    EXPECT_NEAR(reflected.reference.dot(c.reflected.vector()), 0.0, 1e-15);
}

// Born and Wolf, Principles of Optics, 1.5.4: past the critical angle s and p are shifted by
// delta = delta_s - delta_p with tan(delta / 2) = cos(i) sqrt(sin^2 i - n^2) / sin^2 i, n = n2 / n1.
double tirPhaseDifference(double incidence, double n) {
    const double s2 = std::sin(incidence) * std::sin(incidence);
    return 2.0 * std::atan(std::cos(incidence) * std::sqrt(s2 - n * n) / s2);
}

TEST(TotalInternalReflection, ReflectsAllOfEitherPolarisationWithThePhaseDifferenceOfBornAndWolf) {
    const double n1 = 1.51, n2 = 1.0;
    for (double degrees = 41.6; degrees < 89.9; degrees += 0.7) {
        const FresnelAmplitudes a = fresnelAmplitudes(std::cos(radians(degrees)), n1, n2);
        ASSERT_TRUE(a.totalInternalReflection) << degrees;
        EXPECT_NEAR(std::abs(a.rs), 1.0, 1e-15);
        EXPECT_NEAR(std::abs(a.rp), 1.0, 1e-15);
        EXPECT_NEAR(std::arg(a.rs * std::conj(a.rp)), tirPhaseDifference(radians(degrees), n2 / n1), 1e-12) << degrees;
    }
}

TEST(TotalInternalReflection, AFresnelRhombTurnsLinearLightAt45DegreesCircular) {
    // Two total reflections at 54.6 degrees inside glass of n = 1.51, each delaying p against s by 45
    // degrees (Fresnel's rhomb; Born and Wolf 1.5.4, Hecht, Optics, 8.6): linear light at 45 degrees to the
    // plane of incidence leaves circularly polarised.
    const double n1 = 1.51, n2 = 1.0, incidence = radians(54.6);
    EXPECT_NEAR(tirPhaseDifference(incidence, n2 / n1), radians(45.0), radians(0.05));
    Crossing first = crossing(incidence, 0.0, n1, n2);
    const Eigen::Vector3d s = first.incident.vector().cross(first.normal.vector()).normalized();
    Polarisation light{{1.0, 0.0, 1.0, 0.0}, first.incident.vector().cross(s)};  // 45 degrees: U = I
    for (int reflection = 0; reflection < 2; ++reflection) {
        // The reflected ray meets a parallel face: the same geometry again, with the plane of incidence kept.
        const PlaneOfIncidence plane = planeOfIncidence(light, first.incident, first.normal);
        light = reflectedPolarisation(plane, first.amplitudes, first.reflected);
        light.reference = Eigen::Vector3d(light.reference.x(), light.reference.y(), -light.reference.z());
    }
    EXPECT_NEAR(light.stokes[0], 1.0, 1e-14);
    // Circular, right-handed: p lags s by delta per reflection, so E_par E_perp* = e^(-i 2 delta) / 2 and
    // V = -2 Im(E_par E_perp*) = sin(2 delta) = +I (P2).
    EXPECT_NEAR(light.stokes[3], 1.0, 1e-6);
    EXPECT_NEAR(light.stokes[1], 0.0, 1e-6);
    EXPECT_NEAR(light.stokes[2], 0.0, 2e-3);  // cos(90.03 degrees)
}

TEST(NormalIncidence, IsWellDefinedWhateverTheBeamsFrame) {
    // k x N vanishes: the plane of incidence is the beam's own, and any plane gives the same light.
    const double n1 = 1.0, n2 = 1.5;
    const Direction k(0, 0, 1), normal(0, 0, -1);  // N outward from the glass, facing the beam
    const double r = (n1 - n2) / (n1 + n2);
    const FresnelAmplitudes a = fresnelAmplitudes(1.0, n1, n2);
    const Field e = fieldOf(0.3, 0.2, Eigen::Vector3d::UnitX(), k);
    for (double turn = 0.0; turn < 6.3; turn += 0.5) {
        const Eigen::Vector3d frame(std::cos(turn), std::sin(turn), 0.0);
        const Polarisation light{stokesOfField(e, frame, k), frame};
        const PlaneOfIncidence plane = planeOfIncidence(light, k, normal);
        const Polarisation reflected = reflectedPolarisation(plane, a, -k);
        const Polarisation transmitted = transmittedPolarisation(plane, a, k);
        ASSERT_TRUE(reflected.stokes.allFinite() && reflected.reference.allFinite());
        // The reflected field is r E: the same ellipse, its handedness reversed as it travels back.
        expectStokesNear(reflected.stokes, r * r * stokesOfField(e, reflected.reference, -k), 1e-14);
        EXPECT_NEAR(reflected.stokes[3], -r * r * stokesOfField(e, frame, k)[3], 1e-14);
        expectStokesNear(transmitted.stokes, (1 - r * r) * stokesOfField(e, transmitted.reference, k), 1e-14);
        EXPECT_NEAR(polarisedReflectance(plane, a), r * r, 1e-16);
    }
}

}  // namespace
}  // namespace dropscope
