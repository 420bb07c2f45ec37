#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace dropscope {

// A count given on the command line: plain digits ("1000000") or exact scientific notation ("1e6",
// "2.5e6"), which is how photon counts are usually written. Nothing for a sign, a fraction that does
// not cancel ("1.5"), anything else, or a value above UINT64_MAX.
std::optional<std::uint64_t> parseWholeNumber(std::string_view text);

}  // namespace dropscope
