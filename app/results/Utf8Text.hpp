#pragma once

#include <string>
#include <string_view>

namespace dropscope {

// `text` with each byte that does not belong to a well-formed UTF-8 sequence replaced by U+FFFD, as
// summary.json has it: a path from argv need not be UTF-8, a file that says its texts are must not lie.
std::string utf8Text(std::string_view text);

}  // namespace dropscope
