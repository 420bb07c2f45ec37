#include "cli/QueryCommand.hpp"

#include "cli/Cli.hpp"
#include "cli/HitCsv.hpp"
#include "cli/RayCsv.hpp"
#include "cli/TraceCommand.hpp"
#include "cli/WholeNumberOption.hpp"
#include "results/AtomicFile.hpp"
#include "scene/SceneLoader.hpp"
#include "tree/Octree.hpp"

#include <omp.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ostream>

namespace dropscope {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

CLI::App* addQueryCommand(CLI::App& app, QueryOptions& options) {
    CLI::App* command = app.add_subcommand("query", "First shape hit by each ray of a CSV file, through the octree");
    command->add_option("scene", options.scenePath, "Scene file (docs/scene-format.md)")->required();
    command->add_option("--rays", options.raysPath, "Rays: CSV with header ox,oy,oz,dx,dy,dz")->required();
    command->add_option("--out", options.outPath, "Hits: CSV ray,shape,distance (-1,nan for a miss)")->required();
    command->add_flag("--brute", options.brute, "Test every shape for every ray instead of using the octree");
    command->add_option("--threads", options.threads, "Threads for the queries; 0: all the machine has")
        ->capture_default_str()
        ->transform(wholeNumberIn(0, kMaxTraceThreads));
    return command;
}

int runQuery(const QueryOptions& options, std::ostream&, std::ostream& err) {
    Scene scene = loadScene(options.scenePath);
    const Clock::time_point readStart = Clock::now();
    const std::vector<CsvRay> rays = readRayCsv(options.raysPath);
    const double readSeconds = secondsSince(readStart);

    const std::size_t shapeCount = scene.shapes.size();
    std::vector<RayHit> hits(rays.size());
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    // Every ray's hit into its own slot, in chunks handed out as threads free up: the file is the same for any
    // thread count.
    const auto queryAll = [&](const auto& firstHit) {
        const auto count = static_cast<std::int64_t>(rays.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 4096)
        for (std::int64_t i = 0; i < count; ++i) {
            const CsvRay& ray = rays[static_cast<std::size_t>(i)];
            hits[static_cast<std::size_t>(i)] = firstHit(ray.origin, ray.direction);
        }
    };
    double buildSeconds = 0.0;
    Clock::time_point queryStart = Clock::now();
    if (options.brute) {
        queryAll([&](const Point& p, const Direction& d) { return bruteForceFirstHit(scene.shapes, p, d); });
    } else {
        const Octree octree(std::move(scene.shapes), scene.octree);
        buildSeconds = secondsSince(queryStart);
        queryStart = Clock::now();
        queryAll([&](const Point& p, const Direction& d) { return octree.firstHit(p, d); });
    }
    const double querySeconds = secondsSince(queryStart);

    const Clock::time_point writeStart = Clock::now();
    try {
        writeFileAtomically(options.outPath, [&](std::ostream& out) { writeHitCsv(hits, out); });
    } catch (const std::runtime_error& error) {
        err << error.what() << '\n';
        return kExitBadInput;
    }
    const double writeSeconds = secondsSince(writeStart);
    const double rate = querySeconds > 0.0 ? static_cast<double>(rays.size()) / querySeconds : 0.0;
    // Scripts parse the summary up to "rays/s" (bench/python_bench.py): new figures go after it.
    char summary[320];
    std::snprintf(summary, sizeof summary,
                  "query: %zu shapes, %zu rays, %s, build %.3f s, query %.3f s, %.0f rays/s, read %.3f s, write %.3f "
                  "s, %d %s\n",
                  shapeCount, rays.size(), options.brute ? "brute force" : "octree", buildSeconds, querySeconds, rate,
                  readSeconds, writeSeconds, threads, threads == 1 ? "thread" : "threads");
    err << summary;
    return kExitSuccess;
}

}  // namespace dropscope
