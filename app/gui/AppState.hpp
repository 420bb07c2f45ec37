#pragma once

#include "edit/SceneDocument.hpp"
#include "gui/TraceJob.hpp"
#include "render/Camera.hpp"
#include "render/OctreeLayer.hpp"
#include "render/SceneLayers.hpp"
#include "transport/RayTree.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dropscope::gui {

// The line at the bottom of the window: what the last action did, or why it was refused.
struct StatusMessage {
    std::string text;
    bool error = false;
};

// Where a click in placement mode drops a droplet when no surface is under the cursor: the plane
// normal to `axis` at `offset` along it (default: the horizontal plane through the scene's centre).
struct PlacementPlane {
    int axis = 1;  // 0 x, 1 y, 2 z
    double offset = 0.0;
};

// The slice plane: everything on the far side of the plane normal to `axis` at `offset` is hidden
// (render::SlicePlane); `flip` keeps the other side.
struct SliceSettings {
    bool enabled = false;
    int axis = 2;
    double offset = 0.0;
    bool flip = false;

    bool operator==(const SliceSettings&) const = default;
};

// What the fire controls start: N Monte Carlo photons, of which the first `paths` are recorded.
struct FireSettings {
    std::uint64_t photons = 1000;
    std::uint64_t paths = 50;
    std::uint64_t seed = 1;
    bool live = true;  // trace again when the scene changes, so paths follow moved droplets
};

// A finished trace and how its compact shape ids map back to the document's slots.
struct TraceShown {
    TraceOutcome outcome;
    std::vector<ShapeId> slotOfShape;
    std::shared_ptr<const Octree> octree;  // over the traced shapes, built for the first traversal asked
};

// The screenshot the next frame writes, after everything is drawn.
struct ScreenshotRequest {
    std::filesystem::path file;
    bool panels = false;
    int width = 0;  // 0: the window's size (panels or not)
    int height = 0;
    int delayFrames = 0;  // frames to wait first, e.g. until the dialog that asked for it has closed
};

// The file-name prompt open, if any (File menu, Ctrl+O).
enum class FilePrompt { None, Open, SaveAs, ExportPaths, Screenshot };

// Where a widget was drawn, in ImGui's display coordinates (window pixels).
struct ItemRect {
    float minX = 0.0f;
    float minY = 0.0f;
    float maxX = 0.0f;
    float maxY = 0.0f;
};

// Everything the panels read and change. The App owns one; panels get it by reference.
struct AppState {
    std::unique_ptr<SceneDocument> document;
    std::uint64_t opened = 0;         // scenes opened since the first: tells one document from the next
    std::filesystem::path scenePath;  // where Save writes; empty for a new scene

    render::Camera camera;
    bool fitRequested = true;
    render::LayerOptions layers;
    SliceSettings slice;
    ShapeId selected = RayHit::kNone;

    bool placementMode = false;
    double placementRadius = 0.25;
    MediumId placementMedium = 0;
    PlacementPlane placementPlane;

    std::size_t selectedSource = 0;
    FireSettings fire;
    TraceJob job;
    std::vector<ShapeId> pendingSlots;  // slotOfShape of the run in progress
    std::uint64_t firedRevision = 0;    // the document revision the last run traced
    std::optional<TraceShown> trace;    // the last finished Monte Carlo run
    std::optional<RayTree> rayTree;     // the last ray fired as a tree
    std::uint64_t rayTreeRevision = 0;
    // Which results are shown: moves on whenever `trace` or `rayTree` is replaced or dropped.
    std::uint64_t shownTraces = 0;
    bool automaticTrace = false;  // the run in progress was started by "live", not the user

    int selectedPath = -1;                          // index into trace->outcome.result.paths
    int selectedEvent = 0;                          // within that path; the segment from it to the next is "selected"
    std::optional<render::RayTraversal> traversal;  // of the selected segment

    StatusMessage status;
    bool showHelp = false;
    FilePrompt prompt = FilePrompt::None;
    std::uint32_t editingItem = 0;  // the ImGui item whose edits merge into one undo step (0: none)
    bool quit = false;
    std::optional<ScreenshotRequest> screenshot;
    std::filesystem::path screenshotDirectory = ".";  // F12's timestamped PNGs
    std::filesystem::path lastScreenshot;
    // A few fields' places as last drawn (the shape editor's "centre"), by name: where the UI tests click
    // to type into them, as a user would, without depending on the panel's layout.
    std::map<std::string, ItemRect> itemRects;

    Eigen::AlignedBox3d sceneBounds;  // of the shapes, as last drawn (render::sceneBounds)

    void say(std::string text) { status = {std::move(text), false}; }
    void refuse(std::string text) { status = {std::move(text), true}; }
};

// The selected source's index among `sources` (non-empty): the selection clamped to the list, which
// may have shrunk since it was made.
inline std::size_t selectedSourceIndex(const AppState& state, const std::vector<Source>& sources) {
    return std::min(state.selectedSource, sources.size() - 1);
}

}  // namespace dropscope::gui
