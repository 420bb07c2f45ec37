#pragma once

#include "scene/Scene.hpp"
#include "tally/ResultReport.hpp"

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace dropscope {

struct MieOptions {
    std::optional<double> index;  // relative to the ambient
    std::optional<double> kappa;
    std::optional<double> x;
    std::vector<double> xRange;  // LO HI
    std::optional<std::uint64_t> xCount;
    std::string scenePath;
    std::optional<std::uint64_t> shape;
    std::optional<std::uint64_t> generator;
    std::uint64_t bins = 180;
    std::string outDir;
};

// Sizes of one --x-range: each is a full Mie computation (15 ms at x = 1000 with 180 bins).
inline constexpr std::uint64_t kMaxSizeCount = 100'000;

// What `dropscope mie` computes: summary.json's values and mie.csv's table.
struct MieRun {
    ResultReport summary;
    ResultTable table;
    std::size_t sizes = 1;
    double seconds = 0.0;
};

// Computes what runMieCommand writes (options.outDir unused); a long range is announced on `err`. With `scene`,
// that is the scene of --scene, already read (options.scenePath names it in the summary and in messages).
// Throws BadInputError or SceneError for bad input.
MieRun computeMie(const MieOptions& options, std::ostream& err, const Scene* scene = nullptr);
// summary.json alone, keys in docs/cli.md's order.
void writeMieSummary(const ResultReport& summary, std::ostream& out);
// DIR/mie.csv and DIR/summary.json, both or neither (DIR exists).
void writeMieFiles(const std::filesystem::path& directory, const MieRun& run);

// Registers `dropscope mie --index N [--kappa K] (--x X | --x-range LO HI [--x-count C] | --scene SCENE
// [--shape ID | --generator I]) [--bins B] --out DIR` (docs/cli.md, "dropscope mie").
CLI::App* addMieCommand(CLI::App& app, MieOptions& options);

// Lorenz-Mie theory for one sphere, a uniform range of size parameters, or a scene's sphere or droplet cloud:
// DIR/mie.csv (the angular distribution in --bins bins, with the polarisation ratios) and DIR/summary.json (the
// efficiencies and g), written whole or not at all; one line on `out`; a range of sizes expected to take more than
// a few seconds is announced on `err` with its estimate. Bad input throws BadInputError or SceneError, which
// runCli reports with exit status 2.
int runMieCommand(const MieOptions& options, std::ostream& out, std::ostream& err);

}  // namespace dropscope
