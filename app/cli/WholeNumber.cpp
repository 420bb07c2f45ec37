#include "cli/WholeNumber.hpp"

#include <limits>
#include <string>

namespace dropscope {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Reads a run of digits starting at `position`, appending them to `digits`.
std::size_t readDigits(std::string_view text, std::size_t position, std::string& digits) {
    while (position < text.size() && isDigit(text[position])) digits += text[position++];
    return position;
}

}  // namespace

std::optional<std::uint64_t> parseWholeNumber(std::string_view text) {
    // digits [. digits] [e|E [+|-] digits], read exactly as the integer `digits` * 10^exponent
    std::string digits;
    std::size_t position = readDigits(text, 0, digits);
    const std::size_t integerDigits = digits.size();
    if (position < text.size() && text[position] == '.') position = readDigits(text, position + 1, digits);
    if (digits.empty()) return std::nullopt;
    long exponent = -static_cast<long>(digits.size() - integerDigits);
    if (position < text.size() && (text[position] == 'e' || text[position] == 'E')) {
        ++position;
        const bool negative = position < text.size() && text[position] == '-';
        if (position < text.size() && (text[position] == '-' || text[position] == '+')) ++position;
        std::string exponentDigits;
        position = readDigits(text, position, exponentDigits);
        if (exponentDigits.empty() || exponentDigits.size() > 3) return std::nullopt;
        exponent += negative ? -std::stol(exponentDigits) : std::stol(exponentDigits);
    }
    if (position != text.size()) return std::nullopt;

    // A negative exponent may only drop trailing zeros.
    for (; exponent < 0; ++exponent) {
        if (digits.back() != '0') return std::nullopt;
        digits.pop_back();
        if (digits.empty()) return 0;
    }
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t value = 0;
    for (const char digit : digits) {
        const auto d = static_cast<std::uint64_t>(digit - '0');
        if (value > (kMax - d) / 10) return std::nullopt;
        value = value * 10 + d;
    }
    for (; exponent > 0; --exponent) {
        if (value == 0) break;
        if (value > kMax / 10) return std::nullopt;
        value *= 10;
    }
    return value;
}

}  // namespace dropscope
