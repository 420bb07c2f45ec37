#include "results/TableCsv.hpp"

#include "results/NumberText.hpp"

#include <charconv>
#include <ostream>
#include <string_view>

namespace dropscope {

namespace {

// A text cell as RFC 4180 has it: quoted, with its quotes doubled, when it holds a comma, a quote or a line break.
void writeText(const std::string& text, std::ostream& out) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        out << text;
        return;
    }
    out << '"';
    for (char c : text) out << (c == '"' ? "\"\"" : std::string(1, c));
    out << '"';
}

void writeCell(const ResultColumn& column, std::size_t row, std::ostream& out) {
    std::visit(
        [&](const auto& values) {
            using T = typename std::decay_t<decltype(values)>::value_type;
            if constexpr (std::is_same_v<T, double>) {
                out << shortestText(values[row]);
            } else if constexpr (std::is_same_v<T, std::string>) {
                writeText(values[row], out);
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
