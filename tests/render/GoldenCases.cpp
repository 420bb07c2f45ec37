#include "render/GoldenCases.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace dropscope::test {

namespace {

// "NAME.json" (tests/data/scenes/golden) or "../NAME.json" (tests/data/scenes), nowhere else.
bool isSceneName(const std::string& scene) {
    const std::string file = scene.starts_with("../") ? scene.substr(3) : scene;
    return file.ends_with(".json") && file.size() > 5 && file.find('/') == std::string::npos;
}

bool isCaseName(const std::string& name) {
    return !name.empty() &&
           std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

}  // namespace

std::vector<GoldenCase> readGoldenCases(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot read");
    std::vector<GoldenCase> cases;
    std::set<std::string> names;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        GoldenCase golden;
        if (!(words >> golden.name) || golden.name.starts_with('#')) continue;
        const std::string where = file.string() + ":" + std::to_string(number) + ": ";
        if (!isCaseName(golden.name))
            throw std::runtime_error(where + "case name \"" + golden.name + "\" is not [A-Za-z0-9_]+");
        if (!names.insert(golden.name).second) throw std::runtime_error(where + "case \"" + golden.name + "\" repeats");
        if (!(words >> golden.scene) || !isSceneName(golden.scene)) {
            throw std::runtime_error(where +
                                     "expected a scene file name (*.json in tests/data/scenes/golden, or "
                                     "../*.json in tests/data/scenes) after the name");
        }
        for (std::string argument; words >> argument;) golden.arguments.push_back(argument);
        cases.push_back(std::move(golden));
    }
    return cases;
}

void PrintTo(const GoldenCase& golden, std::ostream* out) {
    *out << golden.name << ' ' << golden.scene;
    for (const std::string& argument : golden.arguments) *out << ' ' << argument;
}

}  // namespace dropscope::test
