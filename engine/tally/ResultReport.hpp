#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace dropscope {

// One value of a run's summary: null, a flag, a count, a number (NaN where undefined) or a text.
using SummaryValue = std::variant<std::nullptr_t, bool, std::uint64_t, double, std::string>;

// A summary value at a key path: {"fractions", "escaped"} is summary.json's fractions.escaped.
struct SummaryEntry {
    std::vector<std::string> path;
    SummaryValue value;
    friend bool operator==(const SummaryEntry&, const SummaryEntry&) = default;
};

// One column of a result table: counts, numbers or texts, one per row, and the unit of its values ("" for
// counts, indices and shares of the emitted power; e.g. "deg", "1/sr", "nm", "scene unit").
struct ResultColumn {
    std::string name;
    std::variant<std::vector<std::uint64_t>, std::vector<double>, std::vector<std::string>> values;
    std::string unit = {};
    std::size_t size() const;
    friend bool operator==(const ResultColumn&, const ResultColumn&) = default;
};

// Columns of equal length under one name; `dropscope trace` writes table NAME as NAME.csv. A detector's
// image is a table whose rows are its pixels, iy outer and ix inner: `grid` is then {ny, nx} (empty for any
// other table), so that results.h5 can store each column as an ny x nx array.
struct ResultTable {
    std::string name;
    std::vector<ResultColumn> columns;
    std::vector<std::size_t> grid = {};
    std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
    const ResultColumn* column(std::string_view columnName) const;  // nullptr when absent
    friend bool operator==(const ResultTable&, const ResultTable&) = default;
};

// A picture a run makes (a far-field detector's sky): `width` x `height` sRGB pixels, 3 bytes each, top row
// first; `dropscope trace` writes it as NAME.png.
struct ResultImage {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;
    friend bool operator==(const ResultImage&, const ResultImage&) = default;
};

// What a run reports, in no file format: a summary of values at key paths and named tables. Tallies
// and the run itself fill it; the result writers (app/results) turn it into files, the app into panels.
class ResultReport {
public:
    // Sets the value at `path`, after those set before. Throws std::invalid_argument when the path is
    // already set, or is a group of values already set (or inside one).
    void set(std::vector<std::string> path, SummaryValue value);
    // Throws std::invalid_argument when a table of that name exists or its columns differ in length.
    void addTable(ResultTable table);
    // Throws std::invalid_argument when an image of that name exists or its size and pixels disagree.
    void addImage(ResultImage image);

    const std::vector<SummaryEntry>& summary() const { return summary_; }
    const std::vector<ResultTable>& tables() const { return tables_; }
    const SummaryValue* find(const std::vector<std::string>& path) const;  // nullptr when not set
    const ResultTable* table(std::string_view name) const;                 // nullptr when absent
    const std::vector<ResultImage>& images() const { return images_; }

    friend bool operator==(const ResultReport&, const ResultReport&) = default;

private:
    std::vector<SummaryEntry> summary_;
    std::vector<ResultTable> tables_;
    std::vector<ResultImage> images_;
};

}  // namespace dropscope
