#pragma once

// Two variants of the same trace timed against each other in one process, alternating so that both see the
// same drift in the machine's load (polarisation_bench: Stokes against none; spectral_bench: a spectrum
// against one line). Each program prints one Markdown table: docs/performance.md.

#include "octree/CountArgument.hpp"
#include "octree/Measure.hpp"
#include "run/TraceRun.hpp"
#include "tally/FateTally.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dropscope::bench {

struct PairedOptions {
    std::uint64_t photons = 200000;      // per run, the small scenes
    std::uint64_t cloudPhotons = 50000;  // per run, the cloud (slower photons: about 8.5 interfaces each)
    int repeat = 7;
};

// --photons N --cloud-photons N --repeat R; --help prints `usage`.
inline PairedOptions parsePairedOptions(int argc, char** argv, const std::string& usage) {
    PairedOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout << usage << '\n';
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const char* value = argv[++i];
        if (flag == "--photons")
            options.photons = parseCount(flag, value);
        else if (flag == "--cloud-photons")
            options.cloudPhotons = parseCount(flag, value);
        else if (flag == "--repeat")
            options.repeat = std::max(1, static_cast<int>(parseCount(flag, value)));
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    return options;
}

struct PairedRow {
    std::string scene;
    std::uint64_t photons = 0;
    double interfacesPerPhoton = 0.0;
    std::vector<double> first, second;  // seconds of each run
};

// One run of a variant: its result (timed by runTrace itself).
using VariantRun = std::function<TraceResult(std::uint64_t photons)>;

// A warm-up, then `repeat` runs of each variant in turn.
inline PairedRow measurePair(const std::string& name, std::uint64_t photons, int repeat, const VariantRun& first,
                             const VariantRun& second) {
    std::cerr << name << '\n';
    PairedRow row{name, photons, 0.0, {}, {}};
    first(std::min<std::uint64_t>(photons, 2000));
    for (int r = 0; r < repeat; ++r) {
        const TraceResult a = first(photons);
        const EventCounts& e = a.tallies.get<FateTally>().events();
        row.interfacesPerPhoton = static_cast<double>(e.reflect + e.refract + e.tir) / static_cast<double>(photons);
        row.first.push_back(a.seconds);
        row.second.push_back(second(photons).seconds);
    }
    return row;
}

// | scene | photons per run | interfaces per photon | FIRST photons/s | SECOND photons/s | time FIRST / SECOND |
inline void printPairedTable(const std::string& title, const std::string& first, const std::string& second, int repeat,
                             const std::vector<PairedRow>& rows) {
    std::cout << title << ": one thread, median of " << repeat << " runs per variant\n\n"
              << "| scene | photons per run | interfaces per photon | " << first << " photons/s | " << second
              << " photons/s | time " << first << " / " << second << " |\n|---|---|---|---|---|---|\n";
    for (const PairedRow& row : rows) {
        const double a = median(row.first), b = median(row.second);
        const auto photons = static_cast<double>(row.photons);
        std::cout << "| " << row.scene << " | " << row.photons << " | " << fixed(row.interfacesPerPhoton, 2) << " | "
                  << fixed(photons / a, 0) << " | " << fixed(photons / b, 0) << " | " << fixed(a / b, 3) << " |\n";
    }
}

}  // namespace dropscope::bench
