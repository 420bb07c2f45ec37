#include "cli/RayCsv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace dropscope {

namespace {

constexpr std::string_view kHeader = "ox,oy,oz,dx,dy,dz";

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
    return {Point(values[0], values[1], values[2]), direction};
}

}  // namespace

std::vector<CsvRay> parseRayCsv(const std::string& text, const std::string& origin) {
    std::vector<CsvRay> rays;
    std::istringstream in(text);
    std::string raw;
    std::size_t line = 0;
    bool headerSeen = false;
    while (std::getline(in, raw)) {
        ++line;
        const std::string_view content = trimmed(raw);
        if (content.empty()) continue;
        if (!headerSeen) {
            if (content != kHeader) fail(origin, line, "expected the header \"" + std::string(kHeader) + "\"");
            headerSeen = true;
            continue;
        }
        rays.push_back(parseLine(content, origin, line));
    }
    if (!headerSeen) throw RayCsvError(origin + ": empty file (expected the header \"" + std::string(kHeader) + "\")");
    return rays;
}

std::vector<CsvRay> readRayCsv(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw RayCsvError(file.string() + ": cannot open (no such file, or not readable)");
    std::ostringstream text;
    text << in.rdbuf();
    return parseRayCsv(text.str(), file.string());
}

}  // namespace dropscope
