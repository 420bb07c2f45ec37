#include "GuiLauncher.hpp"

#include "cli/Cli.hpp"
#include "gui/App.hpp"
#include "gui/window/GlfwWindow.hpp"
#include "scene/SceneLoader.hpp"

#include <array>
#include <ostream>
#include <string_view>

namespace dropscope {

namespace {

constexpr std::array<std::string_view, 4> kCommands{"inspect", "query", "trace", "snapshot"};

}  // namespace

bool argumentsOpenGui(int argc, const char* const* argv) {
    if (argc == 1) return true;
    if (argc != 2) return false;
    const std::string_view argument = argv[1];
    if (argument.starts_with("-")) return false;
    for (std::string_view command : kCommands) {
        if (argument == command) return false;
    }
    // A scene file: named so, or an existing file. Any other word is a mistyped command, which the
    // command line reports as such ("unknown command").
    return argument.ends_with(".json") || std::filesystem::is_regular_file(std::filesystem::path(argument));
}

int runGui(const std::optional<std::string>& scenePath, std::ostream& err) {
    const std::filesystem::path file = scenePath ? std::filesystem::path(*scenePath) : DROPSCOPE_DEFAULT_SCENE;
    std::optional<Scene> scene;
    try {
        scene = loadScene(file);
    } catch (const SceneError& error) {
        err << error.what() << '\n';
        return kExitBadInput;
    }
    gui::WindowOptions window;
    std::filesystem::path settings = gui::defaultSettingsDirectory();
    if (std::error_code error; !settings.empty() && (std::filesystem::create_directories(settings, error), error)) {
        err << "dropscope: cannot keep settings in " << settings.string() << " (" << error.message()
            << "); window size and panel layout will not be remembered\n";
        settings.clear();
    }
    if (!settings.empty()) window.settingsFile = settings / "window.txt";
    gui::AppOptions options;
    if (scenePath) options.scenePath = file;  // the bundled scene is never saved over: Save asks for a name
    if (!settings.empty()) options.iniFile = settings / "imgui.ini";
    return gui::runWindow(
        window,
        [&](const render::GlFunctions& gl) -> std::unique_ptr<gui::FrameClient> {
            return std::make_unique<gui::App>(gl, std::move(*scene), options);
        },
        err);
}

}  // namespace dropscope
