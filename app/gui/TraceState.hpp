#pragma once

#include "gui/PathFilter.hpp"
#include "gui/RayTreeJob.hpp"
#include "gui/ResultViews.hpp"
#include "gui/TraceJob.hpp"
#include "render/OctreeLayer.hpp"
#include "render/RayTreeLayer.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/RayTree.hpp"
#include "transport/SurfaceCrossing.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace dropscope::gui {

// What the fire controls start: N Monte Carlo photons, of which the first `paths` are recorded.
struct FireSettings {
    std::uint64_t photons = 1000;
    std::uint64_t paths = 50;
    std::uint64_t seed = 1;
    // Stokes: every photon and ray-tree branch carries its Stokes vector; None: unpolarised Fresnel.
    PolarisationModel polarisation = PolarisationModel::Stokes;
    // Equal wavelength bands over the sources' range, each with its angular distribution (Results); 1: none.
    int wavelengthBins = 1;
    // Fraunhofer diffraction by spheres and ellipsoids (trace --diffraction fraunhofer); off: ray optics only.
    bool diffraction = false;
    bool live = true;  // trace again when the scene, the polarisation model, the bands or diffraction change
};

// What "live" traces again for when it changes: the document's revision, the polarisation model and the
// wavelength bands.
struct TracedWith {
    std::uint64_t revision = 0;
    PolarisationModel polarisation = PolarisationModel::Stokes;
    int wavelengthBins = 1;
    bool diffraction = false;

    bool operator==(const TracedWith&) const = default;
};

// A finished trace and how its compact shape ids map back to the document's slots.
struct TraceShown {
    TraceOutcome outcome;
    std::vector<ShapeId> slotOfShape;
    std::shared_ptr<const Octree> octree;  // over the traced shapes, built for the first traversal asked
};

// The traces: the run in progress, the results shown (the last Monte Carlo run, the last ray tree) and
// the photon event selected in them. The trace actions (TraceActions.hpp) change it.
struct TraceState {
    FireSettings fire;
    TraceJob job;
    std::vector<ShapeId> pendingSlots;  // slotOfShape of the run in progress
    TracedWith fired;                   // what the last run traced
    bool automatic = false;             // the run in progress was started by "live", not the user

    std::optional<TraceShown> trace;  // the last finished Monte Carlo run
    // The run in progress's tallies so far (TraceJob::takePartial); dropped when it finishes.
    std::optional<TracePartial> partial;
    // Which tallies the result views show: moves on with every partial taken and every trace shown or dropped,
    // so the detector windows make their images again.
    std::uint64_t talliesId = 0;
    std::optional<RayTree> rayTree;  // the last ray fired as a tree
    TracedWith rayTreeTraced;        // what it was traced with
    // What it was traced through, and the next one may be.
    std::shared_ptr<const RayTreeScene> rayTreeScene;
    // Its draw order, the chords those of rayTreeScene's shapes: the 3D view takes it while the document's shapes
    // are those (ViewportScene).
    std::optional<render::RayTreeDrawOrder> rayTreeDrawOrder;
    // Trees of documents with more shapes than this are traced on rayTreeJob, so that the app keeps drawing:
    // above it the first tree of a scene costs more than about 0.1 s (its optical scene built), 2.2 s at 1e6
    // droplets, and each tree again 0.08-0.4 s (docs/performance.md).
    std::size_t rayTreeBackgroundShapes = 50'000;
    RayTreeJob rayTreeJob;
    bool rayTreeJobAutomatic = false;  // the tree on rayTreeJob was asked for by "live", not the user
    bool rayTreeJobWanted = false;     // its outcome is to be shown (not since the traces were forgotten)
    // A tree asked for while rayTreeJob was busy, traced when it is done: by "live" alone, or by the user.
    enum class RayTreeAsked { No, ByLive, ByUser };
    RayTreeAsked rayTreeAsked = RayTreeAsked::No;
    // Which results are shown: moves on whenever `trace` or `rayTree` is replaced or dropped, so the 3D
    // view knows to draw them again (as SceneDocument::revision() does for the scene).
    std::uint64_t shownId = 0;

    int selectedPath = -1;                          // index into trace->outcome.result.paths
    int selectedEvent = 0;                          // within that path; the segment from it to the next is "selected"
    std::optional<render::RayTraversal> traversal;  // of the selected segment
    PathFilter pathFilter;                          // which recorded photons the Paths panel lists
    ResultViews views;                              // detector windows, the ray orders' plot
};

}  // namespace dropscope::gui
