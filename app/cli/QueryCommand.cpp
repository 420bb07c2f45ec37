#include "cli/QueryCommand.hpp"

#include "cli/Cli.hpp"
#include "cli/RayCsv.hpp"
#include "results/AtomicFile.hpp"
#include "scene/SceneLoader.hpp"
#include "tree/Octree.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <ostream>

namespace dropscope {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void writeHits(const std::vector<RayHit>& hits, std::ostream& out) {
    out << "ray,shape,distance\n";
    char distance[32];
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (hits[i]) {
            std::snprintf(distance, sizeof distance, "%.17g", hits[i].distance);
            out << i << ',' << hits[i].shape << ',' << distance << '\n';
        } else {
            out << i << ",-1,nan\n";
        }
    }
}

}  // namespace

CLI::App* addQueryCommand(CLI::App& app, QueryOptions& options) {
    CLI::App* command = app.add_subcommand("query", "First shape hit by each ray of a CSV file, through the octree");
    command->add_option("scene", options.scenePath, "Scene file (docs/scene-format.md)")->required();
    command->add_option("--rays", options.raysPath, "Rays: CSV with header ox,oy,oz,dx,dy,dz")->required();
    command->add_option("--out", options.outPath, "Hits: CSV ray,shape,distance (-1,nan for a miss)")->required();
    command->add_flag("--brute", options.brute, "Test every shape for every ray instead of using the octree");
    return command;
}

int runQuery(const QueryOptions& options, std::ostream&, std::ostream& err) {
    Scene scene = loadScene(options.scenePath);
    const std::vector<CsvRay> rays = readRayCsv(options.raysPath);

    const std::size_t shapeCount = scene.shapes.size();
    std::vector<RayHit> hits(rays.size());
    double buildSeconds = 0.0;
    Clock::time_point queryStart = Clock::now();
    if (options.brute) {
        for (std::size_t i = 0; i < rays.size(); ++i) {
            hits[i] = bruteForceFirstHit(scene.shapes, rays[i].origin, rays[i].direction);
        }
    } else {
        const Octree octree(std::move(scene.shapes), scene.octree);
        buildSeconds = secondsSince(queryStart);
        queryStart = Clock::now();
        for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = octree.firstHit(rays[i].origin, rays[i].direction);
    }
    const double querySeconds = secondsSince(queryStart);

    try {
        writeFileAtomically(options.outPath, [&](std::ostream& out) { writeHits(hits, out); });
    } catch (const std::runtime_error& error) {
        err << error.what() << '\n';
        return kExitBadInput;
    }
    const double rate = querySeconds > 0.0 ? static_cast<double>(rays.size()) / querySeconds : 0.0;
    char summary[256];
    std::snprintf(summary, sizeof summary, "query: %zu shapes, %zu rays, %s, build %.3f s, query %.3f s, %.0f rays/s\n",
                  shapeCount, rays.size(), options.brute ? "brute force" : "octree", buildSeconds, querySeconds, rate);
    err << summary;
    return kExitSuccess;
}

}  // namespace dropscope
