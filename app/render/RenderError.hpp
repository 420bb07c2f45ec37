#pragma once

#include <stdexcept>

namespace dropscope::render {

// Anything the renderer cannot do: no context, a missing GL function, a shader that does not compile.
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace dropscope::render
