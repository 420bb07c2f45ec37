#include "results/Utf8Text.hpp"

#include <cstddef>

namespace dropscope {

namespace {

// The length of the well-formed UTF-8 sequence `text` starts with (Unicode 15, table 3-7), 0 when it
// starts with none.
std::size_t sequenceLength(std::string_view text) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(0);
    if (lead < 0x80) return 1;
    std::size_t length = 0;
    unsigned char secondLo = 0x80;  // the second byte's range; the others are 80..BF
    unsigned char secondHi = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) secondLo = 0xA0;  // no overlong forms
        if (lead == 0xED) secondHi = 0x9F;  // no surrogates
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) secondLo = 0x90;  // no overlong forms
        if (lead == 0xF4) secondHi = 0x8F;  // nothing above U+10FFFF
    } else {
        return 0;
    }
    if (text.size() < length) return 0;
    if (byte(1) < secondLo || byte(1) > secondHi) return 0;
    for (std::size_t k = 2; k < length; ++k) {
        if (byte(k) < 0x80 || byte(k) > 0xBF) return 0;
    }
    return length;
}

}  // namespace

std::string utf8Text(std::string_view text) {
    std::string valid;
    valid.reserve(text.size());
    while (!text.empty()) {
        const std::size_t length = sequenceLength(text);
        valid += length ? text.substr(0, length) : std::string_view("\xEF\xBF\xBD");
        text.remove_prefix(length ? length : 1);
    }
    return valid;
}

}  // namespace dropscope
