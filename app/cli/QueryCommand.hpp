#pragma once

#include <iosfwd>
#include <string>

namespace CLI {
class App;
}

namespace dropscope {

struct QueryOptions {
    std::string scenePath;
    std::string raysPath;
    std::string outPath;
    bool brute = false;
    int threads = 1;  // for the octree (or brute-force) queries; 0: all the machine has
};

// Registers `dropscope query SCENE --rays RAYS.csv --out HITS.csv [--brute] [--threads N]`.
CLI::App* addQueryCommand(CLI::App& app, QueryOptions& options);

// First hit of every ray: HITS.csv gets `ray,shape,distance`, one line per ray in input order,
// `-1,nan` for a miss, distances to 17 significant digits; written whole or not at all. The summary
// (shapes, rays, build and query seconds, rays per second, then the seconds reading RAYS.csv and writing
// HITS.csv, and the threads that queried) goes to `err`. A bad scene or rays file
// throws (SceneError, RayCsvError), which runCli reports.
int runQuery(const QueryOptions& options, std::ostream& out, std::ostream& err);

}  // namespace dropscope
