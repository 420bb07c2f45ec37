#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <limits>

namespace dropscope {

inline constexpr std::uint64_t kNoUpperBound = std::numeric_limits<std::uint64_t>::max();

// A CLI11 transform for a count option: a whole number in [minimum, maximum] in the forms
// parseWholeNumber accepts ("1000000", "1e6", "2.5e6"; never a sign), handed on as plain digits.
CLI::Validator wholeNumberIn(std::uint64_t minimum, std::uint64_t maximum);

}  // namespace dropscope
