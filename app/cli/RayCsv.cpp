#include "cli/RayCsv.hpp"

#include "scene/JsonPath.hpp"
#include "scene/SceneLimits.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>

namespace dropscope {

namespace {

constexpr std::string_view kHeader = "ox,oy,oz,dx,dy,dz";

// The block a file is read through: large enough that a read costs little against parsing what it brings,
// small enough to stay in the processor's cache (the whole file in memory would cost a page fault per 4 KiB).
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;

// The part of a text whose lines are counted to reserve room for its rays.
constexpr std::size_t kSampleBytes = kBlockBytes;

// Ended lines are parsed on up to kMaxParts threads (OpenMP's count), in parts of at least kPartBytes: less is
// parsed by one thread, where starting a second would cost more than it saves.
constexpr int kMaxParts = 16;
constexpr std::size_t kPartBytes = std::size_t{1} << 16;

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

[[noreturn]] void fail(const std::string& origin, std::size_t line, const std::string& message) {
    throw RayCsvError(origin + ":" + std::to_string(line) + ": " + message);
}

double parseField(std::string_view field, const std::string& origin, std::size_t line, int column) {
    const std::string_view text = trimmed(field);
    double value = 0.0;
    const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (status != std::errc() || end != text.data() + text.size() || text.empty()) {
        fail(origin, line,
             "field " + std::to_string(column + 1) + " (" +
                 std::string(kHeader.substr(static_cast<std::size_t>(column) * 3, 2)) + ") is not a number: \"" +
                 std::string(text) + "\"");
    }
    if (!std::isfinite(value)) fail(origin, line, "field " + std::to_string(column + 1) + " is not finite");
    return value;
}

CsvRay parseLine(std::string_view text, const std::string& origin, std::size_t line) {
    double values[6];
    int column = 0;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        if (column == 6) fail(origin, line, "more than 6 fields");
        values[column] = parseField(text.substr(start, comma - start), origin, line, column);
        ++column;
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (column != 6)
        fail(origin, line, "expected 6 fields (" + std::string(kHeader) + "), got " + std::to_string(column));
    const Direction direction(values[3], values[4], values[5]);
    if (!direction) fail(origin, line, "direction (dx, dy, dz) is zero");
    const Point rayOrigin(values[0], values[1], values[2]);
    if (!withinCoordinateLimit(rayOrigin)) fail(origin, line, "origin (ox, oy, oz) " + beyondCoordinateLimit());
    return {rayOrigin, direction};
}

// The common line, six numbers between single commas with nothing around them, read without splitting it
// first: each std::from_chars stops at the comma that ends its number. True, with `ray`, for such a line with
// finite numbers and a non-zero direction, which parseLine would read alike; anything else (spaces, a missing
// or extra field, a bad number) is left to parseLine, which knows every rule and error.
bool parsePlainLine(std::string_view text, CsvRay& ray) {
    double values[6];
    const char* at = text.data();
    const char* const end = at + text.size();
    for (int column = 0; column < 6; ++column) {
        const auto [next, status] = std::from_chars(at, end, values[column]);
        if (status != std::errc() || !std::isfinite(values[column])) return false;
        if (column == 5) {
            if (next != end) return false;
        } else {
            if (next == end || *next != ',') return false;
            at = next + 1;
        }
    }
    const Direction direction(values[3], values[4], values[5]);
    if (!direction) return false;
    const Point start(values[0], values[1], values[2]);
    if (!withinCoordinateLimit(start)) return false;
    ray = {start, direction};
    return true;
}

// The rays of one file, fed one line at a time (its text without the '\n') as std::getline splits them: the
// line numbers of the errors count every line, blank ones too.
class RayLines {
public:
    explicit RayLines(const std::string& origin) : origin_(origin) {}

    // Room for the rays of `totalBytes` of text whose first part is `sample` (more are added if later lines
    // are shorter). Room reserved and never used costs address space only.
    void reserveLike(std::string_view sample, std::size_t totalBytes) {
        const auto sampleLines = static_cast<std::size_t>(std::count(sample.begin(), sample.end(), '\n')) + 1;
        const std::size_t restBytes = std::max(totalBytes, sample.size()) - sample.size();
        rays_.reserve(sampleLines + sampleLines * restBytes / std::max<std::size_t>(sample.size(), 1));
    }

    // One line, in order: the header until it is seen, then a ray.
    void add(std::string_view raw) {
        ++line_;
        const std::string_view content = trimmed(raw);
        if (content.empty()) return;
        if (!headerSeen_) {
            if (content != kHeader) fail(origin_, line_, "expected the header \"" + std::string(kHeader) + "\"");
            headerSeen_ = true;
            return;
        }
        rays_.push_back(parseRay(content, line_));
    }

    // Every line up to the last '\n' of [begin, end); returns where the rest (a line not yet ended) starts.
    const char* addEndedLines(const char* begin, const char* end) {
        while (!headerSeen_) {
            const void* newline = std::memchr(begin, '\n', static_cast<std::size_t>(end - begin));
            if (!newline) return begin;
            add(std::string_view(begin, static_cast<std::size_t>(static_cast<const char*>(newline) - begin)));
            begin = static_cast<const char*>(newline) + 1;
        }
        const char* last = end;
        while (last != begin && last[-1] != '\n') --last;
        // At most a block's bytes (and the line across its end) at once: a slot is set aside for every line,
        // blank ones too, so this bounds the slots a text of blank lines holds to one block's worth.
        while (begin != last) {
            const char* cut = static_cast<std::size_t>(last - begin) > kBlockBytes ? begin + kBlockBytes : last;
            while (cut[-1] != '\n') ++cut;  // stops at last at the latest
            addRayLines(begin, cut);
            begin = cut;
        }
        return last;
    }

    std::vector<CsvRay> finish() {
        if (!headerSeen_) {
            throw RayCsvError(origin_ + ": empty file (expected the header \"" + std::string(kHeader) + "\")");
        }
        return std::move(rays_);
    }

private:
    // Lines of rays, [begin, end) ending with '\n', cut into parts at line ends and parsed in parallel, each
    // part into its own slots of rays_ (as many as its lines; blank lines leave some unused, closed up after).
    // The first error in the text is the one thrown, with its line number, as if read line by line. A text too
    // short for two parts, or a single thread, is read in one pass.
    void addRayLines(const char* begin, const char* end) {
        const auto bytes = static_cast<std::size_t>(end - begin);
        const std::size_t parts =
            std::clamp<std::size_t>(bytes / kPartBytes, 1, std::min<std::size_t>(omp_get_max_threads(), kMaxParts));
        if (parts == 1) {  // in one pass, without counting the lines first
            parseRays(begin, end, line_, [&](const CsvRay& ray) { rays_.push_back(ray); });
            return;
        }
        std::array<const char*, kMaxParts + 1> cuts{};
        cuts[0] = begin;
        cuts[parts] = end;
        for (std::size_t part = 1; part < parts; ++part) {
            const char* at = std::max(cuts[part - 1], begin + bytes * part / parts);
            while (at != begin && at[-1] != '\n') ++at;  // stops at end at the latest
            cuts[part] = at;
        }
        std::array<std::size_t, kMaxParts + 1> linesBefore{};  // of each part in the file; [parts]: all
        std::array<std::size_t, kMaxParts> written{};
        std::array<std::exception_ptr, kMaxParts> errors{};
        const int threads = static_cast<int>(parts);
#pragma omp parallel for num_threads(threads) schedule(static, 1)
        for (int k = 0; k < threads; ++k) {
            const auto part = static_cast<std::size_t>(k);
            linesBefore[part + 1] = static_cast<std::size_t>(std::count(cuts[part], cuts[part + 1], '\n'));
        }
        linesBefore[0] = line_;
        for (std::size_t part = 0; part < parts; ++part) linesBefore[part + 1] += linesBefore[part];
        const std::size_t firstSlot = rays_.size();
        const auto slotOf = [&](std::size_t part) { return firstSlot + (linesBefore[part] - line_); };
        rays_.resize(slotOf(parts));
#pragma omp parallel for num_threads(threads) schedule(static, 1)
        for (int k = 0; k < threads; ++k) {
            const auto part = static_cast<std::size_t>(k);
            try {
                CsvRay* slot = rays_.data() + slotOf(part);
                std::size_t line = linesBefore[part];
                written[part] =
                    parseRays(cuts[part], cuts[part + 1], line, [&slot](const CsvRay& ray) { *slot++ = ray; });
            } catch (...) {
                errors[part] = std::current_exception();
            }
        }
        for (std::size_t part = 0; part < parts; ++part) {
            if (errors[part]) std::rethrow_exception(errors[part]);
        }
        std::size_t next = firstSlot;
        for (std::size_t part = 0; part < parts; ++part) {
            if (next != slotOf(part)) std::copy_n(rays_.data() + slotOf(part), written[part], rays_.data() + next);
            next += written[part];
        }
        rays_.resize(next);
        line_ = linesBefore[parts];
    }

    // The ray of a trimmed, non-blank line: the common form read in one scan, anything else by every rule.
    CsvRay parseRay(std::string_view content, std::size_t line) const {
        CsvRay ray;
        return parsePlainLine(content, ray) ? ray : parseLine(content, origin_, line);
    }

    // The rays of the lines [begin, end) (each ending with '\n'), numbered from line + 1 (line is left at the
    // last), each handed to `emit`; returns how many.
    template <typename Emit>
    std::size_t parseRays(const char* begin, const char* end, std::size_t& line, const Emit& emit) const {
        std::size_t rays = 0;
        while (begin != end) {
            const char* lineEnd =
                static_cast<const char*>(std::memchr(begin, '\n', static_cast<std::size_t>(end - begin)));
            ++line;
            const std::string_view content =
                trimmed(std::string_view(begin, static_cast<std::size_t>(lineEnd - begin)));
            begin = lineEnd + 1;
            if (content.empty()) continue;
            emit(parseRay(content, line));
            ++rays;
        }
        return rays;
    }

    const std::string& origin_;
    std::size_t line_ = 0;
    bool headerSeen_ = false;
    std::vector<CsvRay> rays_;
};

}  // namespace

std::vector<CsvRay> parseRayCsv(std::string_view text, const std::string& origin) {
    RayLines lines(origin);
    lines.reserveLike(text.substr(0, kSampleBytes), text.size());
    const char* const end = text.data() + text.size();
    const char* rest = lines.addEndedLines(text.data(), end);
    if (rest != end) lines.add(std::string_view(rest, static_cast<std::size_t>(end - rest)));  // no final '\n'
    return lines.finish();
}

// The file goes through a block of kBlockBytes, reused: a line cut at the end of a block moves to its start and
// is completed by the next read (the block doubles for a line longer than itself). A read that fails ends the
// file, as the stream copy this replaced did (a folder reads as empty).
std::vector<CsvRay> readRayCsv(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw RayCsvError(file.string() + ": cannot open (no such file, or not readable)");
    const std::string origin = file.string();
    std::error_code error;
    const std::uintmax_t fileBytes = std::filesystem::file_size(file, error);
    RayLines lines(origin);
    std::vector<char> block(kBlockBytes);
    std::size_t kept = 0;  // bytes of an unfinished line at the start of the block
    bool first = true;
    while (in) {
        if (kept == block.size()) block.resize(2 * block.size());
        in.read(block.data() + kept, static_cast<std::streamsize>(block.size() - kept));
        const char* const end = block.data() + kept + static_cast<std::size_t>(in.gcount());
        if (first && !error)
            lines.reserveLike(std::string_view(block.data(), static_cast<std::size_t>(end - block.data())), fileBytes);
        first = false;
        const char* rest = lines.addEndedLines(block.data(), end);
        kept = static_cast<std::size_t>(end - rest);
        std::memmove(block.data(), rest, kept);
    }
    if (kept > 0) lines.add(std::string_view(block.data(), kept));  // no final '\n'
    return lines.finish();
}

}  // namespace dropscope
