// The octree against brute force and Embree 3 on random non-overlapping droplet clouds, one thread:
// build time, memory per droplet, and first-hit throughput for independent random rays and for photon
// walks, with every octree hit checked against the exact peers in the same run. docs/performance.md
// has the figures and how to read them.
//
// Run: build/bench/octree_bench [--min-n 1e3] [--max-n 1e6] [--rays 1e6] [--brute-rays K]
//                               [--brute-max-n 1e4] [--repeat 1] [--seed 1] [--max-depth D] [--max-leaf K]
#include "geometry/Sphere.hpp"
#include "octree/CountArgument.hpp"
#include "octree/EmbreePeers.hpp"
#include "octree/Measure.hpp"
#include "octree/Rays.hpp"
#include "octree/SphereCloud.hpp"
#include "tree/Octree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace dropscope;
using namespace dropscope::bench;

// The platform note's cloud: 1e6 droplets of radius 0.002-0.005 in [-1, 1]^3 (2.7 % of the volume).
// Smaller clouds keep the radii and the density, so their cube shrinks as N^(1/3).
constexpr double kMinRadius = 0.002;
constexpr double kMaxRadius = 0.005;
constexpr double kReferenceCount = 1e6;
constexpr double kReferenceHalfSide = 1.0;

// Float peers, relative to the cube's half-side: a float origin on a droplet is off its surface by
// ~1e-7 of the coordinates, so Embree's float sphere needs tnear above that to not re-hit the surface
// a walk segment leaves (1e-5: 100x margin, still far below the smallest chord that matters); the user
// geometry's boxes are padded by as much so that no sphere the double ray reaches is culled.
constexpr double kFloatTnearRelative = 1e-5;
constexpr double kUserBoundsPadRelative = 1e-5;

// Rays replayed with TraversalRecord to count the octree's work (not timed).
constexpr std::size_t kRecordedRays = 10000;

struct Options {
    std::size_t minCount = 1000;  // N runs over minCount, 10 minCount, ... up to maxCount
    std::size_t maxCount = 1000000;
    std::size_t rays = 1000000;
    std::size_t bruteRays = 0;  // 0: min(rays, 1e8 / N)
    std::size_t bruteMaxCount = 10000;
    int repeat = 1;
    std::uint64_t seed = 1;
    OctreeSettings octree;  // the engine's defaults unless --max-depth / --max-leaf
};

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout
                << "octree_bench [--min-n 1e3] [--max-n 1e6] [--rays 1e6] [--brute-rays K (default min(rays, 1e8/N))]\n"
                   "             [--brute-max-n 1e4] [--repeat 1 (best of, per chunk of 1e5 rays)] [--seed 1]\n"
                   "             [--max-depth D] [--max-leaf K] (octree settings; engine defaults otherwise)\n";
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const char* value = argv[++i];
        if (flag == "--min-n")
            options.minCount = parseCount(flag, value);
        else if (flag == "--max-n")
            options.maxCount = parseCount(flag, value);
        else if (flag == "--rays")
            options.rays = parseCount(flag, value);
        else if (flag == "--brute-rays")
            options.bruteRays = parseCount(flag, value);
        else if (flag == "--brute-max-n")
            options.bruteMaxCount = parseCount(flag, value);
        else if (flag == "--repeat")
            options.repeat = std::max(1, static_cast<int>(parseCount(flag, value)));
        else if (flag == "--seed")
            options.seed = parseCount(flag, value);
        else if (flag == "--max-depth")
            options.octree.maxDepth = static_cast<int>(parseCount(flag, value));
        else if (flag == "--max-leaf")
            options.octree.maxShapesPerLeaf = static_cast<int>(parseCount(flag, value));
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    if (options.rays == 0) throw std::invalid_argument("--rays must be > 0");
    if (options.minCount == 0) throw std::invalid_argument("--min-n must be > 0");
    return options;
}

struct Timed {
    double seconds = 0.0;  // the sum over the chunks of the best of the repeats (trace)
    std::vector<RayHit> hits;
    double mraysPerSecond() const { return static_cast<double>(hits.size()) / seconds * 1e-6; }
};

// Rays a peer traces in one go before the next peer takes its turn (trace).
constexpr std::size_t kChunkRays = 100000;

// The first hits of the first `count` rays by one or more peers, in turns so that the machine's slow spells
// (other guests on the host) fall on them alike: each chunk of kChunkRays rays is traced `repeat` times by every
// peer in turn, the first of them changing from chunk to chunk, and a peer's time is the sum over the chunks of
// its best time for each. A spell then spoils one attempt at one chunk rather than one peer's whole figure. The
// peers' calls stay inline in the timed loops.
template <class... FirstHit>
std::array<Timed, sizeof...(FirstHit)> trace(const std::vector<Ray>& rays, std::size_t count, int repeat,
                                             FirstHit&&... peers) {
    constexpr std::size_t kPeers = sizeof...(FirstHit);
    const std::size_t traced = std::min(count, rays.size());
    std::array<Timed, kPeers> timed;
    for (Timed& peer : timed) peer.hits.resize(traced);
    for (std::size_t begin = 0, chunk = 0; begin < traced; begin += kChunkRays, ++chunk) {
        const std::size_t end = std::min(traced, begin + kChunkRays);
        std::array<double, kPeers> best;
        best.fill(std::numeric_limits<double>::infinity());
        // Peer k's attempt at this chunk.
        const auto attempt = [&](std::size_t k, auto& firstHit) {
            const Stopwatch watch;
            for (std::size_t i = begin; i < end; ++i) timed[k].hits[i] = firstHit(rays[i]);
            best[k] = std::min(best[k], watch.seconds());
        };
        for (int r = 0; r < repeat; ++r) {
            for (std::size_t turn = 0; turn < kPeers; ++turn) {
                const std::size_t k = (chunk + turn) % kPeers;
                std::size_t peer = 0;
                ((peer++ == k ? attempt(k, peers) : void()), ...);
            }
        }
        for (std::size_t k = 0; k < kPeers; ++k) timed[k].seconds += best[k];
    }
    return timed;
}

// Rays (over the shorter list) whose hits differ in shape or distance (exact comparison).
std::size_t exactMismatches(const std::vector<RayHit>& a, const std::vector<RayHit>& b) {
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        if (a[i].shape != b[i].shape || a[i].distance != b[i].distance) ++mismatches;
    }
    return mismatches;
}

std::size_t sameShape(const std::vector<RayHit>& a, const std::vector<RayHit>& b) {
    std::size_t same = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) same += a[i].shape == b[i].shape ? 1 : 0;
    return same;
}

struct OrderResult {
    std::string name;
    std::size_t rays = 0;
    std::size_t bruteRays = 0;  // 0: brute force not run
    double brute = 0.0;         // Mrays/s
    double octree = 0.0;
    double embreeFloat = 0.0;
    double embreeUser = 0.0;
    std::size_t bruteMismatches = 0;
    std::size_t userMismatches = 0;
    double floatSameShape = 0.0;     // fraction of rays
    double hitFraction = 0.0;        // rays that hit a droplet
    double cellsPerRay = 0.0;        // octree, on the first kRecordedRays rays
    double sphereTestsPerRay = 0.0;  // octree distance evaluations
    double uniqueTestsPerRay = 0.0;  // distinct shapes among them
    double userTestsPerRay = 0.0;    // Embree user-geometry callbacks
};

struct SizeResult {
    std::size_t count = 0;
    double halfSide = 0.0;
    double octreeBuild = 0.0;
    double oneByOneBuild = 0.0;
    double floatBuild = 0.0;
    double userBuild = 0.0;
    double octreeBytesUsed = 0.0;  // per droplet: Octree::bytesUsed()
    double octreeHeap = 0.0;       // per droplet: mallinfo2 across the constructor
    double octreeTotal = 0.0;      // per droplet: mallinfo2 across making the Spheres and the octree
    double floatBytes = 0.0;       // per droplet: Embree's memory monitor
    double userBytes = 0.0;        // per droplet: Embree's memory monitor + our packed spheres
    int depth = 0;
    int gridLevel = 0;
    std::size_t leaves = 0;
    double referencesPerDroplet = 0.0;
    std::vector<OrderResult> orders;
};

void recordWork(const Octree& octree, const std::vector<Ray>& rays, OrderResult& result) {
    const std::size_t count = std::min(kRecordedRays, rays.size());
    TraversalRecord record;
    double cells = 0.0;
    double tests = 0.0;
    double unique = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        octree.firstHit(rays[i].origin, rays[i].direction, record);
        cells += static_cast<double>(record.cells.size());
        tests += static_cast<double>(record.distanceEvaluations);
        std::sort(record.shapesTested.begin(), record.shapesTested.end());
        unique += static_cast<double>(std::unique(record.shapesTested.begin(), record.shapesTested.end()) -
                                      record.shapesTested.begin());
    }
    const auto n = static_cast<double>(count);
    result.cellsPerRay = cells / n;
    result.sphereTestsPerRay = tests / n;
    result.uniqueTestsPerRay = unique / n;
}

OrderResult runOrder(const std::string& name, const std::vector<Ray>& rays, const Octree& octree,
                     const EmbreeFloatSpheres& embreeFloat, EmbreeUserSpheres& embreeUser, double floatTnear,
                     std::size_t bruteRays, const Options& options) {
    OrderResult result;
    result.name = name;
    result.rays = rays.size();
    std::cerr << "  " << name << ": octree, embree float and embree user in turns" << std::flush;
    const auto ft = static_cast<float>(floatTnear);
    const std::size_t testsBefore = embreeUser.sphereTests();
    const auto [byOctree, byFloat, byUser] = trace(
        rays, rays.size(), options.repeat, [&](const Ray& ray) { return octree.firstHit(ray.origin, ray.direction); },
        [&](const Ray& ray) { return embreeFloat.firstHit(ray, ft); },
        [&](const Ray& ray) { return embreeUser.firstHit(ray); });
    result.userTestsPerRay = static_cast<double>(embreeUser.sphereTests() - testsBefore) /
                             static_cast<double>(rays.size() * static_cast<std::size_t>(options.repeat));
    if (bruteRays > 0) {
        std::cerr << ", brute force" << std::flush;
        const auto [byBrute] = trace(rays, bruteRays, options.repeat, [&](const Ray& ray) {
            return bruteForceFirstHit(octree.shapes(), ray.origin, ray.direction);
        });
        result.bruteRays = byBrute.hits.size();
        result.brute = byBrute.mraysPerSecond();
        result.bruteMismatches = exactMismatches(byOctree.hits, byBrute.hits);
    }
    std::cerr << '\n';
    result.octree = byOctree.mraysPerSecond();
    result.embreeFloat = byFloat.mraysPerSecond();
    result.embreeUser = byUser.mraysPerSecond();
    result.userMismatches = exactMismatches(byOctree.hits, byUser.hits);
    const auto n = static_cast<double>(rays.size());
    result.floatSameShape = static_cast<double>(sameShape(byOctree.hits, byFloat.hits)) / n;
    result.hitFraction = static_cast<double>(std::count_if(byOctree.hits.begin(), byOctree.hits.end(),
                                                           [](const RayHit& h) { return bool(h); })) /
                         n;
    recordWork(octree, rays, result);
    return result;
}

SizeResult runSize(std::size_t count, const Options& options) {
    SizeResult result;
    result.count = count;
    result.halfSide = kReferenceHalfSide * std::cbrt(static_cast<double>(count) / kReferenceCount);
    const auto perDroplet = [&](double bytes) { return bytes / static_cast<double>(count); };
    std::cerr << "N = " << count << ": cloud" << std::flush;
    const SphereCloud cloud({count, result.halfSide, kMinRadius, kMaxRadius, options.seed + count});

    std::cerr << ", octree" << std::flush;
    const std::size_t heapStart = heapInUse();
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.reserve(count);
    for (const Droplet& droplet : cloud.droplets())
        shapes.push_back(std::make_unique<Sphere>(droplet.center, droplet.radius));
    const std::size_t heapShapes = heapInUse();
    const Stopwatch octreeWatch;
    const Octree octree(std::move(shapes), options.octree);
    result.octreeBuild = octreeWatch.seconds();
    const std::size_t heapOctree = heapInUse();
    result.octreeBytesUsed = perDroplet(static_cast<double>(octree.bytesUsed()));
    result.octreeHeap = perDroplet(static_cast<double>(heapOctree) - static_cast<double>(heapShapes));
    result.octreeTotal = perDroplet(static_cast<double>(heapOctree) - static_cast<double>(heapStart));
    result.gridLevel = octree.gridLevel();
    {
        // The same tree placed one shape at a time (OctreeBuild::OneByOne), as the octree was built before the
        // top-down build: its peer for the build time.
        std::vector<std::unique_ptr<Shape>> copies;
        copies.reserve(count);
        for (const auto& shape : octree.shapes()) copies.push_back(shape->clone());
        const Stopwatch oneByOneWatch;
        const Octree oneByOne(std::move(copies), options.octree, OctreeBuild::OneByOne);
        result.oneByOneBuild = oneByOneWatch.seconds();
    }
    for (const LevelStatistics& level : octree.statistics()) {
        result.depth = std::max(result.depth, level.level);
        result.leaves += level.leaves;
        result.referencesPerDroplet += perDroplet(static_cast<double>(level.shapesStored));
    }

    std::cerr << ", embree" << std::flush;
    EmbreeDevice device;
    const std::int64_t deviceStart = device.bytesInUse();
    const Stopwatch floatWatch;
    const EmbreeFloatSpheres embreeFloat(device, cloud.droplets());
    result.floatBuild = floatWatch.seconds();
    const std::int64_t deviceFloat = device.bytesInUse();
    result.floatBytes = perDroplet(static_cast<double>(deviceFloat - deviceStart));

    const Stopwatch userWatch;
    std::vector<SphereGeometry> geometries;
    geometries.reserve(count);
    for (const auto& shape : octree.shapes()) geometries.push_back(static_cast<const Sphere&>(*shape).geometry());
    EmbreeUserSpheres embreeUser(device, std::move(geometries), kUserBoundsPadRelative * result.halfSide);
    result.userBuild = userWatch.seconds();
    result.userBytes = perDroplet(static_cast<double>(device.bytesInUse() - deviceFloat) +
                                  static_cast<double>(embreeUser.bytesOwned()));

    std::cerr << ", rays\n";
    const std::size_t bruteRays =
        count > options.bruteMaxCount
            ? 0
            : std::min(options.rays, options.bruteRays > 0
                                         ? options.bruteRays
                                         : static_cast<std::size_t>(1e8 / static_cast<double>(count)));
    const double floatTnear = kFloatTnearRelative * result.halfSide;
    const std::vector<Ray> randoms = randomRays(cloud, options.rays, options.seed * 7919 + count);
    result.orders.push_back(
        runOrder("random", randoms, octree, embreeFloat, embreeUser, floatTnear, bruteRays, options));
    const std::vector<Ray> walks = photonWalks(cloud, options.rays, options.seed * 104729 + count, [&](const Ray& ray) {
        return octree.firstHit(ray.origin, ray.direction);
    });
    result.orders.push_back(runOrder("walk", walks, octree, embreeFloat, embreeUser, floatTnear, bruteRays, options));
    return result;
}

void printTables(const std::vector<SizeResult>& results, double floatTnearRelative) {
    std::cout << "\n### Build and memory (bytes per droplet)\n\n"
                 "| N | cube half-side | octree build s | one by one s | Embree float build s | Embree user build s | "
                 "octree bytesUsed | octree heap | octree + Spheres heap | Embree float | Embree user + spheres | "
                 "octree depth | top grid level | leaves | references per droplet |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SizeResult& r : results) {
        std::cout << "| " << r.count << " | " << fixed(r.halfSide, 3) << " | " << fixed(r.octreeBuild, 3) << " | "
                  << fixed(r.oneByOneBuild, 3) << " | " << fixed(r.floatBuild, 3) << " | " << fixed(r.userBuild, 3)
                  << " | " << fixed(r.octreeBytesUsed, 1) << " | " << fixed(r.octreeHeap, 0) << " | "
                  << fixed(r.octreeTotal, 0) << " | " << fixed(r.floatBytes, 0) << " | " << fixed(r.userBytes, 0)
                  << " | " << r.depth << " | " << r.gridLevel << " | " << r.leaves << " | "
                  << fixed(r.referencesPerDroplet, 2) << " |\n";
    }
    std::cout << "\n### Throughput (Mrays/s, one thread)\n\n"
                 "| N | rays | brute force | octree | Embree float | Embree user (double) | octree / Embree float | "
                 "octree / Embree user |\n|---|---|---|---|---|---|---|---|\n";
    for (const SizeResult& r : results) {
        for (const OrderResult& o : r.orders) {
            std::cout << "| " << r.count << " | " << o.name << " | " << (o.bruteRays ? fixed(o.brute, 4) : "-") << " | "
                      << fixed(o.octree, 3) << " | " << fixed(o.embreeFloat, 3) << " | " << fixed(o.embreeUser, 3)
                      << " | " << fixed(o.octree / o.embreeFloat, 2) << " | " << fixed(o.octree / o.embreeUser, 2)
                      << " |\n";
        }
    }
    std::cout << "\n### Agreement and work per ray\n\n"
                 "Float peer: tnear = "
              << floatTnearRelative
              << " x cube half-side; the others count only t > 0.\n\n"
                 "| N | rays | traced | hit a droplet | brute-checked | octree != brute | octree != Embree user | "
                 "Embree float same shape | octree cells/ray | octree sphere tests/ray | distinct spheres/ray | "
                 "Embree user tests/ray |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SizeResult& r : results) {
        for (const OrderResult& o : r.orders) {
            std::cout << "| " << r.count << " | " << o.name << " | " << o.rays << " | "
                      << fixed(100.0 * o.hitFraction, 1) << " % | " << o.bruteRays << " | "
                      << (o.bruteRays ? std::to_string(o.bruteMismatches) : "-") << " | " << o.userMismatches << " | "
                      << fixed(100.0 * o.floatSameShape, 4) << " % | " << fixed(o.cellsPerRay, 1) << " | "
                      << fixed(o.sphereTestsPerRay, 1) << " | " << fixed(o.uniqueTestsPerRay, 1) << " | "
                      << fixed(o.userTestsPerRay, 1) << " |\n";
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        std::cout << "octree_bench: rays " << options.rays << " per order, repeat " << options.repeat << ", seed "
                  << options.seed << ", octree max_depth " << options.octree.maxDepth << ", max_shapes_per_leaf "
                  << options.octree.maxShapesPerLeaf << '\n';
        std::vector<SizeResult> results;
        for (std::size_t count = options.minCount; count <= options.maxCount; count *= 10)
            results.push_back(runSize(count, options));
        printTables(results, kFloatTnearRelative);
        bool exact = true;
        for (const SizeResult& r : results) {
            for (const OrderResult& o : r.orders) exact = exact && o.bruteMismatches == 0 && o.userMismatches == 0;
        }
        std::cout << "\nevery octree hit identical to brute force and to the Embree double peer: "
                  << (exact ? "yes" : "NO") << '\n';
        return exact ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "octree_bench: " << error.what() << '\n';
        return 2;
    }
}
