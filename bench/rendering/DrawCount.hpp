#pragma once

#include "render/GlFunctions.hpp"

#include <cstdint>

namespace dropscope::bench {

// What the draw calls since the last reset submitted, counted by wrapping the draw functions of the
// GL table a renderer is given (render_bench): the renderer's own count, not a prediction of it.
struct DrawCount {
    int calls = 0;
    std::uint64_t instances = 0;  // summed over the instanced calls
    std::uint64_t vertices = 0;   // vertices submitted, times instances: vertex shader runs when nothing is reused
};

// The running count; assign {} to reset it.
DrawCount& drawCount();

// A copy of `real` whose draw functions count into drawCount() and then call `real`'s. `real` is
// copied, so it need not outlive the result; one counting table at a time.
render::GlFunctions countingDraws(const render::GlFunctions& real);

}  // namespace dropscope::bench
