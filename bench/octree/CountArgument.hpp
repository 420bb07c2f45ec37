#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace dropscope::bench {

// A benchmark's count argument: "200000", "2e5" and "1.5e6" alike, at most 1e12.
inline std::uint64_t parseCount(const std::string& flag, const char* text) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(value >= 0.0) || value > 1e12) {
        throw std::invalid_argument(flag + ": expected a count such as 1e5, got '" + text + "'");
    }
    return static_cast<std::uint64_t>(std::llround(value));
}

}  // namespace dropscope::bench
