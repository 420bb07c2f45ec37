#include "cli/InspectCommand.hpp"

#include "cli/Cli.hpp"
#include "cli/InspectReport.hpp"
#include "scene/SceneLoader.hpp"

#include <CLI/CLI.hpp>

#include <ostream>

namespace dropscope {

CLI::App* addInspectCommand(CLI::App& app, InspectOptions& options) {
    CLI::App* command = app.add_subcommand("inspect", "Check a scene file and print its shapes, media and totals");
    command->add_option("scene", options.scenePath, "Scene file (docs/scene-format.md)")->required();
    command->add_flag("--json", options.json, "Print one JSON document instead of tables");
    return command;
}

int runInspect(const InspectOptions& options, std::ostream& out, std::ostream&) {
    const Scene scene = loadScene(options.scenePath);
    const SceneSummary summary = summarise(scene);
    if (options.json) {
        writeInspectJson(scene, summary, out);
    } else {
        writeInspectTables(scene, summary, out);
    }
    return kExitSuccess;
}

}  // namespace dropscope
