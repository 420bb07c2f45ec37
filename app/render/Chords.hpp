#pragma once

#include "render/DrawData.hpp"
#include "transport/Event.hpp"
#include "tree/Octree.hpp"

#include <vector>

namespace dropscope::render {

// A segment from `from` to `to` is a chord of a sphere or ellipsoid when both ends are interface events
// (reflect, refract, TIR) at that one shape of `octree` and neither end is outside it as it is now (the
// scene may have been edited since the trace). A chord lies inside the shape, which is convex, so where
// the shape is drawn opaque and neither the eye nor the near plane is inside it, the shape's front hides
// the chord (but for pixels at its rim, which a line lights up to half a pixel off the segment:
// docs/rendering.md, "Chords"). In a cloud nearly half the path segments are such
// chords (a photon crosses each droplet it enters), and llvmpipe pays for every segment it sets up, seen
// or not: the layers keep them apart so that the renderer can leave them out (Renderer::setLines).
// `slotOfShape`, when given, maps the shape ids the events name to `octree`'s (a trace's compact scene leaves out
// the document's empty slots: SceneDocument::toScene).
bool isChord(const Event& from, const Event& to, const Octree& octree,
             const std::vector<ShapeId>* slotOfShape = nullptr);

// Where a layer puts its chords: `batch`, not the layer's own lines.
struct ChordSplit {
    const Octree& octree;
    LineBatch& batch;
    const std::vector<ShapeId>* slotOfShape = nullptr;  // as isChord's
};

}  // namespace dropscope::render
