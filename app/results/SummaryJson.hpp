#pragma once

#include "tally/ResultReport.hpp"

#include <iosfwd>
#include <string_view>
#include <vector>

namespace dropscope {

// A report's summary as one JSON object, indented by 2, nested by key path. Top-level keys named in
// `keyOrder` come first, in that order (a file format's documented order); the others follow in the
// order they were set. Non-finite numbers are written as null, counts as integers, numbers in the
// shortest form that reads back exactly. Text that is not UTF-8 (a path from argv) is replaced, not refused.
void writeSummaryJson(const ResultReport& report, const std::vector<std::string_view>& keyOrder, std::ostream& out);

}  // namespace dropscope
