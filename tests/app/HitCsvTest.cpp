#include "cli/HitCsv.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace dropscope {
namespace {

// The hits file as `dropscope query` wrote it before std::to_chars: snprintf "%.17g" and ostream insertion.
std::string printfHitCsv(const std::vector<RayHit>& hits) {
    std::ostringstream out;
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
    return out.str();
}

std::string hitCsv(const std::vector<RayHit>& hits) {
    std::ostringstream out;
    writeHitCsv(hits, out);
    return out.str();
}

RayHit hitAt(ShapeId shape, double distance) {
    RayHit hit;
    hit.shape = shape;
    hit.distance = distance;
    return hit;
}

// The first line where the two texts differ, with its number (line 1 is the header), or "" if they are equal.
std::string firstDifference(const std::string& actual, const std::string& expected) {
    std::istringstream a(actual);
    std::istringstream e(expected);
    std::string lineA;
    std::string lineE;
    for (std::size_t line = 1;; ++line) {
        const bool moreA = static_cast<bool>(std::getline(a, lineA));
        const bool moreE = static_cast<bool>(std::getline(e, lineE));
        if (!moreA && !moreE) return actual == expected ? "" : "same lines, different bytes";
        if (moreA != moreE || lineA != lineE) {
            return "line " + std::to_string(line) + ": \"" + (moreA ? lineA : "<end>") + "\", printf: \"" +
                   (moreE ? lineE : "<end>") + "\"";
        }
    }
}

TEST(HitCsv, EdgeDistancesAreByteIdenticalToPrintf) {
    const double kEdges[] = {0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             11.0,
                             0.1,
                             0.2,
                             0.3,
                             1.0 / 3.0,
                             2.0 / 3.0,
                             1e300,
                             -1e300,
                             1e-300,
                             DBL_MAX,
                             -DBL_MAX,
                             DBL_MIN,
                             std::nextafter(DBL_MIN, 0.0),  // the largest subnormal
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             1e-310,
                             4.9406564584124654e-324,
                             123456789.0,
                             9007199254740992.0,  // 2^53
                             9007199254740994.0,
                             1e15,
                             1e16,
                             1e17,  // %g turns to an exponent at 17 digits
                             99999999999999999.0,
                             12345678901234567890.0,
                             1e21,
                             1e22,
                             1e23,
                             1e-4,  // %g turns to an exponent below 1e-4
                             9.9999999999999991e-5,
                             1e-5,
                             0.5,
                             2.5,
                             1.5e-7,
                             5e-324,
                             std::ldexp(1.0, 1023),
                             std::ldexp(1.0, -1022),
                             std::ldexp(1.0, -1074),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN(),
                             -std::numeric_limits<double>::quiet_NaN()};
    std::vector<RayHit> hits;
    for (const double distance : kEdges) hits.push_back(hitAt(static_cast<ShapeId>(hits.size()), distance));
    hits.push_back(hitAt(RayHit::kNone - 1, 2.0));  // the largest shape id
    hits.push_back(RayHit{});                       // a miss
    EXPECT_EQ(firstDifference(hitCsv(hits), printfHitCsv(hits)), "");
}

// Random bit patterns cover every exponent, subnormals and NaN payloads; random distances in (0, 100) are the
// common case. 4e5 lines are about 12 MB: the text crosses the writer's block boundary a dozen times.
TEST(HitCsv, RandomDistancesAreByteIdenticalToPrintf) {
    for (int seed = 0; seed < 2; ++seed) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
        std::uniform_real_distribution<double> uniform(0.0, 100.0);
        std::uniform_int_distribution<ShapeId> shape(0, RayHit::kNone - 1);
        std::vector<RayHit> hits(200000);
        for (RayHit& hit : hits) {
            const std::uint64_t draw = rng();
            if (draw % 8 == 0) continue;  // a miss
            hit = hitAt(shape(rng), seed == 0 ? std::bit_cast<double>(rng()) : uniform(rng));
        }
        EXPECT_EQ(firstDifference(hitCsv(hits), printfHitCsv(hits)), "") << "seed " << seed;
    }
}

TEST(HitCsv, NoHitsIsTheHeaderAlone) { EXPECT_EQ(hitCsv({}), "ray,shape,distance\n"); }

TEST(HitCsv, MissesAreMinusOneNan) {
    EXPECT_EQ(hitCsv({RayHit{}, hitAt(7, 0.25), RayHit{}}), "ray,shape,distance\n0,-1,nan\n1,7,0.25\n2,-1,nan\n");
}

// Counts the writes that reach the stream buffer, and their bytes.
class CountingBuffer : public std::streambuf {
public:
    std::size_t writes = 0;
    std::size_t bytes = 0;

protected:
    std::streamsize xsputn(const char*, std::streamsize count) override {
        ++writes;
        bytes += static_cast<std::size_t>(count);
        return count;
    }
    int_type overflow(int_type c) override { return xsputn(nullptr, 1) == 1 ? c : traits_type::eof(); }
};

TEST(HitCsv, TextGoesOutInFewLargeWrites) {
    std::vector<RayHit> hits(1000000);
    for (std::size_t i = 0; i < hits.size(); ++i) hits[i] = hitAt(3, 1.0 + static_cast<double>(i) * 1e-7);
    CountingBuffer buffer;
    std::ostream out(&buffer);
    writeHitCsv(hits, out);
    EXPECT_EQ(buffer.bytes, hitCsv(hits).size());
    EXPECT_LE(buffer.writes, buffer.bytes / 500000 + 1) << "bytes " << buffer.bytes;  // blocks of about 1 MiB
}

}  // namespace
}  // namespace dropscope
