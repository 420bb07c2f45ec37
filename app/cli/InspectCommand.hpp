#pragma once

#include <iosfwd>
#include <string>

namespace CLI {
class App;
}

namespace dropscope {

struct InspectOptions {
    std::string scenePath;
    bool json = false;
};

// Registers `dropscope inspect SCENE [--json]` on `app`, filling `options` when parsed.
CLI::App* addInspectCommand(CLI::App& app, InspectOptions& options);

// Loads the scene and prints its shapes, media, sources and totals: an aligned table, or one JSON
// document with --json (keys in docs/scene-format.md). Returns the exit status; a bad scene throws
// SceneError, which runCli reports.
int runInspect(const InspectOptions& options, std::ostream& out, std::ostream& err);

}  // namespace dropscope
