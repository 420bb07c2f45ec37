#pragma once

#include "render/DetectorGlyphs.hpp"
#include "render/DrawData.hpp"
#include "render/OctreeLayer.hpp"
#include "render/PathLayer.hpp"
#include "render/RayTreeLayer.hpp"
#include "render/Renderer.hpp"
#include "render/SlicePlane.hpp"
#include "run/TraceRun.hpp"
#include "scene/Source.hpp"
#include "transport/RayTree.hpp"

#include <optional>
#include <vector>

namespace dropscope::render {

// Every switch of what is drawn, in one struct the GUI holds and the snapshot fills from its options.
struct LayerOptions {
    RenderOptions render;              // shapes on/off, translucency, background (Renderer::draw)
    ShapeId selected = RayHit::kNone;  // drawn in kHighlight
    bool octree = false;
    OctreeFilter octreeFilter{OctreeFilter::Mode::OnlyLevel, 0, false};
    bool traversal = false;  // the cells of one ray's octree traversal
    bool paths = true;
    PathColouring pathColouring = PathColouring::Weight;
    bool markers = false;  // event markers of the paths and the ray tree
    bool rayTree = false;
    bool sources = false;
    bool detectors = false;  // plane outlines with their images, far-field frusta (DetectorGlyphs.hpp)
    bool axes = false;
    bool grid = false;
    // Hides what lies beyond the plane (SlicePlane.hpp): shapes and markers by their centre; the octree
    // cells, traversal, paths, ray tree and grid cut at the plane. Source and detector glyphs and axes, the
    // guides that say where the light comes from, where it is counted and which way is which, stay whole.
    std::optional<SlicePlane> slice;

    bool operator==(const LayerOptions&) const = default;
};

// What the layers are drawn from. Paths, the ray tree and the traversal are computed by the caller
// (the GUI on demand, the snapshot from its options); a layer whose data is absent draws nothing.
struct LayerInputs {
    const Octree& octree;
    const std::vector<Source>& sources;
    Eigen::AlignedBox3d bounds;                     // the shapes' (sceneBounds): sizes glyphs, markers, grid
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();  // the camera's: the grid lies across it
    const std::vector<PhotonPath>* paths = nullptr;
    const RayTree* rayTree = nullptr;
    // The ray tree's draw order, its chords found among shapes the same as `octree`'s (rayTreeDrawOrder); null: the
    // layer works it out.
    const RayTreeDrawOrder* rayTreeDrawOrder = nullptr;
    // The octree slot of each shape id the paths' and the ray tree's events name (a trace's compact scene:
    // SceneDocument::toScene); null: the octree's own ids.
    const std::vector<ShapeId>* pathSlots = nullptr;
    const std::vector<ShapeId>* rayTreeSlots = nullptr;
    const RayTraversal* traversal = nullptr;
    // The event the path inspector is at: its polarisation ellipse is drawn there when it carries a
    // polarisation (PolarisationEllipse.hpp).
    const Event* currentEvent = nullptr;
    const std::vector<Detector>* detectors = nullptr;
    const std::vector<DetectorImage>* detectorImages = nullptr;  // drawn on the planes of the same name and grid
};

// Sizes of the drawn helpers, as fractions of the diagonal of the scene's bounds.
inline constexpr double kEscapeLength = 0.5;  // escaping paths and branches go on this far
inline constexpr double kMarkerRadius = 0.006;
inline constexpr double kSourceGlyph = 0.15;  // a source's arrow, a detector's normal and frustum
inline constexpr double kAxisLength = 0.25;
// The polarisation ellipse's semi-major axis: about five times the current event's marker (2.5
// kMarkerRadius), so it shows well around it.
inline constexpr double kEllipseSize = 0.08;

struct SceneLayers {
    LineBatch lines;
    std::vector<ShapeInstance> markers;
    TriangleBatch surfaces{Anchor{}};  // detector images and fills
    // The paths' and the ray tree's chords of spheres and ellipsoids (Chords.hpp), drawn only when they can
    // show. Without a slice plane only: a shape beyond the plane is left out, and its chord may show.
    LineBatch chords{Anchor{}};
};

// The bounds of the shapes (null slots skipped); the cube [-1, 1]^3 for a scene with none.
Eigen::AlignedBox3d sceneBounds(const std::vector<std::unique_ptr<Shape>>& shapes);

// The line batch and the markers of every layer switched on. Where lines coincide the first one added
// wins the depth test (GL_LESS), so they go in order of importance: polarisation ellipse (its line along
// the direction lies on the path), traversal, ray tree, paths, sources, detectors, axes, octree cells, grid. With a
// slice plane, the hidden side is left out.
SceneLayers buildSceneLayers(const LayerInputs& inputs, const LayerOptions& options, const Anchor& anchor);

// Hands the shapes (the selected one highlighted; with a slice plane only those on its kept side) and the
// layers to the renderer.
void uploadScene(Renderer& renderer, const std::vector<std::unique_ptr<Shape>>& shapes, const SceneLayers& layers,
                 const LayerOptions& options);
// Its two halves: the shapes alone (the costly one at 1e6 droplets), and the layers alone.
void uploadShapes(Renderer& renderer, const std::vector<std::unique_ptr<Shape>>& shapes, const LayerOptions& options);
void uploadLayers(Renderer& renderer, const SceneLayers& layers);

}  // namespace dropscope::render
