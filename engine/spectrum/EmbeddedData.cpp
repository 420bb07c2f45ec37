#include "spectrum/EmbeddedData.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

namespace dropscope {

std::vector<std::vector<double>> parseNumberTable(std::string_view text, std::size_t columns, std::string_view name) {
    std::vector<std::vector<double>> rows;
    bool headerSeen = false;
    std::size_t lineNumber = 0;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.empty() || line.front() == '#') continue;
        if (!headerSeen) {
            headerSeen = true;
            continue;
        }
        std::vector<double> row;
        std::string_view rest = line;
        for (;;) {
            const std::size_t comma = rest.find(',');
            std::string_view field = rest.substr(0, comma);
            while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
            while (!field.empty() && field.back() == ' ') field.remove_suffix(1);
            double value = 0.0;
            const auto [next, error] = std::from_chars(field.data(), field.data() + field.size(), value);
            if (error != std::errc{} || next != field.data() + field.size() || field.empty()) {
                throw std::runtime_error(std::string(name) + " line " + std::to_string(lineNumber) +
                                         ": not a number: \"" + std::string(field) + "\"");
            }
            row.push_back(value);
            if (comma == std::string_view::npos) break;
            rest = rest.substr(comma + 1);
        }
        if (row.size() != columns) {
            throw std::runtime_error(std::string(name) + " line " + std::to_string(lineNumber) + ": " +
                                     std::to_string(row.size()) + " numbers, expected " + std::to_string(columns));
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace dropscope
