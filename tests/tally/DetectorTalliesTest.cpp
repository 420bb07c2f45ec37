// Detector geometry (plane crossings, far-field projections and solid angles) and the detector, order and
// budget tallies on made-up event streams: what they count, exact merges, first-K records for any split.
#include "tally/AngularTally.hpp"
#include "tally/BudgetTally.hpp"
#include "tally/DetectorTallies.hpp"
#include "tally/OrderTally.hpp"
#include "tally/TallySet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace dropscope {
namespace {

constexpr double kPi = std::numbers::pi;

Detector plane(DetectorSide side = DetectorSide::Both, bool absorbing = false) {
    Detector d;
    d.name = "screen";
    d.type = DetectorType::Plane;
    d.center = Point(0, 0, 2);
    d.normal = Direction(0, 0, -1);
    d.up = Eigen::Vector3d(0, 1, 0);
    d.size = {4.0, 2.0};
    d.pixels = {4, 2};
    d.side = side;
    d.absorbing = absorbing;
    return d;
}

Detector camera(FarFieldProjection projection, double fovDeg, int pixels) {
    Detector d;
    d.name = "sky";
    d.type = DetectorType::FarField;
    d.look = Direction(0, 0, 1);
    d.up = Eigen::Vector3d(0, 1, 0);
    d.projection = projection;
    d.fovDeg = fovDeg;
    d.pixels = {pixels, pixels};
    return d;
}

double totalSolidAngle(const Detector& d) {
    const FarFieldCamera cam(d);
    double sum = 0.0;
    for (int iy = 0; iy < d.pixels.ny; ++iy) {
        for (int ix = 0; ix < d.pixels.nx; ++ix) sum += cam.pixelSolidAngle(ix, iy);
    }
    return sum;
}

TEST(PlaneCrossing, CountsCrossingsInsideTheRectangleOnAdmittedSides) {
    const Detector both = plane();
    const PlaneFrame frame = planeFrame(both);
    // u = v x n = y x (-z) = -x: a point at x = +1.5 is at u = -1.5, pixel ix 0.
    const auto crossing = crossPlane(both, frame, Point(1.5, 0.5, 0), Direction(0, 0, 1), 10.0);
    ASSERT_TRUE(crossing);
    EXPECT_DOUBLE_EQ(crossing->distance, 2.0);
    EXPECT_DOUBLE_EQ(crossing->u, -1.5);
    EXPECT_DOUBLE_EQ(crossing->v, 0.5);
    EXPECT_EQ(crossing->pixel, both.pixels.index(0, 1));
    EXPECT_FALSE(crossPlane(both, frame, Point(1.5, 0.5, 0), Direction(0, 0, 1), 1.999));  // ends short
    EXPECT_TRUE(crossPlane(both, frame, Point(1.5, 0.5, 0), Direction(0, 0, 1), 2.0));     // ends on it
    EXPECT_FALSE(crossPlane(both, frame, Point(1.5, 0.5, 2), Direction(0, 0, 1), 5.0));    // starts on it
    EXPECT_FALSE(crossPlane(both, frame, Point(2.5, 0, 0), Direction(0, 0, 1), 5.0));      // beside it
    EXPECT_FALSE(crossPlane(both, frame, Point(0, 0, 0), Direction(1, 0, 0), 5.0));        // parallel
    // The far edges belong to the last pixels.
    const auto corner = crossPlane(both, frame, Point(-2, 1, 0), Direction(0, 0, 1), 5.0);
    ASSERT_TRUE(corner);
    EXPECT_EQ(corner->pixel, both.pixels.index(3, 1));
    // front: light arriving on the side the normal (-z) points to, travelling along +z.
    const Detector front = plane(DetectorSide::Front);
    EXPECT_TRUE(crossPlane(front, frame, Point(0, 0, 0), Direction(0, 0, 1), 5.0));
    EXPECT_FALSE(crossPlane(front, frame, Point(0, 0, 4), Direction(0, 0, -1), 5.0));
    const Detector back = plane(DetectorSide::Back);
    EXPECT_FALSE(crossPlane(back, frame, Point(0, 0, 0), Direction(0, 0, 1), 5.0));
    EXPECT_TRUE(crossPlane(back, frame, Point(0, 0, 4), Direction(0, 0, -1), 5.0));
}

TEST(FarFieldCamera, PixelCentresMapBackToTheirPixels) {
    for (const auto projection :
         {FarFieldProjection::Equidistant, FarFieldProjection::EqualArea, FarFieldProjection::Perspective}) {
        // Views whose corners stay inside each projection's domain.
        const double fov = projection == FarFieldProjection::Perspective ? 120.0
                           : projection == FarFieldProjection::EqualArea ? 160.0
                                                                         : 200.0;
        const Detector d = camera(projection, fov, 17);
        const FarFieldCamera cam(d);
        for (int iy = 0; iy < 17; ++iy) {
            for (int ix = 0; ix < 17; ++ix) {
                const auto viewing = cam.viewingDirection(ix, iy);
                ASSERT_TRUE(viewing) << ix << "," << iy;
                EXPECT_NEAR(viewing->norm(), 1.0, 1e-14);
                EXPECT_EQ(cam.pixelOf(*viewing), d.pixels.index(ix, iy));
            }
        }
    }
}

TEST(FarFieldCamera, RightIsLookCrossUpAndThetaIsMeasuredFromLook) {
    const Detector d = camera(FarFieldProjection::Equidistant, 90.0, 90);  // one degree per pixel
    const FarFieldCamera cam(d);
    EXPECT_EQ(cam.right(), Eigen::Vector3d(-1, 0, 0));  // looking along +z with +y up, -x is to the right
    // 30.5 degrees from look towards the right: in the 31st pixel right of the centre, in the middle rows.
    const double theta = 30.5 * kPi / 180.0;
    const Eigen::Vector3d viewing(-std::sin(theta), 0.0, std::cos(theta));
    const auto pixel = cam.pixelOf(viewing + Eigen::Vector3d(0, 1e-9, 0));
    ASSERT_TRUE(pixel);
    EXPECT_EQ(*pixel % 90, 75u);
    EXPECT_EQ(*pixel / 90, 45u);
    EXPECT_FALSE(cam.pixelOf(Eigen::Vector3d(0, 0, -1)));  // behind the camera: outside the image
}

TEST(FarFieldCamera, SolidAnglesAddUpToClosedForms) {
    // A perspective square of 90 degrees: a quarter of... the square pyramid of half-angle 45 degrees,
    // 4 asin(sin^2 45) = 2 pi / 3, exact per pixel.
    EXPECT_NEAR(totalSolidAngle(camera(FarFieldProjection::Perspective, 90.0, 33)), 2.0 * kPi / 3.0, 1e-12);
    // The equal-area disk r <= 2 is the whole sphere; pixels cut by the edge by the midpoint rule.
    EXPECT_NEAR(totalSolidAngle(camera(FarFieldProjection::EqualArea, 360.0, 64)), 4.0 * kPi, 2e-4);
    // Equidistant out to 180 degrees is the whole sphere too.
    EXPECT_NEAR(totalSolidAngle(camera(FarFieldProjection::Equidistant, 360.0, 64)), 4.0 * kPi, 2e-3);
    // A 60-degree equidistant square against the cap it contains and the cap containing it.
    const double inner = 2.0 * kPi * (1.0 - std::cos(kPi / 6));
    const double outer = 2.0 * kPi * (1.0 - std::cos(std::sqrt(2.0) * kPi / 6));
    const double square = totalSolidAngle(camera(FarFieldProjection::Equidistant, 60.0, 30));
    EXPECT_GT(square, inner);
    EXPECT_LT(square, outer);
}

// Events of made-up photons for the event-driven tallies.
struct Photon {
    PhotonState state;
    std::vector<Event> events;
};

Event event(EventType type, ShapeId shape = RayHit::kNone, Direction direction = Direction(0, 0, 1)) {
    Event e;
    e.type = type;
    e.shape = shape;
    e.direction = direction;
    return e;
}

void score(Tally& tally, std::uint64_t index, Photon& photon) {
    for (const Event& e : photon.events) tally.score(e, {index, 0, photon.state});
}

TEST(OrderTally, RayOrderIsEventsAtTheOneShapeMetLessOne) {
    OrderTally tally(180);
    const Direction back(0, 0, -1);
    std::vector<Photon> photons(5, Photon{{{Point::Zero(), Direction(0, 0, 1)}}, {}});
    photons[0].events = {event(EventType::Emit), event(EventType::Reflect, 3),
                         event(EventType::Escape, RayHit::kNone, back)};
    photons[1].events = {event(EventType::Emit), event(EventType::Refract, 3), event(EventType::Tir, 3),
                         event(EventType::Refract, 3), event(EventType::Escape, RayHit::kNone, back)};
    photons[2].events = {event(EventType::Emit), event(EventType::Refract, 3), event(EventType::Refract, 4),
                         event(EventType::Escape)};
    photons[3].events = {event(EventType::Emit), event(EventType::Escape)};  // unscattered
    photons[4].events = {event(EventType::Emit), event(EventType::Refract, 1), event(EventType::Absorb)};
    for (std::size_t i = 0; i < photons.size(); ++i) score(tally, i, photons[i]);
    EXPECT_EQ(tally.order(0)[179], 1u);
    EXPECT_EQ(tally.order(2)[179], 1u);
    EXPECT_EQ(tally.multiple()[0], 1u);
    EXPECT_EQ(tally.singleTotal(), 2u);
    EXPECT_EQ(tally.multipleTotal(), 1u);
    ResultReport report;
    tally.report(report);
    EXPECT_EQ(std::get<double>(*report.find({"single_scattering"})), 2.0 / 5.0);
    EXPECT_EQ(std::get<double>(*report.find({"multiple_scattering"})), 1.0 / 5.0);
    const ResultTable* table = report.table("angular_orders");
    ASSERT_TRUE(table);
    std::vector<std::string> names;
    for (const auto& column : table->columns) names.push_back(column.name);
    EXPECT_EQ(names, (std::vector<std::string>{"theta_lo_deg", "theta_hi_deg", "p0", "p1", "p2", "p3", "p4", "p5_plus",
                                               "multiple"}));
}

// A droplet that diffracts a photon is met by it: alone it is the "diffraction" column, with another shape multiple.
TEST(OrderTally, DiffractedPhotonsHaveTheirOwnColumnInSingleScattering) {
    OrderTally tally(180, true);
    const Direction back(0, 0, -1);
    std::vector<Photon> photons(3, Photon{{{Point::Zero(), Direction(0, 0, 1)}}, {}});
    photons[0].events = {event(EventType::Emit), event(EventType::Diffract, 3), event(EventType::Escape)};
    photons[1].events = {event(EventType::Emit), event(EventType::Diffract, 3), event(EventType::Reflect, 4),
                         event(EventType::Escape, RayHit::kNone, back)};
    photons[2].events = {event(EventType::Emit), event(EventType::Refract, 4), event(EventType::Refract, 4),
                         event(EventType::Escape)};
    for (std::size_t i = 0; i < photons.size(); ++i) score(tally, i, photons[i]);
    EXPECT_EQ(tally.diffracted()[0], 1u);
    EXPECT_EQ(tally.multiple()[179], 1u);
    EXPECT_EQ(tally.order(1)[0], 1u);
    EXPECT_EQ(tally.singleTotal(), 2u);
    ResultReport report;
    tally.report(report);
    const ResultTable* table = report.table("angular_orders");
    ASSERT_TRUE(table);
    EXPECT_EQ(table->columns.back().name, "diffraction");
    EXPECT_EQ(std::get<std::vector<double>>(table->columns.back().values)[0], 1.0 / 3.0);
    // Without diffraction the table keeps its nine columns.
    ResultReport plain;
    OrderTally(180).report(plain);
    EXPECT_EQ(plain.table("angular_orders")->columns.size(), 9u);
}

// results.h5 records each column's unit (docs/results-format.md): the angle tables state theirs alike.
TEST(OrderTally, AngleColumnsHaveTheUnitsOfAngularCsv) {
    ResultReport report;
    AngularTally(4, true).report(report);
    OrderTally(4).report(report);
    for (const char* name : {"angular", "angular_orders"}) {
        const ResultTable* table = report.table(name);
        ASSERT_TRUE(table) << name;
        EXPECT_EQ(table->column("theta_lo_deg")->unit, "deg") << name;
        EXPECT_EQ(table->column("theta_hi_deg")->unit, "deg") << name;
    }
    // Shares of the emitted photons have none.
    EXPECT_EQ(report.table("angular")->column("fraction")->unit, "");
    EXPECT_EQ(report.table("angular_orders")->column("p2")->unit, "");
    EXPECT_EQ(report.table("angular")->column("fraction_per_sr")->unit, "1/sr");
}

TEST(BudgetTally, PutsEveryPhotonInOnePlace) {
    std::vector<Detector> detectors{camera(FarFieldProjection::Equidistant, 90.0, 4), plane(DetectorSide::Both, true)};
    BudgetTally tally(detectors, {"air", "water"});
    std::vector<Photon> photons(5, Photon{{{Point::Zero(), Direction(0, 0, 1)}}, {}});
    photons[0].events = {event(EventType::Emit), event(EventType::Escape, RayHit::kNone, Direction(0, 0, -1))};  // seen
    photons[1].events = {event(EventType::Emit), event(EventType::Escape)};  // elsewhere
    Event absorbed = event(EventType::Absorb);
    absorbed.from = 1;
    photons[2].events = {event(EventType::Emit), absorbed};
    Event detected = event(EventType::Detect);
    detected.detector = 1;
    photons[3].events = {event(EventType::Emit), detected};
    Event lost = event(EventType::Lost);
    lost.lostReason = LostReason::NoExit;
    photons[4].events = {event(EventType::Emit), lost};
    for (std::size_t i = 0; i < photons.size(); ++i) score(tally, i, photons[i]);
    ResultReport report;
    tally.report(report);
    const auto count = [&](std::vector<std::string> path) {
        path.insert(path.begin(), "budget");
        path.push_back("count");
        return std::get<std::uint64_t>(*report.find(path));
    };
    EXPECT_EQ(count({"escaped", "far_field", "sky"}), 1u);
    EXPECT_EQ(count({"escaped", "elsewhere"}), 1u);
    EXPECT_EQ(count({"absorbed", "by_medium", "water"}), 1u);
    EXPECT_EQ(count({"absorbed", "by_medium", "air"}), 0u);
    EXPECT_EQ(count({"detected", "by_detector", "screen"}), 1u);
    EXPECT_EQ(count({"lost", "by_reason", "no_exit"}), 1u);
    EXPECT_EQ(count({"escaped"}) + count({"absorbed"}) + count({"detected"}) + count({"lost"}), 5u);
    EXPECT_EQ(std::get<double>(*report.find({"budget", "escaped", "share"})), 0.4);
}

// Random flights through a plane detector, split between "threads" in two ways.
TEST(PlaneDetectorTally, MergedSplitsGiveTheSameTableAndRecords) {
    Detector d = plane();
    d.record = 25;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Flight> flights;
    std::vector<Polarisation> lights;
    for (int i = 0; i < 400; ++i) {
        const Eigen::Vector3d to(3 * unit(random), 2 * unit(random), 2.0);
        const Point from(unit(random), unit(random), -1.0);
        flights.push_back({from, Direction((to - from).normalized()), 10.0, 0, nullptr});
        lights.push_back({StokesVector(1.0, 0.3 * unit(random), 0.3 * unit(random), 0.1), Eigen::Vector3d::UnitX()});
    }
    const auto run = [&](std::size_t split) {
        PlaneDetectorTally first(d, 0, true);
        auto second = first.emptyCopy();
        for (std::size_t i = 0; i < flights.size(); ++i) {
            Tally& into = i < split ? static_cast<Tally&>(first) : *second;
            PhotonState state{{flights[i].origin, flights[i].direction}};
            Flight flight = flights[i];
            // a reference perpendicular to the flight
            Eigen::Vector3d reference = Eigen::Vector3d::UnitX() - flight.direction.x() * flight.direction.vector();
            Polarisation light{lights[i].stokes, reference.normalized()};
            flight.polarisation = &light;
            into.score(event(EventType::Emit), {i, 0, state});
            into.scoreFlight(flight, {i, 0, state});
        }
        auto merged = first.emptyCopy();
        merged->merge(*second);  // the later photons first: merges need no order
        merged->merge(first);
        ResultReport report;
        merged->report(report);
        return report;
    };
    const ResultReport a = run(0);
    const ResultReport b = run(173);
    const ResultReport c = run(400);
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, c);
    const ResultTable* records = a.table("detector-screen-records");
    ASSERT_TRUE(records);
    ASSERT_EQ(records->rows(), 25u);
    const auto& photon = std::get<std::vector<std::uint64_t>>(records->columns[0].values);
    EXPECT_TRUE(std::is_sorted(photon.begin(), photon.end()));
    const ResultTable* image = a.table("detector-screen");
    ASSERT_TRUE(image);
    EXPECT_EQ(image->grid, (std::vector<std::size_t>{2, 4}));
    double total = 0.0;
    for (double f : std::get<std::vector<double>>(image->columns[4].values)) total += f;
    EXPECT_EQ(std::get<std::uint64_t>(*a.find({"detectors", "screen", "hits"})),
              static_cast<std::uint64_t>(std::lround(total * 400)));
    EXPECT_GT(total, 0.25);  // the targets cover 6 x 4 around the 4 x 2 rectangle: about a third cross it
}

TEST(HitRecords, KeepsTheFirstKByPhotonThenSequence) {
    HitRecords records(3);
    for (std::uint64_t photon : {9u, 4u, 7u, 1u, 8u}) records.offer({photon, 0});
    records.offer({4, 1});
    ASSERT_EQ(records.hits().size(), 3u);
    EXPECT_EQ(records.hits()[0].photon, 1u);
    EXPECT_EQ(records.hits()[1].photon, 4u);
    EXPECT_EQ(records.hits()[1].sequence, 0u);
    EXPECT_EQ(records.hits()[2].sequence, 1u);
    HitRecords other(3);
    other.offer({0, 0});
    records.merge(other);
    EXPECT_EQ(records.hits()[0].photon, 0u);
    EXPECT_EQ(records.hits()[2].photon, 4u);
}

}  // namespace
}  // namespace dropscope
