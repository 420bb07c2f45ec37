#pragma once

#include <charconv>
#include <string>

namespace dropscope {

// The shortest decimal that reads back as `value` ("700", "587.56", "1e-07"), for messages.
inline std::string shortestDecimal(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace dropscope
