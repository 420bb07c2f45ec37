#include "gui/window/WindowSettings.hpp"

#include "results/AtomicFile.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>

namespace dropscope::gui {

namespace {

std::filesystem::path environmentPath(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::filesystem::path(value) : std::filesystem::path();
}

}  // namespace

WindowSize clampWindowSize(WindowSize size) {
    return {std::clamp(size.width, kMinimumWindowSide, kMaximumWindowSide),
            std::clamp(size.height, kMinimumWindowSide, kMaximumWindowSide)};
}

std::filesystem::path defaultSettingsDirectory() {
    const std::filesystem::path config = environmentPath("XDG_CONFIG_HOME");
    if (config.is_absolute()) return config / "dropscope";
    const std::filesystem::path home = environmentPath("HOME");
    if (!home.empty()) return home / ".config" / "dropscope";
    return {};
}

std::optional<WindowSize> readWindowSize(const std::filesystem::path& file) {
    std::ifstream in(file);
    WindowSize size;
    if (!(in >> size.width >> size.height)) return std::nullopt;
    in >> std::ws;
    if (!in.eof()) return std::nullopt;  // anything after the two numbers: not a file we wrote
    return clampWindowSize(size);
}

void writeWindowSize(const std::filesystem::path& file, WindowSize size) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    writeFileAtomically(file, [&](std::ostream& out) { out << size.width << ' ' << size.height << '\n'; });
}

}  // namespace dropscope::gui
