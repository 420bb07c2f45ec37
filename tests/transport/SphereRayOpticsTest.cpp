// The sphere reference with s and p tracked (SphereRayOptics.hpp) against closed forms that it does not
// compute the same way: Fresnel at normal incidence, Brewster's angle and 45 degrees; the Descartes ray;
// energy conservation; the diffuse reflectance of a flat surface; a plain histogram of rays; the weak-absorption
// limit; a nearly index-matched sphere. docs/validation.md, "Ray optics of a sphere with s and p tracked".
#include "transport/SphereRayOptics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

namespace dropscope::testing {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
constexpr double kWater = 1.3337;  // 532 nm, as the validation scenes
// Sums over the same quadrature nodes that agree in exact arithmetic: a few thousand terms below 1.
constexpr double kRoundingTolerance = 1e-13;
// The orders above the 20th are binned at 20000 impact parameters; what they miss of their own total.
constexpr double kTailBinningTolerance = 1e-10;
// One Fresnel formula of numbers below 1: a few rounding units.
constexpr double kFormulaRounding = 1e-15;
// Two forms of one formula: the sine and tangent forms lose digits where theta_i - theta_t is small.
constexpr double kOtherFormTolerance = 1e-13;

std::vector<double> edgesEvery(double widthDegrees, double from = 0.0, double to = 180.0) {
    std::vector<double> edges;
    const auto count = static_cast<int>(std::lround((to - from) / widthDegrees));
    for (int i = 0; i <= count; ++i) edges.push_back(from + (to - from) * i / count);
    return edges;
}

// Coarse bins with a fine window, the edges of each part included once.
std::vector<double> edgesWithWindow(double from, double to, double fineWidth) {
    std::vector<double> edges = edgesEvery(10.0, 0.0, from);
    for (const double edge : edgesEvery(fineWidth, from, to)) edges.push_back(edge);
    for (const double edge : edgesEvery(10.0, to, 180.0)) edges.push_back(edge);
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

// Snell's law for an angle in radians.
double refractionAngle(double thetaI, double m) { return std::asin(std::sin(thetaI) / m); }

// The Fresnel reflectances in their other form (Born and Wolf 1.5): R_s = sin^2(i - t) / sin^2(i + t),
// R_p = tan^2(i - t) / tan^2(i + t); not defined at normal incidence.
PolarisedReflectance fresnelBySines(double thetaI, double m) {
    const double thetaT = refractionAngle(thetaI, m);
    const double s = std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
    const double p = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
    return {s * s, p * p};
}

// The integral of the unpolarised R(theta) sin(2 theta) over [from, to] (radians), midpoint rule.
double reflectedShare(double m, double from, double to) {
    constexpr int kSteps = 100000;
    double sum = 0.0;
    for (int step = 0; step < kSteps; ++step) {
        const double thetaI = from + (to - from) * (step + 0.5) / kSteps;
        sum += fresnelBySines(thetaI, m).mean() * std::sin(2.0 * thetaI);
    }
    return sum * (to - from) / kSteps;
}

// The Descartes ray with k internal reflections in closed form: there m cos(theta_t) = (k + 1) cos(theta_i),
// so r_s = -k / (k + 2) and r_p = (m^2 - k - 1) / (m^2 + k + 1) whatever m is.
struct ClosedFormDescartes {
    double scatteringAngleDegrees;
    double degreeOfPolarisation;
};

ClosedFormDescartes closedFormDescartes(double m, int reflections) {
    const double k = reflections;
    const double thetaI = std::acos(std::sqrt((m * m - 1.0) / (k * (k + 2.0))));
    const double deviation = 2.0 * (thetaI - refractionAngle(thetaI, m)) + k * (kPi - 2.0 * refractionAngle(thetaI, m));
    const double reflectS = std::pow(k / (k + 2.0), 2);
    const double reflectP = std::pow((m * m - k - 1.0) / (m * m + k + 1.0), 2);
    const double shareS = std::pow(1.0 - reflectS, 2) * std::pow(reflectS, k);
    const double shareP = std::pow(1.0 - reflectP, 2) * std::pow(reflectP, k);
    return {std::acos(std::cos(deviation)) / kDegree, (shareS - shareP) / (shareS + shareP)};
}

std::size_t binOf(const SphereRayOptics& optics, double angleDegrees) {
    const auto& edges = optics.binEdgesDegrees;
    return static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), angleDegrees) - edges.begin() - 1);
}

TEST(SphereSurfaceReflectance, NormalIncidenceBrewsterAngleFortyFiveDegreesAndGrazing) {
    for (const double m : {1.0001, kWater, 1.5, 2.4}) {
        const double normal = std::pow((m - 1.0) / (m + 1.0), 2);
        EXPECT_NEAR(sphereSurfaceReflectance(1.0, m).s, normal, kFormulaRounding);
        EXPECT_NEAR(sphereSurfaceReflectance(1.0, m).p, normal, kFormulaRounding);
        // Brewster: tan(theta_B) = m; p does not reflect, s reflects cos^2(2 theta_B) = ((m^2 - 1)/(m^2 + 1))^2.
        const PolarisedReflectance brewster = sphereSurfaceReflectance(1.0 / std::sqrt(1.0 + m * m), m);
        EXPECT_LT(brewster.p, kFormulaRounding * kFormulaRounding) << "m = " << m;  // r_p vanishes to rounding
        EXPECT_NEAR(brewster.s, std::pow((m * m - 1.0) / (m * m + 1.0), 2), kFormulaRounding);
        // At 45 degrees R_p = R_s^2 for every index.
        const PolarisedReflectance at45 = sphereSurfaceReflectance(std::sqrt(0.5), m);
        EXPECT_NEAR(at45.p, at45.s * at45.s, kFormulaRounding);
        EXPECT_NEAR(sphereSurfaceReflectance(0.0, m).s, 1.0, kFormulaRounding);
        EXPECT_NEAR(sphereSurfaceReflectance(0.0, m).p, 1.0, kFormulaRounding);
    }
}

TEST(SphereSurfaceReflectance, AgreesWithTheSineAndTangentFormsOutsideAndInside) {
    for (const double m : {1.0001, kWater, 1.5}) {
        for (double degrees = 1.0; degrees < 90.0; degrees += 1.0) {
            const double thetaI = degrees * kDegree;
            const PolarisedReflectance outside = sphereSurfaceReflectance(std::cos(thetaI), m);
            const PolarisedReflectance bySines = fresnelBySines(thetaI, m);
            EXPECT_NEAR(outside.s, bySines.s, kOtherFormTolerance) << degrees;
            EXPECT_NEAR(outside.p, bySines.p, kOtherFormTolerance) << degrees;
            // From inside at theta_t, out into index 1: the same fractions (Stokes relations).
            const double thetaT = refractionAngle(thetaI, m);
            const double insideS =
                (m * std::cos(thetaT) - std::cos(thetaI)) / (m * std::cos(thetaT) + std::cos(thetaI));
            const double insideP =
                (std::cos(thetaT) - m * std::cos(thetaI)) / (std::cos(thetaT) + m * std::cos(thetaI));
            EXPECT_NEAR(insideS * insideS, outside.s, kOtherFormTolerance) << degrees;
            EXPECT_NEAR(insideP * insideP, outside.p, kOtherFormTolerance) << degrees;
        }
    }
}

TEST(DescartesRay, MatchesItsClosedForms) {
    constexpr double kAngleTolerance = 1e-10;  // degrees; arccos(cos D) near cos D = -0.74 keeps ~1e-13 rad
    constexpr double kQuotedAngle = 0.005;     // half the last digit of docs/validation.md's figures
    for (const double m : {1.333, kWater, 1.5}) {
        for (const int reflections : {1, 2}) {
            const DescartesRay ray = descartesRay(m, reflections + 1);
            const ClosedFormDescartes expected = closedFormDescartes(m, reflections);
            EXPECT_NEAR(ray.scatteringAngleDegrees, expected.scatteringAngleDegrees, kAngleTolerance);
            EXPECT_NEAR(ray.degreeOfPolarisation, expected.degreeOfPolarisation, kOtherFormTolerance);
        }
    }
    // The bows of docs/validation.md, "The rainbows".
    EXPECT_NEAR(descartesRay(kWater, 2).scatteringAngleDegrees, 138.02, kQuotedAngle);
    EXPECT_NEAR(descartesRay(kWater, 3).scatteringAngleDegrees, 128.93, kQuotedAngle);
    EXPECT_THROW(descartesRay(2.5, 2), std::invalid_argument);  // order 2 has no minimum deviation for m >= 2
}

struct Sphere {
    double m;
    double sigmaA;
};

void PrintTo(const Sphere& sphere, std::ostream* out) { *out << "m = " << sphere.m << ", sigma a = " << sphere.sigmaA; }

class SphereRayOpticsPower : public ::testing::TestWithParam<Sphere> {};

TEST_P(SphereRayOpticsPower, OrdersAndAbsorptionAddUpToTheIncidentPowerAndBinsToTheirTotals) {
    const Sphere sphere = GetParam();
    const SphereRayOptics optics = sphereRayOptics(sphere.m, sphere.sigmaA, edgesEvery(1.0), 5);
    PowerFraction everything = optics.absorbed;
    everything += optics.higherOrders.total;
    for (const RayOrderPower& order : optics.orders) {
        everything += order.total;
        PowerFraction binned;
        for (const PowerFraction& bin : order.bins) binned += bin;
        EXPECT_NEAR(binned.s, order.total.s, kRoundingTolerance);
        EXPECT_NEAR(binned.p, order.total.p, kRoundingTolerance);
        EXPECT_NEAR(binned.unpolarisedFresnel, order.total.unpolarisedFresnel, kRoundingTolerance);
    }
    EXPECT_NEAR(everything.s, 1.0, kRoundingTolerance);
    EXPECT_NEAR(everything.p, 1.0, kRoundingTolerance);
    EXPECT_NEAR(everything.unpolarisedFresnel, 1.0, kRoundingTolerance);

    PowerFraction binned = optics.absorbed;
    for (const PowerFraction& bin : optics.bins) binned += bin;
    EXPECT_NEAR(binned.s, 1.0, kTailBinningTolerance);
    EXPECT_NEAR(binned.p, 1.0, kTailBinningTolerance);
    EXPECT_NEAR(binned.unpolarisedFresnel, 1.0, kTailBinningTolerance);
    EXPECT_LT(optics.unresolvedTail.intensity(), 1.5e-11);  // at most, for m up to 3
}

INSTANTIATE_TEST_SUITE_P(ClearAbsorbingAndNearlyMatched, SphereRayOpticsPower,
                         ::testing::Values(Sphere{kWater, 0.0}, Sphere{kWater, 0.4}, Sphere{1.5, 2.0},
                                           Sphere{1.000001, 0.0}, Sphere{2.5, 0.0}));

TEST(SphereRayOptics, MergedBinsHoldWhatTheirPartsHold) {
    // Each bin integrates between the impact parameters where an order crosses its edges: a crossing missed or
    // misplaced puts power in a neighbour, differently for different edges. Edges not symmetric about 90
    // degrees, where the folds of the deviation at odd multiples of pi would hide a mistake.
    const SphereRayOptics fine = sphereRayOptics(kWater, 0.2, edgesEvery(1.0), 5);
    const SphereRayOptics coarse = sphereRayOptics(
        kWater, 0.2, {0.0, 3.0, 10.0, 25.0, 47.0, 90.0, 100.0, 121.0, 138.0, 139.0, 150.0, 171.0, 180.0}, 5);
    for (std::size_t order = 0; order < fine.orders.size(); ++order) {
        for (std::size_t bin = 0; bin < coarse.bins.size(); ++bin) {
            const PowerFraction merged =
                bandPower(fine, fine.orders[order].bins, coarse.binEdgesDegrees[bin], coarse.binEdgesDegrees[bin + 1]);
            EXPECT_NEAR(merged.s, coarse.orders[order].bins[bin].s, kRoundingTolerance) << order << ", " << bin;
            EXPECT_NEAR(merged.p, coarse.orders[order].bins[bin].p, kRoundingTolerance) << order << ", " << bin;
        }
    }
}

TEST(SphereRayOptics, OuterReflectionIsTheDiffuseReflectanceOfAFlatSurface) {
    // A beam as wide as the sphere meets its surface with weight d(sin^2 theta_i), as a flat surface under a
    // uniform sky; order 0 leaves at 180 - 2 theta_i, so the bin [a, b] holds theta_i in [(180 - b)/2, (180 - a)/2].
    constexpr double kMidpointTolerance = 1e-10;  // 1e5 steps of a smooth integrand: error ~1e-12
    constexpr double kQuotedReflectance = 5e-6;   // half the last digit of the 0.06652 quoted
    const SphereRayOptics optics = sphereRayOptics(kWater, 0.0, edgesEvery(15.0), 1);
    EXPECT_NEAR(optics.orders[0].total.intensity(), reflectedShare(kWater, 0.0, kPi / 2), kMidpointTolerance);
    EXPECT_NEAR(optics.orders[0].total.intensity(), 0.06652, kQuotedReflectance);  // docs/validation.md
    for (std::size_t bin = 0; bin < optics.bins.size(); ++bin) {
        const double from = (180.0 - optics.binEdgesDegrees[bin + 1]) / 2 * kDegree;
        const double to = (180.0 - optics.binEdgesDegrees[bin]) / 2 * kDegree;
        EXPECT_NEAR(optics.orders[0].bins[bin].intensity(), reflectedShare(kWater, from, to), kMidpointTolerance)
            << "bin " << bin;
    }
}

TEST(SphereRayOptics, BinsAgreeWithAPlainHistogramOfRays) {
    // Orders 0-3 of 4e5 impact parameters, midpoints in cos(theta_i), each into the 5-degree bin of its
    // deviation. A step carries at most 5e-6 of the power, and each time an order crosses a bin edge at most
    // one step lands on the wrong side: a few steps per bin.
    constexpr int kSteps = 400000;
    constexpr double kHistogramTolerance = 3e-5;
    constexpr double kSigmaA = 0.4;
    constexpr int kBins = 36;
    std::vector<PowerFraction> histogram(kBins * 4);
    for (int step = 0; step < kSteps; ++step) {
        const double cosI = (step + 0.5) / kSteps;
        const double thetaI = std::acos(cosI);
        const double thetaT = refractionAngle(thetaI, kWater);
        const PolarisedReflectance r = fresnelBySines(thetaI, kWater);
        const double tau = std::exp(-2.0 * kSigmaA * std::cos(thetaT));
        double s = r.s;
        double p = r.p;
        for (int order = 0; order <= 3; ++order) {
            const double deviation =
                order == 0 ? kPi - 2 * thetaI : 2 * (thetaI - thetaT) + (order - 1) * (kPi - 2 * thetaT);
            const auto bin = std::min(static_cast<int>(std::acos(std::cos(deviation)) / kPi * kBins), kBins - 1);
            histogram[static_cast<std::size_t>(order * kBins + bin)] +=
                {s * 2 * cosI / kSteps, p * 2 * cosI / kSteps, 0};
            s = order == 0 ? (1 - r.s) * (1 - r.s) * tau : s * r.s * tau;
            p = order == 0 ? (1 - r.p) * (1 - r.p) * tau : p * r.p * tau;
        }
    }
    const SphereRayOptics optics = sphereRayOptics(kWater, kSigmaA, edgesEvery(5.0), 3);
    for (int order = 0; order <= 3; ++order) {
        for (int bin = 0; bin < kBins; ++bin) {
            const PowerFraction& expected = histogram[static_cast<std::size_t>(order * kBins + bin)];
            const PowerFraction& actual =
                optics.orders[static_cast<std::size_t>(order)].bins[static_cast<std::size_t>(bin)];
            EXPECT_NEAR(actual.s, expected.s, kHistogramTolerance) << "order " << order << ", bin " << bin;
            EXPECT_NEAR(actual.p, expected.p, kHistogramTolerance) << "order " << order << ", bin " << bin;
        }
    }
}

TEST(SphereRayOptics, RainbowsPeakAtTheirDescartesAngles) {
    // Between 120 and 150 degrees in bins of 0.02 degrees: the caustic is an inverse square-root peak on the
    // bright side of the Descartes angle (above it for the primary, below for the secondary), and nothing of
    // that order reaches the dark side.
    constexpr double kWidth = 0.02;
    const SphereRayOptics optics = sphereRayOptics(kWater, 0.0, edgesWithWindow(120.0, 150.0, kWidth), 3);
    for (const int order : {2, 3}) {
        const double descartes = closedFormDescartes(kWater, order - 1).scatteringAngleDegrees;
        const std::vector<PowerFraction>& bins = optics.orders[static_cast<std::size_t>(order)].bins;
        std::size_t brightest = binOf(optics, 120.0);
        for (std::size_t bin = brightest; bin < binOf(optics, 150.0); ++bin)
            if (bins[bin].intensity() > bins[brightest].intensity()) brightest = bin;
        const double centre = 0.5 * (optics.binEdgesDegrees[brightest] + optics.binEdgesDegrees[brightest + 1]);
        EXPECT_NEAR(centre, descartes, kWidth) << "order " << order;
        const PowerFraction darkSide = order == 2 ? bandPower(optics, bins, 120.0, descartes - kWidth)
                                                  : bandPower(optics, bins, descartes + kWidth, 150.0);
        EXPECT_EQ(darkSide.intensity(), 0.0) << "order " << order;
    }
}

TEST(SphereRayOptics, PrimaryBowIsPolarisedAcrossTheScatteringPlane) {
    constexpr double kWidth = 0.02;
    const SphereRayOptics optics = sphereRayOptics(kWater, 0.0, edgesWithWindow(120.0, 150.0, kWidth), 3);
    for (const int order : {2, 3}) {
        // The bin of the caustic holds rays from both sides of the Descartes ray, up to 0.95 degrees of theta_i
        // away (Theta - Theta_R = D''(theta_i - theta_R)^2 / 2), where -Q/I is 0.024 higher on one side and
        // lower on the other; the two sides cancel that to first order, leaving less than 0.002.
        constexpr double kCausticBinTolerance = 0.002;
        const ClosedFormDescartes descartes = closedFormDescartes(kWater, order - 1);
        const PowerFraction caustic =
            optics.orders[static_cast<std::size_t>(order)].bins[binOf(optics, descartes.scatteringAngleDegrees)];
        EXPECT_NEAR(caustic.degreeOfPolarisation(), descartes.degreeOfPolarisation, kCausticBinTolerance)
            << "order " << order;
    }
    // Over the degree inside the primary bow nearly all the light is order 2, from theta_i within 7 degrees of
    // the Descartes ray: each of those rays is more than 68 % polarised across the scattering plane, and the
    // ones that carry most of the power, near the caustic, more than 87 %.
    const double bow = closedFormDescartes(kWater, 1).scatteringAngleDegrees;
    const double bandStart = optics.binEdgesDegrees[binOf(optics, bow)];
    const PowerFraction band = bandPower(optics, optics.bins, bandStart, bow + 1.0);
    const PowerFraction primary = bandPower(optics, optics.orders[2].bins, bandStart, bow + 1.0);
    EXPECT_GT(primary.intensity(), 0.95 * band.intensity());
    EXPECT_GT(primary.degreeOfPolarisation(), 0.85);
    EXPECT_GT(band.degreeOfPolarisation(), 0.8);
}

TEST(SphereRayOptics, NearlyIndexMatchedSphereSendsAlmostEverythingStraightOn) {
    // m = 1 + 1e-6: a ray reflects appreciably only within sqrt(2e-6) rad of grazing, where the disk holds
    // ~1e-6 of the beam, and order 1 turns by at most 2 sqrt(2e-6) rad = 0.16 degrees.
    constexpr double kReflectedAtMost = 1e-6;
    constexpr double kNotStraightOnAtMost = 1e-5;
    const SphereRayOptics optics = sphereRayOptics(1.000001, 0.0, {0.0, 0.2, 1.0, 180.0}, 2);
    EXPECT_LT(optics.orders[0].total.intensity(), kReflectedAtMost);
    EXPECT_GT(optics.orders[1].total.intensity(), 1.0 - kNotStraightOnAtMost);
    EXPECT_NEAR(optics.orders[1].bins[0].intensity(), optics.orders[1].total.intensity(), kRoundingTolerance);
    EXPECT_GT(optics.bins[0].intensity(), 1.0 - kNotStraightOnAtMost);
    EXPECT_GT(optics.asymmetry, 1.0 - kNotStraightOnAtMost);
}

TEST(SphereRayOptics, AsymmetryAndBackscatterAgreeWithTheBins) {
    // g against the bins' mean cosine at their centres: off by at most half a bin (0.0017 rad) times the
    // power of the few bins where the caustics make the distribution lopsided.
    constexpr double kBinnedCosineTolerance = 1e-5;
    const SphereRayOptics optics = sphereRayOptics(kWater, 0.1, edgesEvery(0.2), 3);
    double cosine = 0.0;
    double escaped = 0.0;
    for (std::size_t bin = 0; bin < optics.bins.size(); ++bin) {
        const double centre = 0.5 * (optics.binEdgesDegrees[bin] + optics.binEdgesDegrees[bin + 1]) * kDegree;
        cosine += optics.bins[bin].intensity() * std::cos(centre);
        escaped += optics.bins[bin].intensity();
    }
    EXPECT_NEAR(escaped, optics.escaped.intensity(), kTailBinningTolerance);
    EXPECT_NEAR(optics.asymmetry, cosine / escaped, kBinnedCosineTolerance);
    EXPECT_NEAR(optics.backscattered.intensity(), bandPower(optics, optics.bins, 90.0, 180.0).intensity(),
                kRoundingTolerance);
    // Bins that do not have an edge at 90 degrees give the same backscatter.
    const SphereRayOptics uneven = sphereRayOptics(kWater, 0.1, edgesEvery(7.2), 3);
    EXPECT_NEAR(uneven.backscattered.intensity(), optics.backscattered.intensity(), kRoundingTolerance);
    EXPECT_NEAR(uneven.backscattered.q(), optics.backscattered.q(), kRoundingTolerance);
}

TEST(SphereRayOptics, WeakAbsorptionApproachesTheMeanChordLimit) {
    // Absorbed share -> sigma a <L/a> = sigmaA (4/3) m^2 [1 - (1 - 1/m^2)^(3/2)] (docs/validation.md); the next
    // term is of relative order sigmaA.
    constexpr double kSigmaA = 1e-6;
    constexpr double kNextOrderTolerance = 10 * kSigmaA;
    const SphereRayOptics optics = sphereRayOptics(kWater, kSigmaA, edgesEvery(90.0), 2);
    const double limit = kSigmaA * 4.0 / 3.0 * kWater * kWater * (1.0 - std::pow(1.0 - 1.0 / (kWater * kWater), 1.5));
    EXPECT_NEAR(optics.absorbed.intensity() / limit, 1.0, kNextOrderTolerance);
    EXPECT_NEAR(optics.absorbed.unpolarisedFresnel / limit, 1.0, kNextOrderTolerance);
}

TEST(SphereRayOptics, UnpolarisedFresnelKeepsOrderZeroAndLosesDirectTransmission) {
    // Order 0 is R either way; order 1 is the mean of T_s^2 and T_p^2, which is at least the square of the
    // mean T (T_s != T_p away from normal incidence).
    const SphereRayOptics optics = sphereRayOptics(kWater, 0.0, edgesEvery(30.0), 1);
    EXPECT_NEAR(optics.orders[0].total.unpolarisedFresnel, optics.orders[0].total.intensity(), kFormulaRounding);
    EXPECT_GT(optics.orders[1].total.intensity(), optics.orders[1].total.unpolarisedFresnel);
}

TEST(SphereRayOptics, QuadratureErrorIsFarBelowMonteCarloNoise) {
    // Halving every quadrature panel and tail step changes no 0.5-degree bin by more than 1e-8 of the incident
    // power, and no bin by more than 1 % of its Monte Carlo standard deviation at 1e7 photons.
    constexpr double kBinChange = 1e-8;
    constexpr double kPhotons = 1e7;
    constexpr double kSigmaFraction = 0.01;
    const SphereRayOptics coarse = sphereRayOptics(kWater, 0.0, edgesEvery(0.5), 3, 1);
    const SphereRayOptics fine = sphereRayOptics(kWater, 0.0, edgesEvery(0.5), 3, 2);
    double largest = 0.0;
    double largestInSigma = 0.0;
    for (std::size_t bin = 0; bin < coarse.bins.size(); ++bin) {
        const double change = std::max(std::abs(coarse.bins[bin].intensity() - fine.bins[bin].intensity()),
                                       std::abs(coarse.bins[bin].q() - fine.bins[bin].q()));
        const double p = std::max(fine.bins[bin].intensity(), 1.0 / kPhotons);
        largest = std::max(largest, change);
        largestInSigma = std::max(largestInSigma, change / std::sqrt(p * (1.0 - p) / kPhotons));
    }
    std::cout << "quadrature: largest change of a 0.5-degree bin " << largest << " (" << largestInSigma
              << " Monte Carlo sigma at 1e7 photons)\n";
    ::testing::Test::RecordProperty("largestBinChange", std::to_string(largest));
    EXPECT_LT(largest, kBinChange);
    EXPECT_LT(largestInSigma, kSigmaFraction);
    for (std::size_t order = 0; order < coarse.orders.size(); ++order)
        EXPECT_NEAR(coarse.orders[order].total.intensity(), fine.orders[order].total.intensity(), kRoundingTolerance);
    EXPECT_NEAR(coarse.asymmetry, fine.asymmetry, kRoundingTolerance);
}

TEST(SphereRayOptics, RefusesWhatItCannotCompute) {
    EXPECT_THROW(sphereRayOptics(1.0, 0.0, edgesEvery(1.0), 3), std::invalid_argument);
    EXPECT_THROW(sphereRayOptics(0.75, 0.0, edgesEvery(1.0), 3), std::invalid_argument);
    EXPECT_THROW(sphereRayOptics(kWater, -1.0, edgesEvery(1.0), 3), std::invalid_argument);
    EXPECT_THROW(sphereRayOptics(kWater, 0.0, {0.0, 90.0}, 3), std::invalid_argument);
    EXPECT_THROW(sphereRayOptics(kWater, 0.0, {0.0, 90.0, 90.0, 180.0}, 3), std::invalid_argument);
}

}  // namespace
}  // namespace dropscope::testing
