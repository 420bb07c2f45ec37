#pragma once

#include "tally/ResultReport.hpp"

#include <iosfwd>

namespace dropscope {

// A result table as CSV: a header of the column names, then one line per row; counts as integers,
// numbers in the shortest form that reads back exactly ("nan" where undefined).
void writeTableCsv(const ResultTable& table, std::ostream& out);

}  // namespace dropscope
