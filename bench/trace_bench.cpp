// Photon transport through a cloud of 1e5 water droplets: photons per second with 1 and 2
// threads, and what one photon costs. The reference, measured in the same run, is Octree::firstHit
// alone on the photons' own segments (the emission and every interface event of recorded photons,
// replayed in order), which splits the time per photon into the octree search and the rest (surface
// crossing, Fresnel, random numbers, emission, tallies). Every run's tally must be identical, whatever
// the thread count, and OpticalScene::nextSurface (the tracer's query, which skips the search inside a sealed
// droplet) must equal firstHit on every segment; the program exits 1 if not. docs/performance.md ("Photon transport")
// has the figures and how to read them.
//
// Run: build/bench/trace_bench [--photons 2e5] [--repeat 5] [--threads 2] [--reference-photons 2e4] [--pairs 10]
//                              [--seed 1] [--scene FILE] [--polarisation none|stokes]
// The photons are traced without polarisation unless asked (the figures of docs/performance.md were
// measured so; polarisation_bench measures what Stokes vectors cost).
#include "CloudScene.hpp"
#include "geometry/Sphere.hpp"
#include "octree/CountArgument.hpp"
#include "octree/Measure.hpp"
#include "run/TraceRun.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/FateTally.hpp"
#include "tally/StandardTallies.hpp"
#include "transport/OpticalScene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace dropscope;
using dropscope::bench::cloudSceneText;
using dropscope::bench::fixed;
using dropscope::bench::median;
using dropscope::bench::parseCount;
using dropscope::bench::Stopwatch;

// The built-in cloud: 1e5 water droplets in a cube of half-side 15 mm (bench/CloudScene.hpp): 2.7 % of
// the volume, and a mean optical depth of about 4.5 along the beam, so about 1 % of the photons cross
// it without meeting a droplet.
constexpr std::size_t kDroplets = 100000;
constexpr double kHalfSide = 15.0;

struct Options {
    std::uint64_t photons = 200000;
    int repeat = 5;
    int threads = 2;                         // compared with 1
    std::uint64_t referencePhotons = 20000;  // photons whose segments are replayed through firstHit
    int pairs = 10;                          // traces of those photons, each beside replays of their segments
    std::uint64_t seed = 1;
    std::optional<std::string> scene;  // a scene file instead of the built-in cloud
    PolarisationModel polarisation = PolarisationModel::None;
};

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout << "trace_bench [--photons 2e5] [--repeat 5 (median of)] [--threads 2 (against 1)]\n"
                         "            [--reference-photons 2e4] [--pairs 10 (traces of those, each beside their "
                         "replays)] [--seed 1] [--scene FILE (default: the built-in 1e5 "
                         "cloud)]\n            [--polarisation none|stokes (default none)]\n";
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const char* value = argv[++i];
        if (flag == "--photons")
            options.photons = parseCount(flag, value);
        else if (flag == "--repeat")
            options.repeat = std::max(1, static_cast<int>(parseCount(flag, value)));
        else if (flag == "--threads")
            options.threads = std::max(1, static_cast<int>(parseCount(flag, value)));
        else if (flag == "--reference-photons")
            options.referencePhotons = parseCount(flag, value);
        else if (flag == "--pairs")
            options.pairs = std::max(1, static_cast<int>(parseCount(flag, value)));
        else if (flag == "--seed")
            options.seed = parseCount(flag, value);
        else if (flag == "--scene")
            options.scene = value;
        else if (flag == "--polarisation" && (std::string(value) == "none" || std::string(value) == "stokes"))
            options.polarisation = std::string(value) == "none" ? PolarisationModel::None : PolarisationModel::Stokes;
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    if (options.photons == 0) throw std::invalid_argument("--photons must be > 0");
    if (options.referencePhotons == 0) throw std::invalid_argument("--reference-photons must be > 0");
    return options;
}

double best(const std::vector<double>& values) { return *std::min_element(values.begin(), values.end()); }

// Every tally of two runs reports the same numbers.
bool sameTallies(const TraceResult& a, const TraceResult& b) {
    ResultReport reportA, reportB;
    a.tallies.report(reportA);
    b.tallies.report(reportB);
    return a.photons == b.photons && reportA == reportB;
}

// Medians over the repeats of: cloning the scene's shapes, an Octree over the clones alone, and the
// whole OpticalScene (clone + octree + each shape's parent through the octree's overlap query).
struct BuildTimes {
    double clone = 0.0;
    double octree = 0.0;
    double opticalScene = 0.0;
};

std::unique_ptr<OpticalScene> buildOpticalScene(const Scene& scene, int repeat, BuildTimes& times) {
    std::vector<double> clone;
    std::vector<double> octree;
    std::vector<double> whole;
    std::unique_ptr<OpticalScene> optical;
    for (int r = 0; r < repeat; ++r) {
        optical.reset();
        const Stopwatch cloneWatch;
        std::vector<std::unique_ptr<Shape>> copies;
        copies.reserve(scene.shapes.size());
        for (const auto& shape : scene.shapes) copies.push_back(shape->clone());
        clone.push_back(cloneWatch.seconds());
        const Stopwatch octreeWatch;
        {
            const Octree alone(std::move(copies), scene.octree);
            octree.push_back(octreeWatch.seconds());
        }
        const Stopwatch wholeWatch;
        optical = std::make_unique<OpticalScene>(scene);
        whole.push_back(wholeWatch.seconds());
    }
    times = {median(clone), median(octree), median(whole)};
    return optical;
}

// Sum of pi r^2 over the spheres per unit area of the built-in cloud's face: the mean optical depth of
// the cloud along the beam, so exp(-tau) is the expected unscattered fraction.
double builtInOpticalDepth(const Scene& scene) {
    double crossSection = 0.0;
    for (const auto& shape : scene.shapes) {
        if (const auto* sphere = dynamic_cast<const Sphere*>(shape.get())) {
            crossSection += std::numbers::pi * sphere->radius() * sphere->radius();
        }
    }
    return crossSection / (4.0 * kHalfSide * kHalfSide);
}

double volumeFraction(const Scene& scene) {
    double volume = 0.0;
    for (const auto& shape : scene.shapes) volume += shape->volume();
    return volume / std::pow(2.0 * kHalfSide, 3);
}

// Wall seconds of each run (runTrace's own clock), and the process CPU seconds across it. On a shared
// machine a run with more threads than free cores loses its speedup to the scheduler, so the fastest
// run is printed beside the median; CPU time per photon that stays flat from 1 to 2 threads means the
// threads do not slow each other down (shared caches, memory, atomics).
struct ThreadRuns {
    int threads = 1;
    std::vector<double> seconds;
    std::vector<double> cpuSeconds;
    double medianSeconds() const { return median(seconds); }
    double bestSeconds() const { return best(seconds); }
};

double processCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// 1 and `threads` threads, interleaved so that both see the same drift in the machine's load; the
// first run's tally is the one every other must equal.
std::vector<ThreadRuns> timeTransport(const OpticalScene& optical, const std::vector<Source>& sources,
                                      const Options& options, FateTally& fates, bool& identical) {
    std::vector<ThreadRuns> runs{{1, {}, {}}};
    if (options.threads > 1) runs.push_back({options.threads, {}, {}});
    TraceSettings settings;
    settings.seed = options.seed;
    settings.transport.polarisation = options.polarisation;
    settings.photons = std::min<std::uint64_t>(options.photons, 2000);  // warm-up: thread pool, caches
    for (const ThreadRuns& run : runs) {
        settings.threads = run.threads;
        runTrace(optical, sources, settings, standardTallies(180, options.polarisation));
    }
    settings.photons = options.photons;
    identical = true;
    std::optional<TraceResult> first;
    for (int r = 0; r < options.repeat; ++r) {
        for (ThreadRuns& run : runs) {
            std::cerr << "  trace: " << run.threads << " thread(s), run " << r + 1 << '/' << options.repeat << '\n';
            settings.threads = run.threads;
            const double cpuStart = processCpuSeconds();
            TraceResult result = runTrace(optical, sources, settings, standardTallies(180, options.polarisation));
            run.cpuSeconds.push_back(processCpuSeconds() - cpuStart);
            run.seconds.push_back(result.seconds);
            identical = identical && !result.partial && (!first || sameTallies(*first, result));
            if (!first) first = std::move(result);
        }
    }
    fates = first->tallies.get<FateTally>();
    return runs;
}

// The rays Octree::firstHit is asked for while photons [0, count) are traced: each photon's emission
// and the leaving direction of each reflect, refract and TIR (tangent passes are not recorded; they
// have measure zero), in tracing order.
std::vector<Ray> segmentStarts(const OpticalScene& optical, const std::vector<Source>& sources, std::uint64_t count,
                               std::uint64_t seed, PolarisationModel polarisation) {
    TraceSettings settings;
    settings.photons = count;
    settings.seed = seed;
    settings.threads = 1;
    settings.paths = count;
    settings.transport.polarisation = polarisation;  // the model timed: its choices make the segments
    const TraceResult recorded = runTrace(optical, sources, settings, TallySet{});
    std::vector<Ray> rays;
    for (const PhotonPath& path : recorded.paths) {
        for (const Event& event : path.events) {
            if (event.type == EventType::Emit || event.type == EventType::Reflect || event.type == EventType::Refract ||
                event.type == EventType::Tir) {
                rays.push_back({event.position, event.direction});
            }
        }
    }
    return rays;
}

struct FirstHitTimes {
    std::size_t rays = 0;
    double hitFraction = 0.0;
    std::vector<double> oneThread;    // seconds over all rays, each repeat
    std::vector<double> manyThreads;  // the same rays split statically over options.threads
    double sealedFraction = 0.0;      // of the rays, those from inside a sealed droplet
    std::vector<double> nextSurface;  // OpticalScene::nextSurface on one thread, seconds each repeat
    bool nextSurfaceIdentical = true;
};

// Seconds for `query(k)` (a RayHit) on every segment k, in order, split statically over `threads`; `hits` counts
// the segments that hit.
template <class Query>
double replayedSeconds(std::size_t segments, int threads, std::size_t& hits, const Query& query) {
    const Stopwatch watch;
    std::size_t found = 0;
    const auto n = static_cast<std::ptrdiff_t>(segments);
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : found)
    for (std::ptrdiff_t i = 0; i < n; ++i) found += query(static_cast<std::size_t>(i)) ? 1 : 0;
    hits = found;
    return watch.seconds();
}

// Octree::firstHit on every ray.
double replaySeconds(const Octree& octree, const std::vector<Ray>& rays, int threads, std::size_t& hits) {
    return replayedSeconds(rays.size(), threads, hits,
                           [&](std::size_t k) { return octree.firstHit(rays[k].origin, rays[k].direction); });
}

// Each segment's region, as the tracer held it: on a surface heading in, inside.
std::vector<ShapeId> segmentRegions(const OpticalScene& optical, const std::vector<Ray>& rays) {
    std::vector<ShapeId> regions;
    regions.reserve(rays.size());
    for (const Ray& ray : rays) regions.push_back(optical.regionAt(ray.origin, ray.direction));
    return regions;
}

// OpticalScene::nextSurface (the tracer's query) on every ray from its region.
double nextSurfaceSeconds(const OpticalScene& optical, const std::vector<Ray>& rays,
                          const std::vector<ShapeId>& regions, int threads, std::size_t& hits) {
    return replayedSeconds(rays.size(), threads, hits, [&](std::size_t k) {
        return optical.nextSurface(regions[k], rays[k].origin, rays[k].direction);
    });
}

FirstHitTimes timeFirstHits(const OpticalScene& optical, const std::vector<Ray>& rays,
                            const std::vector<ShapeId>& regions, const Options& options) {
    const Octree& octree = optical.octree();
    const auto pass = [&](int threads, std::size_t& hits) { return replaySeconds(octree, rays, threads, hits); };
    FirstHitTimes times;
    times.rays = rays.size();
    std::size_t hits = 0;
    pass(options.threads, hits);  // warm-up
    for (int r = 0; r < options.repeat; ++r) {
        times.oneThread.push_back(pass(1, hits));
        times.manyThreads.push_back(pass(options.threads, hits));
    }
    times.hitFraction = static_cast<double>(hits) / static_cast<double>(rays.size());

    std::size_t sealed = 0;
    for (const ShapeId region : regions) sealed += optical.sealed(region) ? 1 : 0;
    times.sealedFraction = static_cast<double>(sealed) / static_cast<double>(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const RayHit searched = octree.firstHit(rays[i].origin, rays[i].direction);
        const RayHit next = optical.nextSurface(regions[i], rays[i].origin, rays[i].direction);
        // A miss is (kNone, +inf) either way.
        times.nextSurfaceIdentical =
            times.nextSurfaceIdentical && next.shape == searched.shape && next.distance == searched.distance;
    }
    for (int r = 0; r < options.repeat; ++r) {
        std::size_t found = 0;
        times.nextSurface.push_back(nextSurfaceSeconds(optical, rays, regions, 1, found));
        if (found != hits) times.nextSurfaceIdentical = false;
    }
    return times;
}

// The target's own measure, on the very photons whose segments are replayed: the reference photons traced
// (runTrace, the standard tallies, the model timed) and, right beside the trace, every segment they travelled
// replayed through Octree::firstHit, `pairs` times on 1 and on `threads` threads. A pair's parts see the same
// load, so a pair's ratio, trace seconds over replay seconds, is the photons' time over the bare firstHit time
// of the same segments. The tracer itself asks OpticalScene::nextSurface, which answers a segment inside a sealed
// droplet without a search (about 45 % of them in the cloud), so the pair also replays that: trace seconds over
// its seconds is what the photons cost beyond their own queries.
struct SamePhotonPairs {
    int threads = 1;
    std::vector<double> trace;        // seconds, each pair
    std::vector<double> replay;       // firstHit, seconds, each pair
    std::vector<double> nextSurface;  // nextSurface, seconds, each pair
    static std::vector<double> ratios(const std::vector<double>& numerator, const std::vector<double>& denominator) {
        std::vector<double> out;
        for (std::size_t i = 0; i < numerator.size(); ++i) out.push_back(numerator[i] / denominator[i]);
        return out;
    }
    std::vector<double> ratios() const { return ratios(trace, replay); }
    std::vector<double> queryRatios() const { return ratios(trace, nextSurface); }
};

std::vector<SamePhotonPairs> timeSamePhotons(const OpticalScene& optical, const std::vector<Source>& sources,
                                             const std::vector<Ray>& rays, const std::vector<ShapeId>& regions,
                                             const Options& options) {
    std::vector<SamePhotonPairs> runs{{1, {}, {}, {}}};
    if (options.threads > 1) runs.push_back({options.threads, {}, {}, {}});
    TraceSettings settings;
    settings.seed = options.seed;
    settings.photons = options.referencePhotons;
    settings.transport.polarisation = options.polarisation;
    std::size_t hits = 0;
    for (int r = 0; r < options.pairs; ++r) {
        for (SamePhotonPairs& run : runs) {
            settings.threads = run.threads;
            // Whether the trace or the replays go first alternates, so that neither always follows the other's
            // memory traffic (an even number of pairs balances it).
            const auto trace = [&] {
                run.trace.push_back(
                    runTrace(optical, sources, settings, standardTallies(180, options.polarisation)).seconds);
            };
            const auto replays = [&] {
                run.replay.push_back(replaySeconds(optical.octree(), rays, run.threads, hits));
                run.nextSurface.push_back(nextSurfaceSeconds(optical, rays, regions, run.threads, hits));
            };
            if (r % 2 == 0) {
                trace();
                replays();
            } else {
                replays();
                trace();
            }
        }
    }
    return runs;
}

void printSamePhotons(const std::vector<SamePhotonPairs>& runs, const Options& options, std::size_t segments) {
    std::cout
        << "\n### The target's measure: the reference photons traced, and every segment they travelled replayed "
           "beside it ("
        << options.pairs
        << " pairs per thread count)\n\n"
           "| threads | photons | segments | trace s (median) | firstHit replay s (median) | trace / firstHit "
           "replay, each pair | median of the pairs' ratios | fastest trace / fastest replay | nextSurface replay s "
           "(median) | trace / nextSurface replay (median of the pairs) |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SamePhotonPairs& run : runs) {
        std::string each;
        for (double ratio : run.ratios()) each += (each.empty() ? "" : ", ") + fixed(ratio, 2);
        std::cout << "| " << run.threads << " | " << options.referencePhotons << " | " << segments << " | "
                  << fixed(median(run.trace), 4) << " | " << fixed(median(run.replay), 4) << " | " << each << " | "
                  << fixed(median(run.ratios()), 2) << " | " << fixed(best(run.trace) / best(run.replay), 2) << " | "
                  << fixed(median(run.nextSurface), 4) << " | " << fixed(median(run.queryRatios()), 2) << " |\n";
    }
    std::cout << "\nThe replays are every segment the photons travelled (the emission and each interface event): "
                 "trace / firstHit replay is their time over the bare firstHit time of the same segments (the "
                 "target's measure). The tracer asks nextSurface, which answers a segment inside a sealed droplet "
                 "without a search, so trace / nextSurface replay is what the photons cost beyond their own queries.\n";
}

void printScene(const Scene& scene, const std::string& name, const BuildTimes& build, double parseSeconds, bool builtIn,
                const OpticalScene& optical) {
    std::size_t sealed = 0;
    for (ShapeId id = 0; id < optical.octree().slotCount(); ++id) sealed += optical.sealed(id) ? 1 : 0;
    std::cout << "\n### Scene and build (median of the repeats; one thread)\n\n"
                 "| scene | shapes | volume fraction | mean optical depth | parse + generate s | clone s | "
                 "octree alone s | OpticalScene s | of which parents and sealing s | octree top grid level | sealed "
                 "droplets |\n|---|---|---|---|---|---|---|---|---|---|---|\n"
              << "| " << name << " | " << scene.shapes.size() << " | "
              << (builtIn ? fixed(100.0 * volumeFraction(scene), 2) + " %" : "-") << " | "
              << (builtIn ? fixed(builtInOpticalDepth(scene), 2) : "-") << " | " << fixed(parseSeconds, 3) << " | "
              << fixed(build.clone, 3) << " | " << fixed(build.octree, 3) << " | " << fixed(build.opticalScene, 3)
              << " | " << fixed(build.opticalScene - build.clone - build.octree, 3) << " | "
              << optical.octree().gridLevel() << " | "
              << fixed(100.0 * static_cast<double>(sealed) / static_cast<double>(optical.octree().shapeCount()), 1)
              << " % |\n";
}

void printPhotons(const FateTally& tally, double expectedUnscattered) {
    const auto perPhoton = [&](std::uint64_t count) {
        return static_cast<double>(count) / static_cast<double>(tally.photons());
    };
    const EventCounts& e = tally.events();
    std::cout << "\n### What a photon does\n\n"
                 "| photons | reflect | refract | TIR | absorb | events (all four) | escaped | absorbed | lost | "
                 "unscattered | exp(-optical depth) |\n|---|---|---|---|---|---|---|---|---|---|---|\n"
              << "| " << tally.photons() << " | " << fixed(perPhoton(e.reflect), 3) << " | "
              << fixed(perPhoton(e.refract), 3) << " | " << fixed(perPhoton(e.tir), 4) << " | "
              << fixed(perPhoton(e.absorb), 5) << " | " << fixed(perPhoton(e.reflect + e.refract + e.tir + e.absorb), 3)
              << " | " << fixed(100.0 * perPhoton(tally.escaped()), 3) << " % | "
              << fixed(100.0 * perPhoton(tally.absorbed()), 3) << " % | " << fixed(100.0 * perPhoton(tally.lost()), 4)
              << " % | " << fixed(100.0 * perPhoton(tally.unscattered()), 3) << " % | "
              << (expectedUnscattered >= 0.0 ? fixed(100.0 * expectedUnscattered, 3) + " %" : "-") << " |\n"
              << "\nPer photon except the percentages.\n";
}

void printTransport(const std::vector<ThreadRuns>& runs, const FateTally& tally) {
    const auto photons = static_cast<double>(tally.photons());
    const EventCounts& e = tally.events();
    const auto interface = static_cast<double>(e.reflect + e.refract + e.tir);
    std::cout << "\n### Throughput (median of the repeats)\n\n"
                 "| threads | seconds (each run) | photons/s | speedup | speedup of the fastest runs | "
                 "interface events/s | CPU us per photon |\n|---|---|---|---|---|---|---|\n";
    const double base = runs.front().medianSeconds();
    const double baseBest = runs.front().bestSeconds();
    for (const ThreadRuns& run : runs) {
        std::string each;
        for (double s : run.seconds) each += (each.empty() ? "" : ", ") + fixed(s, 3);
        const double t = run.medianSeconds();
        std::cout << "| " << run.threads << " | " << each << " | " << fixed(photons / t, 0) << " | "
                  << fixed(base / t, 2) << " | " << fixed(baseBest / run.bestSeconds(), 2) << " | "
                  << fixed(interface / t * 1e-6, 3) << " M | " << fixed(median(run.cpuSeconds) / photons * 1e6, 2)
                  << " |\n";
    }
}

void printReference(const FirstHitTimes& hits, const ThreadRuns& oneThread, const FateTally& tally, int threads) {
    const auto photons = static_cast<double>(tally.photons());
    const EventCounts& e = tally.events();
    const double events = static_cast<double>(e.reflect + e.refract + e.tir + e.absorb) / photons;
    const double queries = 1.0 + static_cast<double>(e.reflect + e.refract + e.tir) / photons;
    const double hitSeconds = median(hits.oneThread);
    const double perHit = hitSeconds / static_cast<double>(hits.rays);
    const double perPhoton = oneThread.medianSeconds() / photons;
    std::cout
        << "\n### Reference: Octree::firstHit alone on the photons' own segments (same run, median)\n\n"
           "| segments | hit | firstHit Mrays/s (1 thread) | ns per firstHit | firstHit speedup on "
        << threads
        << " threads (median / fastest) | us per photon (1 thread) | firstHit calls per photon | time per photon / "
           "(events per photon x time per firstHit) | octree share of the photon time |\n"
           "|---|---|---|---|---|---|---|---|---|\n"
        << "| " << hits.rays << " | " << fixed(100.0 * hits.hitFraction, 1) << " % | "
        << fixed(static_cast<double>(hits.rays) / hitSeconds * 1e-6, 3) << " | " << fixed(perHit * 1e9, 0) << " | "
        << fixed(hitSeconds / median(hits.manyThreads), 2) << " / "
        << fixed(best(hits.oneThread) / best(hits.manyThreads), 2) << " | " << fixed(perPhoton * 1e6, 2) << " | "
        << fixed(queries, 3) << " | " << fixed(perPhoton / (events * perHit), 2) << " | "
        << fixed(100.0 * queries * perHit / perPhoton, 1) << " % |\n"
        << "\nfirstHit calls per photon = 1 + interface events per photon (the emission's query, then one "
           "after each event; the last one finds nothing, or an absorption comes first).\n";
    const double perNext = median(hits.nextSurface) / static_cast<double>(hits.rays);
    std::cout << "\n| segments from inside a sealed droplet | ns per nextSurface (the tracer's query, 1 thread) | "
                 "time per photon / (events per photon x time per nextSurface) | nextSurface equal to firstHit on "
                 "every segment |\n|---|---|---|---|\n"
              << "| " << fixed(100.0 * hits.sealedFraction, 1) << " % | " << fixed(perNext * 1e9, 0) << " | "
              << fixed(perPhoton / (events * perNext), 2) << " | " << (hits.nextSurfaceIdentical ? "yes" : "NO")
              << " |\n";
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        const bool builtIn = !options.scene;
        const std::string name = builtIn ? "built-in cloud, 1e5 droplets" : *options.scene;
        std::cerr << "scene: " << name << '\n';
        const Stopwatch parseWatch;
        const Scene scene =
            builtIn ? parseScene(cloudSceneText(kDroplets, kHalfSide), "trace_bench cloud") : loadScene(*options.scene);
        const double parseSeconds = parseWatch.seconds();
        if (scene.sources.empty()) throw std::invalid_argument(name + ": the scene has no light sources");

        std::cerr << "OpticalScene\n";
        BuildTimes build;
        const std::unique_ptr<OpticalScene> optical = buildOpticalScene(scene, options.repeat, build);
        std::cerr << "reference: segments of " << options.referencePhotons << " photons\n";
        const std::vector<Ray> rays =
            segmentStarts(*optical, scene.sources, options.referencePhotons, options.seed, options.polarisation);
        FateTally tally;
        bool identical = false;
        const std::vector<ThreadRuns> runs = timeTransport(*optical, scene.sources, options, tally, identical);
        std::cerr << "reference: firstHit on " << rays.size() << " segments\n";
        const std::vector<ShapeId> regions = segmentRegions(*optical, rays);
        const FirstHitTimes hits = timeFirstHits(*optical, rays, regions, options);
        std::cerr << "the reference photons traced and replayed, " << options.pairs << " pairs\n";
        const std::vector<SamePhotonPairs> same = timeSamePhotons(*optical, scene.sources, rays, regions, options);

        std::cout << "trace_bench: " << name << ", polarisation " << polarisationModelName(options.polarisation)
                  << ", photons " << options.photons << ", repeat " << options.repeat << ", threads 1 and "
                  << options.threads << ", seed " << options.seed << ", reference photons " << options.referencePhotons
                  << '\n';
        printScene(scene, name, build, parseSeconds, builtIn, *optical);
        printPhotons(tally, builtIn ? std::exp(-builtInOpticalDepth(scene)) : -1.0);
        printTransport(runs, tally);
        printReference(hits, runs.front(), tally, options.threads);
        printSamePhotons(same, options, rays.size());
        std::cout << "\nevery run's tally identical (1 and " << options.threads
                  << " threads, every repeat): " << (identical ? "yes" : "NO") << '\n';
        return identical && hits.nextSurfaceIdentical ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "trace_bench: " << error.what() << '\n';
        return 2;
    }
}
