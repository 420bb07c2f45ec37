#include "cli/TextTable.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>

namespace dropscope {

TextTable::TextTable(std::vector<Column> columns) : columns_(std::move(columns)) {}

void TextTable::addRow(std::vector<std::string> cells) {
    cells.resize(columns_.size());
    rows_.push_back(std::move(cells));
}

void TextTable::write(std::ostream& out, const std::string& indent) const {
    std::vector<std::size_t> widths(columns_.size());
    for (std::size_t c = 0; c < columns_.size(); ++c) {
        widths[c] = columns_[c].heading.size();
        for (const auto& row : rows_) widths[c] = std::max(widths[c], row[c].size());
    }
    const auto writeLine = [&](const auto& cellText) {
        std::string line = indent;
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            const std::string& text = cellText(c);
            const std::string padding(widths[c] - text.size(), ' ');
            const bool last = c + 1 == columns_.size();
            if (columns_[c].align == Align::Right) {
                line += padding + text;
            } else {
                line += text + (last ? "" : padding);
            }
            if (!last) line += "  ";
        }
        out << line << '\n';
    };
    writeLine([&](std::size_t c) -> const std::string& { return columns_[c].heading; });
    for (const auto& row : rows_) writeLine([&](std::size_t c) -> const std::string& { return row[c]; });
}

std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

std::string formatRange(double low, double high) { return formatNumber(low) + " .. " + formatNumber(high); }

std::string formatVector(const Eigen::Vector3d& v) {
    std::string text = "(";
    text.append(formatNumber(v.x())).append(", ").append(formatNumber(v.y())).append(", ");
    return text.append(formatNumber(v.z())).append(")");
}

}  // namespace dropscope
