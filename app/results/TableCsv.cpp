#include "results/TableCsv.hpp"

#include "results/NumberText.hpp"

#include <charconv>
#include <ostream>
#include <string_view>

namespace dropscope {

namespace {

void writeCell(const ResultColumn& column, std::size_t row, std::ostream& out) {
    std::visit(
        [&](const auto& values) {
            using T = typename std::decay_t<decltype(values)>::value_type;
            if constexpr (std::is_same_v<T, double>) {
                out << shortestText(values[row]);
            } else {
                char text[24];  // to_chars, as for the numbers: no locale
                out << std::string_view(text, std::to_chars(text, text + sizeof text, values[row]).ptr);
            }
        },
        column.values);
}

}  // namespace

void writeTableCsv(const ResultTable& table, std::ostream& out) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) out << (c ? "," : "") << table.columns[c].name;
    out << '\n';
    for (std::size_t row = 0; row < table.rows(); ++row) {
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            if (c) out << ',';
            writeCell(table.columns[c], row, out);
        }
        out << '\n';
    }
}

}  // namespace dropscope
