// How fast `dropscope query` reads its rays and writes its hits (CSV), one thread, against peers in the same
// run: the istringstream/snprintf code it replaced (kept here only, as the baseline), and the bytes alone read
// and written with one fread/fwrite (the ceiling for the file, page cache and all). The files go to the
// temporary folder. Rays are random (origins N(0, 10^2), directions N(0, 1)) written two ways: 17 significant
// digits ("%.17g", what a program that keeps every bit writes) and 6 ("%.6g"); 3 in 4 rays hit, with a random
// shape id below 1e5 and a distance in (0, 20). Every run's rays and hits are checked against the baseline's:
// exit 1 if any differ. docs/performance.md ("Query I/O").
//
// Run: build/bench/query_io_bench [--rays 2e6] [--repeat 3] [--seed 1]
#include "cli/HitCsv.hpp"
#include "cli/RayCsv.hpp"
#include "octree/CountArgument.hpp"
#include "octree/Measure.hpp"
#include "results/AtomicFile.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace dropscope;
using namespace dropscope::bench;
namespace fs = std::filesystem;

struct Options {
    std::size_t rays = 2000000;
    int repeat = 3;
    std::uint64_t seed = 1;
};

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout << "query_io_bench [--rays 2e6] [--repeat 3 (best of)] [--seed 1]\n";
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const char* value = argv[++i];
        if (flag == "--rays")
            options.rays = parseCount(flag, value);
        else if (flag == "--repeat")
            options.repeat = std::max(1, static_cast<int>(parseCount(flag, value)));
        else if (flag == "--seed")
            options.seed = parseCount(flag, value);
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    return options;
}

// The baseline: the rays parser before this benchmark (std::getline from an istringstream over a copy of the
// file, one std::string a line), with its error reports left out; it parses each field as the new one does.
std::vector<CsvRay> baselineReadRays(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream whole;
    whole << in.rdbuf();
    std::istringstream lines(whole.str());
    const auto trimmed = [](std::string_view s) {
        while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
        while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
        return s;
    };
    std::vector<CsvRay> rays;
    std::string raw;
    bool headerSeen = false;
    while (std::getline(lines, raw)) {
        const std::string_view content = trimmed(raw);
        if (content.empty()) continue;
        if (!headerSeen) {
            headerSeen = true;
            continue;
        }
        double values[6];
        std::size_t start = 0;
        for (double& value : values) {
            const std::size_t comma = content.find(',', start);
            const std::string_view field = trimmed(content.substr(start, comma - start));
            const auto [end, status] = std::from_chars(field.data(), field.data() + field.size(), value);
            if (status != std::errc() || end != field.data() + field.size() || !std::isfinite(value)) {
                throw std::runtime_error("baseline: bad field");
            }
            start = comma + 1;
        }
        rays.push_back({Point(values[0], values[1], values[2]), Direction(values[3], values[4], values[5])});
    }
    return rays;
}

// The baseline's hits writer: snprintf "%.17g" and ostream insertion, through the same atomic file.
void baselineWriteHits(const std::vector<RayHit>& hits, std::ostream& out) {
    out << "ray,shape,distance\n";
    char distance[32];
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (hits[i]) {
            std::snprintf(distance, sizeof distance, "%.17g", hits[i].distance);
            out << i << ',' << hits[i].shape << ',' << distance << '\n';
        } else {
            out << i << ",-1,nan\n";
        }
    }
}

std::string raysText(std::size_t count, std::uint64_t seed, const char* format) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    std::string text = "ox,oy,oz,dx,dy,dz\n";
    char field[40];
    for (std::size_t i = 0; i < count; ++i) {
        for (int column = 0; column < 6; ++column) {
            const double value = normal(rng) * (column < 3 ? 10.0 : 1.0);
            text.append(field, static_cast<std::size_t>(std::snprintf(field, sizeof field, format, value)));
            text += column < 5 ? ',' : '\n';
        }
    }
    return text;
}

std::vector<RayHit> randomHits(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed + 1000);
    std::uniform_int_distribution<ShapeId> shape(0, 99999);
    std::uniform_real_distribution<double> distance(0.0, 20.0);
    std::vector<RayHit> hits(count);
    for (RayHit& hit : hits) {
        if (rng() % 4 == 0) continue;  // a miss
        hit.shape = shape(rng);
        hit.distance = distance(rng);
    }
    return hits;
}

std::string fileText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const fs::path& file, const std::string& text) {
    std::FILE* out = std::fopen(file.c_str(), "wb");
    if (out == nullptr || std::fwrite(text.data(), 1, text.size(), out) != text.size() || std::fclose(out) != 0) {
        throw std::runtime_error(file.string() + ": cannot write");
    }
}

std::string readText(const fs::path& file) {
    std::FILE* in = std::fopen(file.c_str(), "rb");
    if (in == nullptr) throw std::runtime_error(file.string() + ": cannot read");
    std::string text(fs::file_size(file), '\0');
    const std::size_t got = std::fread(text.data(), 1, text.size(), in);
    std::fclose(in);
    if (got != text.size()) throw std::runtime_error(file.string() + ": short read");
    return text;
}

bool sameRays(const std::vector<CsvRay>& a, const std::vector<CsvRay>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].origin != b[i].origin || a[i].direction.vector() != b[i].direction.vector()) return false;
    }
    return true;
}

struct Timing {
    double seconds = std::numeric_limits<double>::infinity();  // wall clock
    double cpuSeconds = 0.0;                                   // the process's, user and system, same run
};

// The best of `repeat` runs of `run`; `check` sees each run's result, untimed (as does its release). The
// processor time shows what the code costs when it has a core to itself: on a shared machine the wall clock
// also counts the waits for one.
template <typename Run, typename Check>
Timing best(int repeat, const Run& run, const Check& check) {
    Timing fastest;
    for (int r = 0; r < repeat; ++r) {
        const std::clock_t cpuStart = std::clock();
        const Stopwatch watch;
        const auto result = run();
        const double seconds = watch.seconds();
        const double cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        if (seconds < fastest.seconds) fastest = {seconds, cpuSeconds};
        check(result);
    }
    return fastest;
}

struct Row {
    std::string step, how;
    double bytes;
    Timing timing;
};

void printTable(const std::vector<Row>& rows, std::size_t rays) {
    std::cout << "| step | how | MB | seconds | rays/s | MB/s | processor s | rays per processor s |\n"
                 "|---|---|---|---|---|---|---|---|\n";
    const auto rate = [&](double seconds) { return fixed(static_cast<double>(rays) / seconds, 0); };
    for (const Row& row : rows) {
        std::cout << "| " << row.step << " | " << row.how << " | " << fixed(row.bytes / 1e6, 1) << " | "
                  << fixed(row.timing.seconds, 3) << " | " << rate(row.timing.seconds) << " | "
                  << fixed(row.bytes / 1e6 / row.timing.seconds, 0) << " | " << fixed(row.timing.cpuSeconds, 3) << " | "
                  << rate(row.timing.cpuSeconds) << " |\n";
    }
}

// Reads the rays of `text` (written to `file`) the three ways; false if the new parser's rays differ.
bool measureRead(const std::string& name, const std::string& text, const fs::path& file, const Options& options,
                 std::vector<Row>& rows) {
    std::cerr << "read, " << name << '\n';
    writeText(file, text);
    const std::vector<CsvRay> expected = baselineReadRays(file);
    bool same = true;
    const double bytes = static_cast<double>(text.size());
    const auto sameAsBaseline = [&](const std::vector<CsvRay>& rays) { same = same && sameRays(rays, expected); };
    const int threads = omp_get_max_threads();
    rows.push_back({"read, " + name, "`readRayCsv` (this code, " + std::to_string(threads) + " threads)", bytes,
                    best(
                        options.repeat, [&] { return readRayCsv(file); }, sameAsBaseline)});
    omp_set_num_threads(1);
    rows.push_back({"read, " + name, "`readRayCsv`, one thread (OMP_NUM_THREADS=1)", bytes,
                    best(
                        options.repeat, [&] { return readRayCsv(file); }, sameAsBaseline)});
    omp_set_num_threads(threads);
    rows.push_back({"read, " + name, "baseline (istringstream, getline)", bytes,
                    best(
                        options.repeat, [&] { return baselineReadRays(file); }, sameAsBaseline)});
    rows.push_back({"read, " + name, "ceiling (one fread of the bytes)", bytes,
                    best(
                        options.repeat, [&] { return readText(file); },
                        [&](const std::string& read) { same = same && read == text; })});
    return same;
}

// Writes the hits the three ways; false if the new writer's bytes differ from the baseline's.
bool measureWrite(const std::vector<RayHit>& hits, const fs::path& file, const Options& options,
                  std::vector<Row>& rows) {
    std::cerr << "write\n";
    writeFileAtomically(file, [&](std::ostream& out) { baselineWriteHits(hits, out); });
    const std::string expected = fileText(file);
    const double bytes = static_cast<double>(expected.size());
    bool same = true;
    // Each run's file, checked against the baseline's bytes (the runs of the baseline check it against itself).
    const auto writer = [&](void (*write)(const std::vector<RayHit>&, std::ostream&)) {
        return [&, write] {
            writeFileAtomically(file, [&](std::ostream& out) { write(hits, out); });
            return 0;
        };
    };
    const auto sameAsBaseline = [&](int) { same = same && fileText(file) == expected; };
    rows.push_back({"write", "`writeHitCsv` through `writeFileAtomically` (this code)", bytes,
                    best(options.repeat, writer(writeHitCsv), sameAsBaseline)});
    rows.push_back({"write", "baseline (snprintf, ostream <<) through `writeFileAtomically`", bytes,
                    best(options.repeat, writer(baselineWriteHits), sameAsBaseline)});
    rows.push_back({"write", "ceiling (one fwrite of the bytes)", bytes,
                    best(
                        options.repeat,
                        [&] {
                            writeText(file, expected);
                            return 0;
                        },
                        sameAsBaseline)});
    return same;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        const fs::path dir = fs::temp_directory_path() / ("query_io_bench-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        std::vector<Row> rows;
        bool same =
            measureRead("17 digits", raysText(options.rays, options.seed, "%.17g"), dir / "rays.csv", options, rows);
        same = measureRead("6 digits", raysText(options.rays, options.seed, "%.6g"), dir / "rays.csv", options, rows) &&
               same;
        same = measureWrite(randomHits(options.rays, options.seed), dir / "hits.csv", options, rows) && same;
        fs::remove_all(dir);
        std::cout << options.rays << " rays, best of " << options.repeat
                  << ", one thread but where the row says otherwise\n\n";
        printTable(rows, options.rays);
        if (!same) {
            std::cerr << "query_io_bench: the new reader or writer disagrees with the baseline\n";
            return 1;
        }
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "query_io_bench: " << error.what() << '\n';
        return 1;
    }
}
