#pragma once

#include "optics/Polarisation.hpp"
#include "render/RayTreeLayer.hpp"
#include "scene/Scene.hpp"
#include "transport/Emission.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/RayTree.hpp"

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace dropscope::gui {

// The optical scene a ray tree is traced through, with its compact shape ids' slots in the document, and
// what it was built from: it is kept for the next tree while the document changes only its sources (a drag of
// the source with "live" on traces a tree a frame), as building it costs about what the tree does at 1e5
// droplets and seconds at 1e6.
struct RayTreeScene {
    std::uint64_t generation = 0;  // SceneState::generation
    std::uint64_t revision = 0;    // SceneDocument::revisionBesidesSources
    std::shared_ptr<const OpticalScene> optical;
    std::vector<ShapeId> slotOfShape;

    // Whether it holds the shapes of the document `generation` at `revision` (revisionBesidesSources).
    bool isOf(std::uint64_t documentGeneration, std::uint64_t documentRevision) const {
        return generation == documentGeneration && revision == documentRevision;
    }
};

// One ray tree to trace: through a kept optical scene, or through one built from `scene` first.
struct RayTreeRequest {
    std::shared_ptr<const RayTreeScene> kept;  // when set, `scene` is not read
    Scene scene;
    std::vector<ShapeId> slotOfShape;  // of `scene`
    std::uint64_t generation = 0;
    std::uint64_t revision = 0;
    Ray ray;
    RayTreeSettings settings;
    std::optional<Polarisation> polarisation;
};

// What a request gives: the tree, the scene it went through and the tree's draw order (its chords those of that
// scene's shapes), or why it failed.
struct RayTreeOutcome {
    std::shared_ptr<const RayTreeScene> scene;
    std::optional<RayTree> tree;
    std::optional<render::RayTreeDrawOrder> drawOrder;
    std::optional<std::string> error;
};

// Works out a request, building the optical scene when the request has none kept, and the tree's draw order
// (on the job's thread for a large scene, so that the frame showing the tree does not).
RayTreeOutcome traceRayTreeRequest(RayTreeRequest request);

// A ray tree of a large scene traced on a worker thread, so that the app keeps drawing while the optical scene
// is built (seconds at 1e6 droplets) and the tree traced (0.4 s there): TraceActions sends a tree there when the
// document holds more than TraceState::rayTreeBackgroundShapes shapes. Neither can be stopped half way, so a
// request made while one runs waits for it (TraceActions asks again when it ends) instead of cancelling it.
//
// Every member function is called from the UI thread only; the outcome passes to it through join().
class RayTreeJob {
public:
    RayTreeJob() = default;
    ~RayTreeJob();  // waits for a tree still being traced
    RayTreeJob(const RayTreeJob&) = delete;
    RayTreeJob& operator=(const RayTreeJob&) = delete;

    // Requires !running().
    void start(RayTreeRequest request);
    // For tests: the next request started waits for `gate` before it begins, so that it is surely still being
    // traced until the test releases it.
    void holdNext(std::shared_future<void> gate);
    bool running() const;
    // The outcome of the finished request, once; nothing while it runs or when already taken.
    std::optional<RayTreeOutcome> takeResult();

private:
    void joinWorker();

    std::thread worker_;
    std::optional<RayTreeOutcome> outcome_;  // written by the worker, read after joining it
    std::atomic<bool> finished_{false};
    std::shared_future<void> gate_;  // holdNext's
};

}  // namespace dropscope::gui
