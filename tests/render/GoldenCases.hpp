#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace dropscope::test {

// One golden image: `dropscope snapshot tests/data/scenes/golden/SCENE --out tests/golden/NAME.png
// ARGUMENTS...`, as listed in tests/golden/cases.txt (read by the test and scripts/update-goldens.sh).
// SCENE is a file of tests/data/scenes/golden, or "../NAME.json" for one of tests/data/scenes that other
// tests use too (general_shapes.json, whose Bezier patches are named relative to it).
struct GoldenCase {
    std::string name;
    std::string scene;
    std::vector<std::string> arguments;
};

// One case a line, "NAME SCENE ARGUMENTS..." separated by spaces; blank lines and lines starting with
// '#' are skipped. Throws std::runtime_error "FILE:LINE: message" for a bad line (a NAME that is not
// [A-Za-z0-9_]+ or repeats, a SCENE that is not a .json file name, optionally after "../") or an
// unreadable file.
std::vector<GoldenCase> readGoldenCases(const std::filesystem::path& file);

// Its line of cases.txt, for GoogleTest's messages.
void PrintTo(const GoldenCase& golden, std::ostream* out);

}  // namespace dropscope::test
