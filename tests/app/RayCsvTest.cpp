#include "app/CliRun.hpp"
#include "cli/RayCsv.hpp"

#include <gtest/gtest.h>
#include <omp.h>
#include <sys/stat.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace dropscope {
namespace {

namespace fs = std::filesystem;

// OpenMP's thread count for one test, restored however it ends.
class OmpThreads {
public:
    explicit OmpThreads(int threads) : before_(omp_get_max_threads()) { omp_set_num_threads(threads); }
    ~OmpThreads() { omp_set_num_threads(before_); }
    OmpThreads(const OmpThreads&) = delete;
    OmpThreads& operator=(const OmpThreads&) = delete;

private:
    int before_;
};

// The message parseRayCsv throws for `text` ("" if it throws none).
std::string errorOf(const std::string& text) {
    try {
        parseRayCsv(text, "rays.csv");
    } catch (const RayCsvError& error) {
        return error.what();
    }
    return "";
}

std::string toChars(double value) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

std::string printf17(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

void expectSameRay(const CsvRay& actual, double ox, double oy, double oz, double dx, double dy, double dz,
                   std::size_t index) {
    const Direction direction(dx, dy, dz);
    EXPECT_EQ(actual.origin.x(), ox) << "ray " << index;
    EXPECT_EQ(actual.origin.y(), oy) << "ray " << index;
    EXPECT_EQ(actual.origin.z(), oz) << "ray " << index;
    EXPECT_EQ(actual.direction.x(), direction.x()) << "ray " << index;
    EXPECT_EQ(actual.direction.y(), direction.y()) << "ray " << index;
    EXPECT_EQ(actual.direction.z(), direction.z()) << "ray " << index;
}

// Every number written by std::to_chars (shortest) or by "%.17g" reads back as the same double, over every
// exponent (random bit patterns, the non-finite ones left out) and the usual scales.
TEST(RayCsv, ToCharsAndPrintfTextReadsBackExactly) {
    for (int format = 0; format < 2; ++format) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(format));
        std::normal_distribution<double> normal;
        std::vector<double> values;
        std::string text = "ox,oy,oz,dx,dy,dz\n";
        for (int i = 0; i < 20000; ++i) {
            for (int column = 0; column < 6; ++column) {
                double value = std::bit_cast<double>(rng());
                if (!std::isfinite(value) || i % 2 == 0) value = normal(rng) * (column < 3 ? 10 : 1);
                // Origins must lie within kMaxCoordinate (docs/limits.md): random mantissas, smaller exponents.
                while (column < 3 && std::abs(value) > 1e100) value *= 1e-200;
                values.push_back(value);
                text += (format == 0 ? toChars(value) : printf17(value)) + (column < 5 ? "," : "\n");
            }
        }
        const std::vector<CsvRay> rays = parseRayCsv(text, "rays.csv");
        ASSERT_EQ(rays.size(), values.size() / 6);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const double* v = &values[6 * i];
            expectSameRay(rays[i], v[0], v[1], v[2], v[3], v[4], v[5], i);
            if (HasFailure()) return;
        }
    }
}

TEST(RayCsv, CrlfBlankLinesSpacesAndTabsAreAccepted) {
    const std::vector<CsvRay> rays = parseRayCsv(
        "\r\n  \t\r\n ox,oy,oz,dx,dy,dz \t\r\n"
        "1,2,3,0,0,1\r\n"
        "\r\n"
        " 4 ,\t5\t, 6 ,1 , 0,0 \r\n"
        "\n"
        "\t-7.5,8e-3,9E2,0,2,0\t",
        "rays.csv");
    ASSERT_EQ(rays.size(), 3u);
    expectSameRay(rays[0], 1, 2, 3, 0, 0, 1, 0);
    expectSameRay(rays[1], 4, 5, 6, 1, 0, 0, 1);
    expectSameRay(rays[2], -7.5, 8e-3, 900, 0, 1, 0, 2);
}

TEST(RayCsv, LastLineWithoutNewlineIsRead) {
    const std::vector<CsvRay> rays = parseRayCsv("ox,oy,oz,dx,dy,dz\n1,2,3,0,0,1\n4,5,6,1,0,0", "rays.csv");
    ASSERT_EQ(rays.size(), 2u);
    expectSameRay(rays[1], 4, 5, 6, 1, 0, 0, 1);
    EXPECT_TRUE(parseRayCsv("ox,oy,oz,dx,dy,dz", "rays.csv").empty());
    EXPECT_EQ(errorOf("ox,oy,oz,dx,dy,dz\n1,2,3,0,0,1\n4,5,6,1,0"),
              "rays.csv:3: expected 6 fields (ox,oy,oz,dx,dy,dz), got 5");
}

// Every message of the istringstream parser this one replaced, word for word, with its line number.
TEST(RayCsv, EveryErrorKeepsItsMessageAndLine) {
    const std::string header = "ox,oy,oz,dx,dy,dz\n";
    const std::pair<std::string, std::string> cases[] = {
        {"", "rays.csv: empty file (expected the header \"ox,oy,oz,dx,dy,dz\")"},
        {"\n \r\n\t\n", "rays.csv: empty file (expected the header \"ox,oy,oz,dx,dy,dz\")"},
        {"x,y,z\n", "rays.csv:1: expected the header \"ox,oy,oz,dx,dy,dz\""},
        {"\n\r\nox, oy,oz,dx,dy,dz\n", "rays.csv:3: expected the header \"ox,oy,oz,dx,dy,dz\""},
        {"1,2,3,0,0,1\n", "rays.csv:1: expected the header \"ox,oy,oz,dx,dy,dz\""},
        {header + "0,0,0,1,0,0\n0,0,zero,1,0,0\n", "rays.csv:3: field 3 (oz) is not a number: \"zero\""},
        {header + "a,0,0,1,0,0\n", "rays.csv:2: field 1 (ox) is not a number: \"a\""},
        {header + "0,b,0,1,0,0\n", "rays.csv:2: field 2 (oy) is not a number: \"b\""},
        {header + "0,0,0, 1x ,0,0\n", "rays.csv:2: field 4 (dx) is not a number: \"1x\""},
        {header + "0,0,0,1,+1,0\n", "rays.csv:2: field 5 (dy) is not a number: \"+1\""},
        {header + "0,0,0,1,0,0x1p3\n", "rays.csv:2: field 6 (dz) is not a number: \"0x1p3\""},
        {header + "0,0,0,1,0,\n", "rays.csv:2: field 6 (dz) is not a number: \"\""},
        {header + "0,,0,1,0,0\n", "rays.csv:2: field 2 (oy) is not a number: \"\""},
        {header + "1e400,0,0,1,0,0\n", "rays.csv:2: field 1 (ox) is not a number: \"1e400\""},
        {header + "1 2,0,0,1,0,0\n", "rays.csv:2: field 1 (ox) is not a number: \"1 2\""},
        {header + "0,0,0,1,0,0;\n", "rays.csv:2: field 6 (dz) is not a number: \"0;\""},
        {header + "1,2,3,nan,0,1\n", "rays.csv:2: field 4 is not finite"},
        {header + "inf,2,3,1,0,1\n", "rays.csv:2: field 1 is not finite"},
        {header + "1,2,3,1,0,-infinity\n", "rays.csv:2: field 6 is not finite"},
        {header + "1,2,3,0,0,0\n", "rays.csv:2: direction (dx, dy, dz) is zero"},
        {header + "1,2,3,0,0,-0\r\n", "rays.csv:2: direction (dx, dy, dz) is zero"},
        {header + "1e101,0,0,1,0,0\n",
         "rays.csv:2: origin (ox, oy, oz) beyond the limit 1e+100 on any coordinate (docs/limits.md)"},
        {header + "0,-1e308,0,1,0,0\n",
         "rays.csv:2: origin (ox, oy, oz) beyond the limit 1e+100 on any coordinate (docs/limits.md)"},
        {header + "1,2,3,0,0\n", "rays.csv:2: expected 6 fields (ox,oy,oz,dx,dy,dz), got 5"},
        {header + "1\n", "rays.csv:2: expected 6 fields (ox,oy,oz,dx,dy,dz), got 1"},
        {header + "1,2,3,0,0,1,7\n", "rays.csv:2: more than 6 fields"},
        {header + "1,2,3,0,0,1,\n", "rays.csv:2: more than 6 fields"},
        {header + "1,2,x,0,0,1,7\n", "rays.csv:2: field 3 (oz) is not a number: \"x\""},  // fields before count
        {header + "1,2,3,0,0,1\r\n\r\n\n1,2,3\r\n", "rays.csv:5: expected 6 fields (ox,oy,oz,dx,dy,dz), got 3"},
        {header + "1,2,3,0,0,1\n" + header, "rays.csv:3: field 1 (ox) is not a number: \"ox\""},
    };
    for (const auto& [text, message] : cases) EXPECT_EQ(errorOf(text), message) << "input: " << text;
}

class RayCsvFile : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::freshTestDirectory("raycsv"); }
    void TearDown() override { fs::remove_all(dir_); }

    // Rays i = 0, 1, ...: origin (i, -i, 0.5), direction (0, 0, 1).
    static std::string numberedRays(std::size_t count) {
        std::string text = "ox,oy,oz,dx,dy,dz\n";
        for (std::size_t i = 0; i < count; ++i) {
            text += std::to_string(i) + ",-" + std::to_string(i) + ",0.5,0,0,1\n";
        }
        return text;
    }
    static void expectNumberedRays(const std::vector<CsvRay>& rays, std::size_t count) {
        ASSERT_EQ(rays.size(), count);
        for (std::size_t i = 0; i < count; i += 997) {
            expectSameRay(rays[i], static_cast<double>(i), -static_cast<double>(i), 0.5, 0, 0, 1, i);
        }
    }

    fs::path dir_;
};

TEST_F(RayCsvFile, ReadsAFileOfSeveralMegabytes) {
    const fs::path path = dir_ / "rays.csv";
    std::ofstream(path, std::ios::binary) << numberedRays(200000);
    expectNumberedRays(readRayCsv(path), 200000);
}

// Lines cut by the reader's block boundaries (a megabyte) keep their numbers; a line longer than a block is read.
TEST_F(RayCsvFile, LinesAcrossAndLongerThanABlockAreRead) {
    const fs::path path = dir_ / "rays.csv";
    std::ofstream(path, std::ios::binary) << numberedRays(100000) << std::string(3 << 20, ' ') << "1,2,3,0,0,1\n";
    const std::vector<CsvRay> rays = readRayCsv(path);
    ASSERT_EQ(rays.size(), 100001u);
    expectSameRay(rays.back(), 1, 2, 3, 0, 0, 1, 100000);
    std::ofstream(path, std::ios::binary) << numberedRays(100000) << "\r\n1,2,x,0,0,1";
    try {
        readRayCsv(path);
        ADD_FAILURE() << "no error";
    } catch (const RayCsvError& error) {
        EXPECT_EQ(std::string(error.what()), path.string() + ":100003: field 3 (oz) is not a number: \"x\"");
    }
}

// A pipe has no size to read ahead of: the reads double until its end.
TEST_F(RayCsvFile, ReadsAPipe) {
    const fs::path path = dir_ / "rays.fifo";
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    const std::string text = numberedRays(200000);
    std::thread writer([&] { std::ofstream(path, std::ios::binary) << text; });
    const std::vector<CsvRay> rays = readRayCsv(path);
    writer.join();
    expectNumberedRays(rays, 200000);
}

// Text is parsed in parts of at least 64 KiB, one per OpenMP thread (a file a megabyte block at a time): every
// ray lands in file order (blank lines leave no gap), and of several bad lines the first in the file is the one
// reported, with its number, whichever part or block it fell in.
TEST_F(RayCsvFile, PartsParsedInParallelKeepTheOrderAndTheFirstError) {
    const OmpThreads four(4);             // four parts even on one core
    constexpr std::size_t kRays = 60000;  // about 1.7 MB
    std::vector<std::string> lines{"ox,oy,oz,dx,dy,dz"};
    std::vector<std::size_t> rayLine;  // the file line (from 1) of ray i
    for (std::size_t i = 0; i < kRays; ++i) {
        if (i % 1000 == 7) lines.emplace_back(i % 2000 == 7 ? "" : " \r");  // blank lines, counted
        lines.push_back(std::to_string(i) + ",-" + std::to_string(i) + ",0.5,0,1e-3," + std::to_string(i + 1));
        rayLine.push_back(lines.size());
    }
    const auto joined = [](const std::vector<std::string>& all) {
        std::string text;
        for (const std::string& line : all) text += line + "\n";
        return text;
    };
    const fs::path path = dir_ / "rays.csv";
    std::ofstream(path, std::ios::binary) << joined(lines);
    for (const std::vector<CsvRay>& rays : {parseRayCsv(joined(lines), "rays.csv"), readRayCsv(path)}) {
        ASSERT_EQ(rays.size(), kRays);
        for (std::size_t i = 0; i < kRays; ++i) {
            expectSameRay(rays[i], static_cast<double>(i), -static_cast<double>(i), 0.5, 0, 1e-3,
                          static_cast<double>(i + 1), i);
        }
    }
    // Bad rays at about 0.33, 0.62 and 1.1 MB: in the first, second and third of the text's four parts; in the
    // file, the last is in its second block.
    const std::size_t first = 12000, second = 22000, third = 40000;
    const auto fileError = [&](const std::vector<std::string>& all) {
        std::ofstream(path, std::ios::binary) << joined(all);
        try {
            readRayCsv(path);
        } catch (const RayCsvError& error) {
            return std::string(error.what()).substr(path.string().size());
        }
        return std::string("no error");
    };
    std::vector<std::string> bad = lines;
    bad[rayLine[third] - 1] = "1,2,3,0,0,0";
    const std::string thirdError = ":" + std::to_string(rayLine[third]) + ": direction (dx, dy, dz) is zero";
    EXPECT_EQ(errorOf(joined(bad)), "rays.csv" + thirdError);
    EXPECT_EQ(fileError(bad), thirdError);
    bad[rayLine[second] - 1] = "1,2,3,0,0";
    const std::string secondError =
        ":" + std::to_string(rayLine[second]) + ": expected 6 fields (ox,oy,oz,dx,dy,dz), got 5";
    EXPECT_EQ(errorOf(joined(bad)), "rays.csv" + secondError);
    EXPECT_EQ(fileError(bad), secondError);
    bad[rayLine[first] - 1] = "1,2,x,0,0,1";
    const std::string firstError = ":" + std::to_string(rayLine[first]) + ": field 3 (oz) is not a number: \"x\"";
    EXPECT_EQ(errorOf(joined(bad)), "rays.csv" + firstError);
    EXPECT_EQ(fileError(bad), firstError);
}

// The parts against one thread on random text: blank, spaced and CRLF lines, a bad line now and then, lines of
// every length; the same rays, or the same first error, either way.
TEST(RayCsv, ParallelPartsReadAsOneThreadDoes) {
    const auto readWith = [](int threads, const std::string& text) {
        const OmpThreads set(threads);
        try {
            std::vector<double> values;
            for (const CsvRay& ray : parseRayCsv(text, "rays.csv")) {
                for (int k = 0; k < 3; ++k) values.insert(values.end(), {ray.origin[k], ray.direction[k]});
            }
            return std::pair{values, std::string()};
        } catch (const RayCsvError& error) {
            return std::pair{std::vector<double>{}, std::string(error.what())};
        }
    };
    std::mt19937_64 random(20261204);
    int failed = 0;
    for (int sample = 0; sample < 24; ++sample) {
        // Bad lines rare enough that about half the texts have none.
        const double badShare = sample % 2 == 0 ? 0.0 : 1e-4 * static_cast<double>(1 + sample % 5);
        std::string text = sample % 3 == 0 ? "\n\r\n" : "";
        text += "ox,oy,oz,dx,dy,dz\n";
        while (text.size() < 400'000) {
            const double draw = std::uniform_real_distribution<double>(0.0, 1.0)(random);
            const auto number = static_cast<int>(random() % 2001) - 1000;
            if (draw < badShare) {
                text += std::to_string(number) + ",1,2,x\n";
            } else if (draw < 0.02) {
                text += draw < 0.01 ? "\n" : " \t\r\n";
            } else if (draw < 0.05) {
                text += " " + std::to_string(number) + " ,1,2,\t0,0,1\r\n";
            } else {
                text += std::to_string(number) + ".25,-3e-2,7," + std::to_string(number % 7) + ",1,0.5\n";
            }
        }
        if (sample % 4 == 1) text += "1,2,3,0,0,1";  // no final newline
        const auto one = readWith(1, text);
        const auto four = readWith(4, text);
        EXPECT_EQ(four.second, one.second) << "sample " << sample;
        EXPECT_TRUE(four.first == one.first) << "sample " << sample;
        failed += one.second.empty() ? 0 : 1;
    }
    EXPECT_GE(failed, 6);  // the errors were exercised too
    EXPECT_LE(failed, 18);
}

TEST_F(RayCsvFile, UnreadableFilesKeepTheirMessages) {
    const fs::path missing = dir_ / "missing.csv";
    EXPECT_THROW(
        {
            try {
                readRayCsv(missing);
            } catch (const RayCsvError& error) {
                EXPECT_EQ(std::string(error.what()),
                          missing.string() + ": cannot open (no such file, or not readable)");
                throw;
            }
        },
        RayCsvError);
    // A folder opens and reads as nothing, as it did before.
    EXPECT_THROW(
        {
            try {
                readRayCsv(dir_);
            } catch (const RayCsvError& error) {
                EXPECT_EQ(std::string(error.what()),
                          dir_.string() + ": empty file (expected the header \"ox,oy,oz,dx,dy,dz\")");
                throw;
            }
        },
        RayCsvError);
}

}  // namespace
}  // namespace dropscope
