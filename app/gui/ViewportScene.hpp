#pragma once

#include "gui/AppState.hpp"
#include "render/OffscreenImage.hpp"
#include "render/Renderer.hpp"

#include <cstdint>
#include <optional>
#include <utility>

namespace dropscope::gui {

// Everything the 3D view's shapes and layers are built from, as ids, revisions and the settings
// themselves: a frame whose key differs from the one the view was last built from rebuilds it, and only
// such a frame does.
struct ViewKey {
    std::uint64_t document = 0;  // which document (SceneState::generation), and its revision
    std::uint64_t revision = 0;
    std::uint64_t shapesRevision = 0;  // SceneDocument::revisionBesidesSources
    render::LayerOptions layers;
    SliceSettings slice;
    ShapeId selectedShape = RayHit::kNone;
    std::size_t selectedSource = 0;
    std::optional<std::size_t> selectedDetector;
    std::uint64_t traces = 0;  // which trace and ray tree are shown
    int selectedPath = -1;     // the photon event selected in the trace
    int selectedEvent = 0;
    PathFilter pathFilter;  // the 3D view draws the paths the Paths panel lists
    glm::dvec3 up{0.0};     // the camera's: the grid lies across it

    bool operator==(const ViewKey&) const = default;
};

ViewKey viewKey(const AppState& state);

// The 3D view behind the panels: turns the app state into the renderer's shapes and line layers
// (rebuilt only when its key changed) and draws them with the state's camera.
//
// The picture is kept: when a frame draws the very view the frame before drew (the same build, camera and
// size) it draws it once more into an image of its own, and from then on copies that image while the view
// is that one. Panels, tooltips and a running trace's progress redraw the window many times a second without
// changing the view, and on a software renderer a view of 1e5 droplets takes tens of milliseconds to draw
// (docs/performance.md, "The app"). A view that changes every frame (an orbit) is drawn straight into the
// framebuffer, with nothing copied. A view drawn on the processor with an overlay (the app's panels) is kept by the
// renderer instead, as its colours before the overlay (render::Renderer::showHeld).
class ViewportScene {
public:
    // `keepImage` false draws the view in every frame (the frame benchmark's reference).
    explicit ViewportScene(const render::GlFunctions& gl, bool keepImage = true)
        : gl_(gl), renderer_(gl), image_(gl), keepImage_(keepImage) {}

    // Rebuilds the shapes and layers when the key changed, fits or clips the camera, and draws into the
    // bound framebuffer, or copies the kept picture there when it shows this view. A view drawn on the processor
    // (render::RenderOptions::processorRaster) gets `overlay` drawn over it before it is handed over; returns whether
    // it did.
    bool draw(AppState& state, int width, int height, const render::Renderer::RasterOverlay& overlay = {});

    // The bounds of the shapes as last drawn (render::sceneBounds): they size the source handles.
    const Eigen::AlignedBox3d& sceneBounds() const { return bounds_; }
    // What the last rebuild handed to the renderer, for the UI tests.
    const render::SceneLayers& layers() const { return layers_; }
    // Changes of what the view draws: rebuilds, and of those the ones that only recoloured the shape selected
    // before and the one selected now (nothing else changed).
    std::uint64_t rebuilds() const { return rebuilds_; }
    std::uint64_t recolours() const { return recolours_; }
    // Of the rebuilds, those that built and uploaded the shapes' instances.
    std::uint64_t shapeUploads() const { return shapeUploads_; }
    // How long the last rebuild took: the layers made and uploaded, the shapes' instances too when they changed
    // (for the frame benchmark).
    double lastRebuildSeconds() const { return lastRebuildSeconds_; }
    // Whether the last 3D view drawn was drawn on the processor (render::RenderOptions::processorRaster).
    bool lastViewOnProcessor() const { return renderer_.lastFrameOnProcessor(); }
    // Frames whose view the renderer drew, and frames that copied the kept picture instead.
    std::uint64_t drawnFrames() const { return drawnFrames_; }
    std::uint64_t copiedFrames() const { return copiedFrames_; }

private:
    // What the renderer's picture depends on besides the layers (which rebuilds_ counts).
    struct DrawnView {
        std::uint64_t build = 0;
        render::Camera camera;
        int width = 0;
        int height = 0;

        bool operator==(const DrawnView&) const = default;
    };

    void rebuild(const AppState& state, const ViewKey& key);
    // When `key` differs from the last one in the selected shape alone, recolours the two shapes in place (a
    // rebuild of 1e6 droplets takes half a second) and says so; false, changing nothing, otherwise.
    bool recolour(const AppState& state, const ViewKey& key);
    // Whether the shapes' instances made for the last key serve `key`: it has the same document, shapes and
    // media (SceneDocument::revisionBesidesSources), selected shape and slice plane. Then a rebuild (a trace or
    // ray tree shown, a layer switched, a source moved) makes and uploads the layers alone, not the shapes (half
    // a second at 1e6 droplets).
    bool shapesStay(const ViewKey& key) const;

    const render::GlFunctions& gl_;
    render::Renderer renderer_;
    render::OffscreenImage image_;
    bool keepImage_ = true;
    std::optional<DrawnView> lastDrawn_;                 // the view of the last frame
    std::optional<DrawnView> kept_;                      // the view image_ or the renderer's held picture holds
    std::optional<std::uint64_t> keptPicture_;           // the renderer's held picture (heldPicture), if it holds it
    std::optional<std::pair<int, int>> unkeepableSize_;  // a size the driver could not make image_ at
    std::uint64_t drawnFrames_ = 0;
    std::uint64_t copiedFrames_ = 0;
    render::SceneLayers layers_{render::LineBatch(render::Anchor{}), {}};
    Eigen::AlignedBox3d bounds_;
    std::optional<ViewKey> builtFrom_;
    std::uint64_t rebuilds_ = 0;
    std::uint64_t recolours_ = 0;
    std::uint64_t shapeUploads_ = 0;
    double lastRebuildSeconds_ = 0.0;
};

// The box the camera keeps between its near and far planes: the shapes, the sources, the detectors when drawn,
// and room for the escaping ends of paths.
Eigen::AlignedBox3d viewBounds(const AppState& state, const Eigen::AlignedBox3d& shapes);

}  // namespace dropscope::gui
