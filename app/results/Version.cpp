#include "results/Version.hpp"

namespace dropscope {

// DROPSCOPE_VERSION is set from project(... VERSION ...) in app/CMakeLists.txt, on this library only.
std::string_view dropscopeVersion() { return DROPSCOPE_VERSION; }

}  // namespace dropscope
