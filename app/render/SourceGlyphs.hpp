#pragma once

#include "render/DrawData.hpp"
#include "scene/Source.hpp"

#include <vector>

namespace dropscope::render {

inline constexpr Colour kSourceColour{1.0f, 0.95f, 0.55f, 1.0f};  // pale yellow: light

// Sources as line glyphs of scale `size`: a beam, an arrow of length `size` from its origin along its
// direction and its disk as a circle of its radius; a ray, the arrow; a point source, a three-axis star
// `size` / 2 across.
void addSourceGlyphs(LineBatch& lines, const std::vector<Source>& sources, double size);

}  // namespace dropscope::render
