// Polarised photons through whole scenes (docs/transport.md, "Polarised photons"): a Fresnel rhomb made of
// the total reflections inside a glass sphere, Brewster's angle on a glass block, and the independence of
// every photon's degree of polarisation from the frame the scene is written in.
#include "TransportFixtures.hpp"
#include "transport/TallyExpectations.hpp"

#include "optics/Stokes.hpp"
#include "transport/PhotonTracer.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using testing::sceneFromJson;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

std::vector<Event> recordedPath(const OpticalScene& scene, const Source& source, std::uint64_t photon,
                                const TransportSettings& settings) {
    PhotonRandom random(3, photon);
    const Ray ray = emitPhoton(source, random);
    std::vector<Event> path;
    EventRecorder recorder(path);
    tracePhoton(scene, ray, random, settings, &recorder, emittedPolarisation(source, ray.direction));
    return path;
}

TEST(PolarisedTransport, TwoTotalReflectionsInsideAGlassSphereActAsAFresnelRhomb) {
    // A ray inside a sphere of n = 1.51 meets the wall at sin(i) = b / radius on every bounce, all in one
    // plane: at i = 54.6 degrees each total reflection delays p against s by 45 degrees (Born and Wolf
    // 1.5.4), so linear light at 45 degrees to that plane is circular after two.
    const double b = std::sin(radians(54.6));
    const Scene scene =
        sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.51})",
                      R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"})",
                      R"({"type": "ray", "origin": [0, )" + std::to_string(b) + R"(, 0], "direction": [1, 0, 0],
                          "polarisation": {"linear_deg": 45, "reference": [0, 0, 1]}})");
    TransportSettings settings;
    settings.maxEvents = 2;
    const std::vector<Event> path = recordedPath(OpticalScene(scene), scene.sources[0], 0, settings);
    ASSERT_EQ(path.size(), 4u);  // emit, tir, tir, lost at the cap
    ASSERT_EQ(path[1].type, EventType::Tir);
    ASSERT_EQ(path[2].type, EventType::Tir);
    const StokesVector& emitted = path[0].polarisation->stokes;
    EXPECT_NEAR(std::abs(emitted[2]), 1.0, 1e-12);  // U = I: 45 degrees to the plane of the bounces
    const StokesVector& once = path[1].polarisation->stokes;
    EXPECT_NEAR(std::abs(once[3]), std::sin(radians(45.0)), 1e-3);  // a quarter of the way round
    const StokesVector& twice = path[2].polarisation->stokes;
    EXPECT_NEAR(twice[0], 1.0, 1e-14);
    // Circular, and which hand: at the first wall s = k x N = +z and p = k x s = -y, so the source's light
    // (z + y)/sqrt(2) has E_par = -E_perp, U = -I in the plane's frame. Each total reflection delays p
    // against s by delta (P9), turning (U, V) by it (P4): V = U sin(2 delta) = -I, left-handed.
    EXPECT_NEAR(twice[3], -1.0, 1e-6);
    EXPECT_NEAR(degreeOfPolarisation(twice), 1.0, 1e-12);
}

TEST(PolarisedTransport, AtBrewstersAngleNoPPolarisedPhotonReflectsAndReflectedLightIsPureS) {
    // assets/scenes/brewster.json: an s-polarised and a p-polarised beam on a glass block (n = 1.5) at
    // Brewster's angle, atan 1.5. The s beam reflects Rs = sin^2(i - t) = 0.1479 of its photons there.
    const Scene scene = loadScene(DROPSCOPE_SOURCE_DIR "/assets/scenes/brewster.json");
    const OpticalScene optical(scene);
    const double incidence = std::atan(1.5);
    const double rs = std::pow(std::sin(incidence - std::asin(std::sin(incidence) / 1.5)), 2);
    constexpr int kPhotons = 20000;
    int sReflected = 0;
    for (std::uint64_t photon = 0; photon < kPhotons; ++photon) {
        const std::size_t source = photon % 2;
        const std::vector<Event> path = recordedPath(optical, scene.sources[source], photon, TransportSettings{});
        ASSERT_GE(path.size(), 2u);
        const Event& first = path[1];  // the top face
        if (source == 1) {
            EXPECT_EQ(first.type, EventType::Refract) << "photon " << photon;
            EXPECT_LT(first.reflectance, 1e-12);
        } else if (first.type == EventType::Reflect) {
            ++sReflected;
            EXPECT_NEAR(first.polarisation->stokes[1], -1.0, 1e-12);  // pure s in the reflected frame
        }
    }
    EXPECT_NEAR(sReflected / (kPhotons / 2.0), rs, testing::monteCarloTolerance(rs, kPhotons / 2.0));

    // Unpolarised light reflected there is pure s too.
    Source unpolarised = scene.sources[0];
    unpolarised.polarisation = {};
    for (std::uint64_t photon = 0, reflected = 0; reflected < 50; ++photon) {
        ASSERT_LT(photon, 2000u);
        const std::vector<Event> path = recordedPath(optical, unpolarised, photon, TransportSettings{});
        if (path[1].type != EventType::Reflect) continue;
        ++reflected;
        EXPECT_NEAR(path[1].polarisation->stokes[1], -1.0, 1e-12);
        EXPECT_NEAR(path[1].reflectance, 0.5 * rs, 1e-12);  // unpolarised: half of Rs, since Rp = 0
    }
}

// A scene of drops and pencils of light in several states, written turned by `turn` about the origin.
std::string sceneText(const Eigen::Matrix3d& turn) {
    std::ostringstream text;
    text.precision(17);
    const auto vec = [&](const Eigen::Vector3d& v) {
        const Eigen::Vector3d t = turn * v;
        std::ostringstream out;
        out.precision(17);
        out << "[" << t.x() << ", " << t.y() << ", " << t.z() << "]";
        return out.str();
    };
    const Eigen::AngleAxisd ellipsoid(turn * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0).normalized()));
    text << R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
        "media": {"air": {"n": 1}, "water": {"n": 1.3337}, "glass": {"n": 1.52}},
        "shapes": [{"type": "sphere", "center": )"
         << vec({0, 0, 0}) << R"(, "radius": 1, "medium": "water"},
                   {"type": "sphere", "center": )"
         << vec({2.4, 0.3, 0.5}) << R"(, "radius": 0.8, "medium": "glass"},
                   {"type": "ellipsoid", "center": )"
         << vec({-0.4, 2.3, -0.2}) << R"(, "semi_axes": [1.1, 0.6, 0.8],
                    "rotation": {"axis": )"
         << "[" << ellipsoid.axis().x() << ", " << ellipsoid.axis().y() << ", " << ellipsoid.axis().z() << "]"
         << R"(, "angle_deg": )" << ellipsoid.angle() * 180.0 / std::numbers::pi << R"(}, "medium": "water"}],
        "sources": [{"type": "ray", "origin": )"
         << vec({-4, 0.3, 0.1}) << R"(, "direction": )" << vec({1, 0, 0}) << R"(,
                     "polarisation": {"linear_deg": 20, "reference": )"
         << vec({0, 0, 1}) << R"(}},
                    {"type": "ray", "origin": )"
         << vec({0.2, -4, 0.4}) << R"(, "direction": )" << vec({0.1, 1, 0}) << R"(,
                     "polarisation": {"stokes": [1, 0.2, -0.3, 0.6], "reference": )"
         << vec({1, -0.1, 0}) << R"(}},
                    {"type": "ray", "origin": )"
         << vec({2.2, 0.5, -4}) << R"(, "direction": )" << vec({0, 0, 1}) << R"(}]})";
    return text.str();
}

TEST(PolarisedTransport, TurningTheWholeSceneLeavesEveryPhotonsPolarisationAlone) {
    // Frames are chosen where the physics has no preference (the source's unpolarised frame, the plane of
    // incidence's sign): whatever they are, the degree of linear polarisation and |V| / I of every photon
    // after every event, and the angular tally's Stokes columns, are the same in the turned scene.
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).matrix();
    const Scene plain = parseScene(sceneText(Eigen::Matrix3d::Identity()), "plain.json");
    const Scene turned = parseScene(sceneText(turn), "turned.json");
    const OpticalScene plainOptics(plain), turnedOptics(turned);
    int compared = 0, different = 0;
    for (std::uint64_t photon = 0; photon < 3000; ++photon) {
        const std::size_t source = photon % 3;
        const std::vector<Event> a = recordedPath(plainOptics, plain.sources[source], photon, TransportSettings{});
        const std::vector<Event> b = recordedPath(turnedOptics, turned.sources[source], photon, TransportSettings{});
        bool same = a.size() == b.size();
        for (std::size_t k = 0; same && k < a.size(); ++k) same = a[k].type == b[k].type;
        if (!same) {  // a random choice fell within rounding of its threshold
            ++different;
            continue;
        }
        for (std::size_t k = 0; k < a.size(); ++k) {
            const StokesVector& sa = a[k].polarisation->stokes;
            const StokesVector& sb = b[k].polarisation->stokes;
            EXPECT_NEAR(degreeOfLinearPolarisation(sa), degreeOfLinearPolarisation(sb), 1e-9) << photon << ", " << k;
            EXPECT_NEAR(std::abs(sa[3]), std::abs(sb[3]), 1e-9) << photon << ", " << k;
            EXPECT_NEAR((turn * a[k].direction.vector() - b[k].direction.vector()).norm(), 0.0, 1e-9);
            ++compared;
        }
    }
    EXPECT_LE(different, 3);
    EXPECT_GT(compared, 12000);

    TraceSettings settings;
    settings.photons = 3000;
    settings.seed = 3;
    const AngularTally::Columns ca =
        test::angular(test::traceStandard(plainOptics, plain.sources, settings, 12)).columns();
    const AngularTally::Columns cb =
        test::angular(test::traceStandard(turnedOptics, turned.sources, settings, 12)).columns();
    for (std::size_t bin = 0; bin < ca.dolp.size(); ++bin) {
        EXPECT_NEAR(ca.fraction[bin], cb.fraction[bin], 2.0 / 3000) << bin;  // up to a photon that chose otherwise
        EXPECT_NEAR(ca.stokesQ[bin], cb.stokesQ[bin], 2.0 / 3000) << bin;
        EXPECT_NEAR(ca.stokesU[bin], cb.stokesU[bin], 2.0 / 3000) << bin;
        EXPECT_NEAR(ca.stokesV[bin], cb.stokesV[bin], 2.0 / 3000) << bin;
    }
}

TEST(PolarisedTransport, OneStateWrittenInTwoFramesGivesTheSameLightEverywhere) {
    // Linear light at A from r is linear light at A + theta from r' = cos(theta) r - sin(theta) (r x k); an
    // elliptical state's (Q, U) turn by (P3) with psi = theta. Traced photon by photon, the light after every
    // event, turned into the first description's frame, is the same Stokes vector, signs of U and V included,
    // and so are the angular tally's Stokes columns: the physics does not depend on how the state is written.
    const Eigen::Vector3d k = Eigen::Vector3d(0.1, 0.05, 1.0).normalized();
    const Eigen::Vector3d r = k.unitOrthogonal();
    const double theta = 0.7;
    const Eigen::Vector3d turned = std::cos(theta) * r - std::sin(theta) * r.cross(k);
    const double q = 0.3, u = -0.5, v = 0.6;
    const double qTurned = std::cos(2 * theta) * q - std::sin(2 * theta) * u;
    const double uTurned = std::sin(2 * theta) * q + std::cos(2 * theta) * u;
    const auto pencil = [&](const std::string& polarisation) {
        std::ostringstream text;
        text.precision(17);
        text << R"({"type": "ray", "origin": [0.35, 0.2, -4], "direction": [)" << k.x() << ", " << k.y() << ", "
             << k.z() << R"(], "polarisation": )" << polarisation << "}";
        return text.str();
    };
    const auto vec = [](const Eigen::Vector3d& a) {
        std::ostringstream text;
        text.precision(17);
        text << "[" << a.x() << ", " << a.y() << ", " << a.z() << "]";
        return text.str();
    };
    const auto number = [](double x) {
        std::ostringstream text;
        text.precision(17);
        text << x;
        return text.str();
    };
    const std::vector<std::pair<std::string, std::string>> descriptions{
        {R"({"linear_deg": 25, "reference": )" + vec(r) + "}",
         R"({"linear_deg": )" + number(25 + theta * 180 / std::numbers::pi) + R"(, "reference": )" + vec(turned) + "}"},
        {R"({"stokes": [1, )" + number(q) + ", " + number(u) + ", " + number(v) + R"(], "reference": )" + vec(r) + "}",
         R"({"stokes": [1, )" + number(qTurned) + ", " + number(uTurned) + ", " + number(v) + R"(], "reference": )" +
             vec(turned) + "}"}};
    for (const auto& [first, second] : descriptions) {
        SCOPED_TRACE(first + " against " + second);
        const Scene scene = sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337}, "glass": {"n": 1.52})",
                                          R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                                             {"type": "sphere", "center": [0.9, 0.4, 2.2], "radius": 0.7, "medium": "glass"})",
                                          pencil(first) + ", " + pencil(second));
        const OpticalScene optical(scene);
        for (std::uint64_t photon = 0; photon < 400; ++photon) {
            const std::vector<Event> a = recordedPath(optical, scene.sources[0], photon, TransportSettings{});
            const std::vector<Event> b = recordedPath(optical, scene.sources[1], photon, TransportSettings{});
            ASSERT_EQ(a.size(), b.size()) << photon;
            for (std::size_t e = 0; e < a.size(); ++e) {
                ASSERT_EQ(a[e].type, b[e].type) << photon << ", " << e;
                const StokesVector inA =
                    stokesInFrame(*b[e].polarisation, b[e].direction, a[e].polarisation->reference);
                EXPECT_LT((inA - a[e].polarisation->stokes).cwiseAbs().maxCoeff(), 1e-12) << photon << ", " << e;
            }
        }
    }
}

TEST(PolarisedTransport, EmittedPhotonsCarryTheSourcesStateInItsReferenceFrame) {
    Source source;
    source.type = SourceType::Beam;
    source.radius = 0.5;
    source.direction = Direction(0, 0, 1);
    source.polarisation = {PolarisationKind::Linear, 30.0, unpolarisedStokes(), Eigen::Vector3d(0, 3, 0.0000001)};
    const Polarisation light = emittedPolarisation(source, source.direction);
    EXPECT_EQ(light.reference, Eigen::Vector3d(0, 1, 0));  // normalised, and made exactly perpendicular
    EXPECT_NEAR(light.stokes[1], 0.5, 1e-15);
    EXPECT_NEAR(light.stokes[2], std::sqrt(3.0) / 2.0, 1e-15);
    source.polarisation.reference = Eigen::Vector3d(0, 1e200, 0);  // no square of it is taken
    EXPECT_EQ(emittedPolarisation(source, source.direction).reference, Eigen::Vector3d(0, 1, 0));
    const Polarisation unpolarised = emittedPolarisation(Source{}, Direction(0.3, -0.2, 0.9));
    EXPECT_EQ(unpolarised.stokes, StokesVector(1, 0, 0, 0));
    EXPECT_NEAR(unpolarised.reference.dot(Direction(0.3, -0.2, 0.9).vector()), 0.0, 1e-16);
    EXPECT_NEAR(unpolarised.reference.norm(), 1.0, 1e-15);
}

}  // namespace
}  // namespace dropscope
