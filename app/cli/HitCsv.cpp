#include "cli/HitCsv.hpp"

#include <charconv>
#include <cstring>
#include <memory>
#include <ostream>
#include <string_view>

namespace dropscope {

namespace {

// The text goes to the stream in blocks of this size (less the last line that did not fit).
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;

// The longest line: a 20-digit ray index, a 10-digit shape id, and a distance of at most 24 characters
// ("-1.2345678901234567e-308"), two commas and the newline; rounded up.
constexpr std::size_t kMaxLineBytes = 64;

// `value` as "%.17g" prints it: std::to_chars with the general format and a precision is specified as
// printf's %g with that precision (tests/app/HitCsvTest.cpp checks the bytes against snprintf).
char* appendDistance(char* at, double value) {
    return std::to_chars(at, at + kMaxLineBytes, value, std::chars_format::general, 17).ptr;
}

template <typename Integer>
char* appendInteger(char* at, Integer value) {
    return std::to_chars(at, at + kMaxLineBytes, value).ptr;
}

char* appendText(char* at, std::string_view text) {
    std::memcpy(at, text.data(), text.size());
    return at + text.size();
}

}  // namespace

void writeHitCsv(const std::vector<RayHit>& hits, std::ostream& out) {
    const std::unique_ptr<char[]> block = std::make_unique_for_overwrite<char[]>(kBlockBytes);
    char* const blockEnd = block.get() + kBlockBytes;
    char* at = appendText(block.get(), "ray,shape,distance\n");
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (blockEnd - at < static_cast<std::ptrdiff_t>(kMaxLineBytes)) {
            out.write(block.get(), at - block.get());
            at = block.get();
        }
        at = appendInteger(at, i);
        if (hits[i]) {
            *at++ = ',';
            at = appendInteger(at, hits[i].shape);
            *at++ = ',';
            at = appendDistance(at, hits[i].distance);
            *at++ = '\n';
        } else {
            at = appendText(at, ",-1,nan\n");
        }
    }
    out.write(block.get(), at - block.get());
}

}  // namespace dropscope
