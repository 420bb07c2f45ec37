#pragma once

#include "geometry/Vector.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace dropscope {

// Columns padded to their widest cell, two spaces apart; numeric columns are right-aligned.
class TextTable {
public:
    enum class Align { Left, Right };
    struct Column {
        std::string heading;
        Align align = Align::Left;
    };

    explicit TextTable(std::vector<Column> columns);
    void addRow(std::vector<std::string> cells);
    // Writes the heading row and the rows, each line prefixed by `indent`.
    void write(std::ostream& out, const std::string& indent = "  ") const;

private:
    std::vector<Column> columns_;
    std::vector<std::vector<std::string>> rows_;
};

// %.6g: the precision of every number in the tables.
std::string formatNumber(double value);
// "lo .. hi"
std::string formatRange(double low, double high);
// "(x, y, z)"
std::string formatVector(const Eigen::Vector3d& v);

}  // namespace dropscope
