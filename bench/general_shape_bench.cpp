// Distance queries per second of each parametric and implicit shape, as a ratio to the Sphere class's
// on the same rays in the same run (docs/performance.md, "Parametric and implicit shapes"). Every shape
// here has the sphere's or a similar size, so the rays hit about as often. Also checks that the
// parametric and implicit unit spheres agree with the Sphere on every ray.
// Run: build/bench/general_shape_bench [--seconds S]
#include "geometry/Sphere.hpp"
#include "geometry/implicit/ImplicitPresets.hpp"
#include "geometry/implicit/ImplicitShape.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "octree/Measure.hpp"
#include "scene/SceneLoader.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace dropscope;

struct Ray {
    Point origin;
    Direction direction;
};

// Rays from a shell of radius 3 towards random points of the ball of radius 0.8 (as shape_distance_bench).
std::vector<Ray> makeRays(std::size_t count) {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> normal;
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < count; ++i) {
        const Direction out(normal(rng), normal(rng), normal(rng));
        const Point target = 0.8 * Direction(normal(rng), normal(rng), normal(rng)).vector();
        const Point origin = 3.0 * out.vector();
        rays.push_back({origin, Direction(target - origin)});
    }
    return rays;
}

struct Timing {
    double queriesPerSecond = 0.0;
    double hitFraction = 0.0;
};

// Passes over the rays until `seconds` have gone by.
Timing time(const Shape& shape, const std::vector<Ray>& rays, double seconds) {
    bench::Stopwatch clock;
    std::size_t queries = 0;
    std::size_t hits = 0;
    while (clock.seconds() < seconds) {
        for (const Ray& ray : rays) hits += std::isnan(shape.distanceToSurface(ray.origin, ray.direction)) ? 0 : 1;
        queries += rays.size();
    }
    return {static_cast<double>(queries) / clock.seconds(), static_cast<double>(hits) / static_cast<double>(queries)};
}

// How many rays the shape answers differently from the sphere (hit vs miss, or distance beyond `tolerance`).
std::size_t disagreements(const Shape& shape, const Sphere& sphere, const std::vector<Ray>& rays, double tolerance) {
    std::size_t count = 0;
    for (const Ray& ray : rays) {
        const double a = shape.distanceToSurface(ray.origin, ray.direction);
        const double b = sphere.distanceToSurface(ray.origin, ray.direction);
        if (std::isnan(a) != std::isnan(b) || (!std::isnan(a) && std::abs(a - b) > tolerance)) ++count;
    }
    return count;
}

// The gallery's Bezier droplet (assets/shapes/flattened_droplet.json), at the origin.
std::unique_ptr<Shape> flattenedDroplet() {
    const std::string file = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/shapes_gallery.json";
    const Scene scene = loadScene(file);
    for (const auto& shape : scene.shapes) {
        const GeneralShape* general = asGeneralShape(*shape);
        if (general && general->presetName() == "bezier") return general->withTransform(AffineTransform());
    }
    std::fprintf(stderr, "%s has no bezier shape\n", file.c_str());
    std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 0.5;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: %s [--seconds S]\n", argv[0]);
            return 2;
        }
    }
    const std::vector<Ray> rays = makeRays(4096);
    const Sphere sphere(Point::Zero(), 1.0);
    const AffineTransform none;
    const AffineTransform tilted = AffineTransform::scaling(Eigen::Vector3d(1.0, 0.7, 0.4))
                                       .then(AffineTransform::rotation(Eigen::Vector3d(1, 1, 0), 0.6));
    struct Case {
        std::string name;
        std::unique_ptr<Shape> shape;
    };
    std::vector<Case> cases;
    cases.push_back({"sphere (class Sphere)", std::make_unique<Sphere>(sphere)});
    cases.push_back(
        {"parametric sphere", std::make_unique<ParametricShape>(makeParametricBase(makeSphereSurface(1.0)), none)});
    cases.push_back({"parametric sphere, scaled+rotated",
                     std::make_unique<ParametricShape>(makeParametricBase(makeSphereSurface(1.0)), tilted)});
    cases.push_back({"parametric torus R=0.7 r=0.3",
                     std::make_unique<ParametricShape>(makeParametricBase(makeTorusSurface(0.7, 0.3)), none)});
    cases.push_back({"parametric bezier droplet", flattenedDroplet()});
    cases.push_back({"implicit superellipsoid e=1",
                     std::make_unique<ImplicitShape>(
                         makeImplicitBase(makeSuperellipsoid(Eigen::Vector3d::Ones(), Eigen::Vector2d(1, 1))), none)});
    cases.push_back(
        {"implicit superellipsoid e=0.3",
         std::make_unique<ImplicitShape>(
             makeImplicitBase(makeSuperellipsoid(Eigen::Vector3d::Ones(), Eigen::Vector2d(0.3, 0.3))), none)});
    cases.push_back({"implicit blob of 2",
                     std::make_unique<ImplicitShape>(
                         makeImplicitBase(makeBlob({Point(-0.4, 0, 0), Point(0.4, 0, 0)}, {0.6, 0.6}, 0.1)), none)});

    std::printf("distance queries on %zu rays, %.2f s per shape\n\n", rays.size(), seconds);
    std::printf("%-36s %14s %10s %8s\n", "shape", "queries/s", "vs sphere", "hits");
    double reference = 0.0;
    for (const Case& c : cases) {
        const Timing t = time(*c.shape, rays, seconds);
        if (reference == 0.0) reference = t.queriesPerSecond;
        std::printf("%-36s %14.0f %9.4fx %7.1f%%\n", c.name.c_str(), t.queriesPerSecond, t.queriesPerSecond / reference,
                    100.0 * t.hitFraction);
    }
    // What sharing a base saves: building one (mesh, cover, integrals, extremes) per preset.
    std::printf("\nbuilding a base (mesh, cover, area, volume, extremes), once per preset:\n");
    const auto timeBase = [](const char* name, const auto& build) {
        bench::Stopwatch clock;
        [[maybe_unused]] const auto built = build();
        std::printf("  %-34s %8.1f ms\n", name, 1e3 * clock.seconds());
    };
    timeBase("parametric sphere", [] { return makeParametricBase(makeSphereSurface(1.0)); });
    timeBase("parametric torus", [] { return makeParametricBase(makeTorusSurface(0.7, 0.3)); });
    // An implicit base computes its parts when first asked: ask for all of them.
    const auto everything = [](std::shared_ptr<const ImplicitFunction> f) {
        const ImplicitShape shape(makeImplicitBase(std::move(f)), AffineTransform());
        return shape.volume() + shape.surfaceArea() + shape.xMax() +
               static_cast<double>(shape.mesh().vertices.size() + shape.surfaceCover().size());
    };
    timeBase("implicit superellipsoid e=1",
             [&] { return everything(makeSuperellipsoid(Eigen::Vector3d::Ones(), Eigen::Vector2d(1, 1))); });
    timeBase("implicit superellipsoid e=0.3",
             [&] { return everything(makeSuperellipsoid(Eigen::Vector3d::Ones(), Eigen::Vector2d(0.3, 0.3))); });
    timeBase("implicit blob of 2", [&] {
        return everything(makeBlob({Point(-0.4, 0, 0), Point(0.4, 0, 0)}, {0.6, 0.6}, 0.1));
    });

    // Same rays, same answers: the general unit spheres against the Sphere class.
    const double tolerance = 1e-9;
    std::printf("\nrays answered differently from the Sphere (distance tolerance %g):\n", tolerance);
    std::printf("  parametric sphere: %zu\n", disagreements(*cases[1].shape, sphere, rays, tolerance));
    std::printf("  implicit superellipsoid e=1: %zu\n", disagreements(*cases[5].shape, sphere, rays, tolerance));
    return 0;
}
