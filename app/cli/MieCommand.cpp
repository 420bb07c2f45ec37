#include "cli/MieCommand.hpp"

#include "cli/BadInput.hpp"
#include "cli/OutputDirectory.hpp"
#include "cli/TraceCommand.hpp"
#include "cli/WholeNumberOption.hpp"
#include "geometry/Sphere.hpp"
#include "results/AtomicFile.hpp"
#include "results/SummaryJson.hpp"
#include "results/TableCsv.hpp"
#include "results/Version.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/AngularTally.hpp"
#include "wave/Mie.hpp"
#include "wave/SceneMie.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <variant>

namespace dropscope {

namespace {

namespace fs = std::filesystem;

// A range expected to take longer than kAnnouncedSeconds is announced on stderr with its estimate.
constexpr double kSecondsPerSizeAtX1000 = 0.015;
constexpr double kAnnouncedSeconds = 5.0;

std::string formatNumber(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// What is computed: the sphere's relative index and the sizes, and where they came from (for summary.json).
struct MieProblem {
    std::complex<double> m;
    enum class Sizes { One, Range, Radii } sizes = Sizes::One;
    double x = 0.0;
    double xLo = 0.0;
    double xHi = 0.0;
    std::size_t count = 1;
    std::optional<RadiusDistribution> radii;
    double wavenumber = 0.0;  // per scene unit, for radii
    ResultReport context;     // the summary's keys that describe the input
};

void checkRelativeIndex(double index, double kappa) {
    if (!(std::isfinite(index) && index > 0.0)) {
        throw BadInputError("--index: the relative index must be a finite number > 0, not " + formatNumber(index));
    }
    if (!(std::isfinite(kappa) && kappa >= 0.0)) {
        throw BadInputError("--kappa: must be a finite number >= 0, not " + formatNumber(kappa));
    }
}

void checkSizeParameter(double x, const std::string& where) {
    if (!(std::isfinite(x) && x > 0.0)) {
        throw BadInputError(where + ": the size parameter must be a finite number > 0, not " + formatNumber(x));
    }
    if (x < kMinSizeParameter || x > kMaxSizeParameter) {
        throw BadInputError(where + ": the size parameter " + formatNumber(x) + " is outside the range " +
                            formatNumber(kMinSizeParameter) + " to " + formatNumber(kMaxSizeParameter) +
                            " where Lorenz-Mie theory is computed (docs/mie.md)");
    }
}

// --scene: the sphere or cloud, its medium relative to the ambient, at the scene wavelength.
MieProblem sceneProblem(const MieOptions& options, const Scene& scene) {
    const std::string& file = options.scenePath;
    const Medium& ambient = scene.media.at(scene.ambient);
    MieProblem problem;
    const Medium* medium = nullptr;
    std::size_t sphereCount = 0;
    std::optional<std::size_t> onlySphere;
    for (std::size_t id = 0; id < scene.explicitShapeCount; ++id) {
        if (scene.shapes[id]->kind() == ShapeKind::Sphere) {
            ++sphereCount;
            onlySphere = id;
        }
    }
    std::optional<std::size_t> shapeId = options.shape;
    std::optional<std::size_t> generator = options.generator;
    if (!shapeId && !generator) {
        if (sphereCount == 1 && scene.generators.empty()) {
            shapeId = onlySphere;
        } else if (sphereCount == 0 && scene.generators.size() == 1) {
            generator = 0;
        } else {
            throw BadInputError(file + ": the scene has " + std::to_string(sphereCount) + " spheres and " +
                                std::to_string(scene.generators.size()) +
                                " generators; choose one with --shape ID or --generator I");
        }
    }
    problem.wavenumber = sceneWavenumber(scene);
    double radius = 0.0;
    if (shapeId) {
        if (*shapeId >= scene.shapes.size()) {
            throw BadInputError("--shape " + std::to_string(*shapeId) + ": " + file + " has " +
                                (scene.shapes.empty() ? std::string("no shapes")
                                                      : std::to_string(scene.shapes.size()) + " shapes (ids 0 to " +
                                                            std::to_string(scene.shapes.size() - 1) + ")"));
        }
        const Shape& shape = *scene.shapes[*shapeId];
        if (shape.kind() != ShapeKind::Sphere) {
            throw BadInputError("--shape " + std::to_string(*shapeId) + ": shape " + std::to_string(*shapeId) + " of " +
                                file + " is a " + std::string(shape.typeName()) +
                                ", and Lorenz-Mie theory is for spheres");
        }
        radius = static_cast<const Sphere&>(shape).radius();
        medium = &scene.mediumOf(shape);
        problem.x = problem.wavenumber * radius;
        checkSizeParameter(problem.x, "--shape " + std::to_string(*shapeId) + " (radius " + formatNumber(radius) + " " +
                                          scene.unit + " at " + formatWavelength(scene.wavelengthNm) + ")");
        problem.context.set({"shape"}, static_cast<std::uint64_t>(*shapeId));
        problem.context.set({"radius"}, radius);
    } else {
        if (*generator >= scene.generators.size()) {
            throw BadInputError("--generator " + std::to_string(*generator) + ": " + file + " has " +
                                std::to_string(scene.generators.size()) + " generators");
        }
        const GeneratedCloud& cloud = scene.generators[*generator];
        medium = &scene.media.at(cloud.medium);
        problem.sizes = MieProblem::Sizes::Radii;
        problem.radii = cloud.radius;
        problem.context.set({"generator"}, static_cast<std::uint64_t>(*generator));
    }
    try {
        problem.m = relativeIndexInScene(scene, *medium);
    } catch (const std::invalid_argument& error) {
        throw BadInputError(file + ": " + error.what());
    }
    problem.context.set({"scene"}, file);
    problem.context.set({"wavelength_nm"}, scene.wavelengthNm);
    problem.context.set({"medium"}, medium->name);
    problem.context.set({"ambient"}, ambient.name);
    problem.context.set({"ambient_index"}, ambient.n);
    return problem;
}

MieProblem problemOf(const MieOptions& options, const Scene* scene) {
    const bool sceneGiven = scene != nullptr || !options.scenePath.empty();
    const int ways = (options.x ? 1 : 0) + (options.xRange.empty() ? 0 : 1) + (sceneGiven ? 1 : 0);
    if (ways != 1) throw BadInputError("mie: give exactly one of --x, --x-range and --scene");
    if (options.xCount && options.xRange.empty()) throw BadInputError("--x-count: only with --x-range");
    if ((options.shape || options.generator) && !sceneGiven) {
        throw BadInputError(options.shape ? "--shape: only with --scene" : "--generator: only with --scene");
    }
    if (options.shape && options.generator) throw BadInputError("--shape and --generator: choose one");
    if (sceneGiven) {
        if (options.index || options.kappa) {
            throw BadInputError(std::string(options.index ? "--index" : "--kappa") +
                                ": with --scene the index comes from the shape's medium and the ambient");
        }
        if (scene) return sceneProblem(options, *scene);
        return sceneProblem(options, loadScene(options.scenePath));
    }
    if (!options.index) throw BadInputError("--index: required (the sphere's index relative to the ambient)");
    checkRelativeIndex(*options.index, options.kappa.value_or(0.0));
    MieProblem problem;
    problem.m = {*options.index, options.kappa.value_or(0.0)};
    if (options.x) {
        checkSizeParameter(*options.x, "--x");
        problem.x = *options.x;
        return problem;
    }
    const double lo = options.xRange[0];
    const double hi = options.xRange[1];
    checkSizeParameter(lo, "--x-range");
    checkSizeParameter(hi, "--x-range");
    if (!(lo < hi)) {
        throw BadInputError("--x-range " + formatNumber(lo) + " " + formatNumber(hi) + ": LO must be below HI");
    }
    problem.sizes = MieProblem::Sizes::Range;
    problem.xLo = lo;
    problem.xHi = hi;
    problem.count = options.xCount ? static_cast<std::size_t>(*options.xCount) : defaultSizeParameterCount(lo, hi);
    return problem;
}

MieResult solve(const MieProblem& problem, std::size_t bins) {
    try {
        switch (problem.sizes) {
        case MieProblem::Sizes::One: return mieSphere(problem.m, problem.x, bins);
        case MieProblem::Sizes::Range:
            return mieAverageOverSizeParameter(problem.m, problem.xLo, problem.xHi, problem.count, bins);
        case MieProblem::Sizes::Radii: return mieAverageOverRadii(problem.m, *problem.radii, problem.wavenumber, bins);
        }
    } catch (const std::invalid_argument& error) {
        throw BadInputError(std::string("mie: ") + error.what());
    }
    throw std::logic_error("unknown kind of sizes");
}

// mie.csv: the bins of angular.csv with the bin integrals of S11 (fraction), per steradian, and the ratios.
ResultTable mieTable(const MieAngularBins& bins) {
    const std::size_t count = bins.fraction.size();
    std::vector<double> lo, hi, perSr, p12, p33, p34;
    for (std::size_t b = 0; b < count; ++b) {
        lo.push_back(angularEdgeDeg(static_cast<int>(b), static_cast<int>(count)));
        hi.push_back(angularEdgeDeg(static_cast<int>(b) + 1, static_cast<int>(count)));
        const double solidAngle = angularBinSolidAngle(static_cast<int>(b), static_cast<int>(count));
        perSr.push_back(bins.fraction[b] / solidAngle);
        const double f = bins.fraction[b];
        p12.push_back(f > 0.0 ? bins.s12[b] / f : std::nan(""));
        p33.push_back(f > 0.0 ? bins.s33[b] / f : std::nan(""));
        p34.push_back(f > 0.0 ? bins.s34[b] / f : std::nan(""));
    }
    ResultTable table{"mie", {}};
    table.columns.push_back({"theta_lo_deg", std::move(lo), "deg"});
    table.columns.push_back({"theta_hi_deg", std::move(hi), "deg"});
    table.columns.push_back({"fraction", bins.fraction});
    table.columns.push_back({"fraction_per_sr", std::move(perSr), "1/sr"});
    table.columns.push_back({"p12_over_p11", std::move(p12)});
    table.columns.push_back({"p33_over_p11", std::move(p33)});
    table.columns.push_back({"p34_over_p11", std::move(p34)});
    return table;
}

}  // namespace

CLI::App* addMieCommand(CLI::App& app, MieOptions& options) {
    CLI::App* command = app.add_subcommand(
        "mie",
        "Lorenz-Mie theory of a sphere, a range of sizes or a scene's sphere or droplet cloud: mie.csv, "
        "summary.json");
    command->add_option("--index", options.index, "The sphere's refractive index relative to the ambient");
    command->add_option("--kappa", options.kappa, "Its imaginary part (absorption), >= 0; default 0");
    command->add_option("--x", options.x, "Size parameter 2 pi a n_ambient / lambda, 1e-3 to 2e4");
    command->add_option("--x-range", options.xRange, "LO HI: uniform over this range of size parameters")->expected(2);
    command->add_option("--x-count", options.xCount, "Sizes sampled over --x-range (default: one per 0.1 of x)")
        ->transform(wholeNumberIn(1, kMaxSizeCount));
    command->add_option("--scene", options.scenePath, "A scene: its sphere's or droplet cloud's medium and size");
    command->add_option("--shape", options.shape, "With --scene: the sphere with this id")
        ->transform(wholeNumberIn(0, kNoUpperBound));
    command->add_option("--generator", options.generator, "With --scene: the droplet cloud of this generator")
        ->transform(wholeNumberIn(0, kNoUpperBound));
    command->add_option("--bins", options.bins, "Angular bins over 0-180 degrees in mie.csv")
        ->capture_default_str()
        ->transform(wholeNumberIn(1, kMaxTraceBins));
    command->add_option("--out", options.outDir, "Output folder (created): mie.csv, summary.json")->required();
    return command;
}

MieRun computeMie(const MieOptions& options, std::ostream& err, const Scene* scene) {
    MieProblem problem = problemOf(options, scene);
    if (problem.sizes == MieProblem::Sizes::Range) {
        // A long average says so first (docs/performance.md, "Mie": 15 ms per size of x = 1000 with 180 bins on one
        // core, growing as x^2).
        const double perSize = kSecondsPerSizeAtX1000 * (problem.xHi / 1000.0) * (problem.xHi / 1000.0);
        const double estimate = perSize * static_cast<double>(problem.count);
        if (estimate > kAnnouncedSeconds) {
            char line[160];
            std::snprintf(line, sizeof line, "mie: %zu sizes up to x = %.6g: about %.0f s on one core\n", problem.count,
                          problem.xHi, estimate);
            err << line << std::flush;
        }
    }

    const auto start = std::chrono::steady_clock::now();
    const MieResult result = solve(problem, static_cast<std::size_t>(options.bins));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    MieRun run{std::move(problem.context), mieTable(result.bins), result.sizes, seconds};
    ResultReport& report = run.summary;
    const MieEfficiencies& q = result.efficiencies;
    report.set({"qext"}, q.qext);
    report.set({"qsca"}, q.qsca);
    report.set({"qabs"}, q.qabs);
    report.set({"qback"}, q.qback);
    report.set({"g"}, q.g);
    report.set({"x"}, result.xMean);
    report.set({"index"}, problem.m.real());
    report.set({"kappa"}, problem.m.imag());
    if (problem.sizes == MieProblem::Sizes::Range) {
        report.set({"x_lo"}, problem.xLo);
        report.set({"x_hi"}, problem.xHi);
    }
    report.set({"sizes"}, static_cast<std::uint64_t>(result.sizes));
    report.set({"bins"}, options.bins);
    report.set({"seconds"}, seconds);
    report.set({"version"}, std::string(dropscopeVersion()));
    return run;
}

void writeMieSummary(const ResultReport& summary, std::ostream& out) {
    static const std::vector<std::string_view> kKeyOrder{
        "qext",   "qsca",    "qabs",          "qback",         "g",       "x",      "index",  "kappa",
        "x_lo",   "x_hi",    "sizes",         "bins",          "scene",   "shape",  "radius", "generator",
        "medium", "ambient", "ambient_index", "wavelength_nm", "seconds", "version"};
    writeSummaryJson(summary, kKeyOrder, out);
}

void writeMieFiles(const std::filesystem::path& directory, const MieRun& run) {
    writeFilesAtomically(
        {{directory / "mie.csv", [&](std::ostream& file) { writeTableCsv(run.table, file); }},
         {directory / "summary.json", [&](std::ostream& file) { writeMieSummary(run.summary, file); }}});
}

int runMieCommand(const MieOptions& options, std::ostream& out, std::ostream& err) {
    const fs::path directory = options.outDir;
    checkOutputDirectory(directory, {"mie.csv", "summary.json"});
    const MieRun run = computeMie(options, err);
    // Only now: sizes a scene's cloud gives outside the valid range are found by the computation, and bad input
    // leaves nothing behind.
    createOutputDirectory(directory);
    writeMieFiles(directory, run);
    const auto number = [&](const char* key) { return std::get<double>(*run.summary.find({key})); };
    char line[256];
    std::snprintf(line, sizeof line, "mie: %zu size%s, %llu bins in %.3f s: Q_ext %.6g, Q_sca %.6g, g %.6g\n",
                  run.sizes, run.sizes == 1 ? "" : "s", static_cast<unsigned long long>(options.bins), run.seconds,
                  number("qext"), number("qsca"), number("g"));
    out << line << "  wrote mie.csv, summary.json in " << directory.string() << '\n';
    return 0;
}

}  // namespace dropscope
