#pragma once

#include <string_view>

namespace dropscope {

// The program's version, the CMake project's (e.g. "0.1.0"): what `dropscope --version` prints and the result
// files record.
std::string_view dropscopeVersion();

}  // namespace dropscope
