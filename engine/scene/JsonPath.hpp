#pragma once

#include <cstddef>
#include <string>

// JSON paths as scene errors print them: "shapes[3].radius", "media.water.n", media["two words"].
// The root has the empty path.
namespace dropscope::jsonpath {

std::string member(const std::string& parent, const std::string& key);
std::string element(const std::string& parent, std::size_t index);

// `text` as a JSON string literal, quotes and escapes included: safe to embed in a one-line message.
std::string quoted(const std::string& text);

// The shortest text that reads back as exactly `value` ("0", "1.5", "1e-09"), for messages.
std::string number(double value);

}  // namespace dropscope::jsonpath
