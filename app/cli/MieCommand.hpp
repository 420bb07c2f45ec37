#pragma once

#include <cstdint>
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
