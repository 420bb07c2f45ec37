#pragma once

#include <string>

namespace dropscope {

// The shortest text that reads back as the same double (std::to_chars); "nan", "inf", "-inf" for those.
std::string shortestText(double value);

}  // namespace dropscope
