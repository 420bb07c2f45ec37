#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace dropscope {

// `dropscope [SCENE.json]`: opens the interactive app on the scene (the bundled default scene when none
// is given). A scene that does not load is bad input (exit 2, its one-line message) before any window
// opens; no display is exit 3 with one line pointing to `dropscope snapshot`.
int runGui(const std::optional<std::string>& scenePath, std::ostream& err);

// Whether the arguments ask for the app rather than a subcommand: none, or a single scene file (a name
// ending in .json, or an existing file) that is not a command or an option.
bool argumentsOpenGui(int argc, const char* const* argv);

}  // namespace dropscope
