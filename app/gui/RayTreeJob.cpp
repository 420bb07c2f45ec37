#include "gui/RayTreeJob.hpp"

#include <exception>
#include <utility>

namespace dropscope::gui {

RayTreeOutcome traceRayTreeRequest(RayTreeRequest request) {
    RayTreeOutcome outcome;
    try {
        std::shared_ptr<const RayTreeScene> scene = std::move(request.kept);
        if (!scene) {
            auto built = std::make_shared<RayTreeScene>();
            built->generation = request.generation;
            built->revision = request.revision;
            built->optical = std::make_shared<const OpticalScene>(request.scene);
            built->slotOfShape = std::move(request.slotOfShape);
            scene = std::move(built);
        }
        outcome.tree = traceRayTree(*scene->optical, request.ray, 1.0, request.settings, request.polarisation);
        outcome.drawOrder = render::rayTreeDrawOrder(*outcome.tree, &scene->optical->octree());
        outcome.scene = std::move(scene);
    } catch (const std::exception& error) {
        outcome.error = error.what();
    } catch (...) {
        outcome.error = "an unknown error";
    }
    return outcome;
}

RayTreeJob::~RayTreeJob() { joinWorker(); }

void RayTreeJob::start(RayTreeRequest request) {
    joinWorker();
    outcome_.reset();
    finished_.store(false);
    worker_ = std::thread([this, traced = std::move(request), gate = std::exchange(gate_, {})]() mutable {
        if (gate.valid()) gate.wait();
        // traceRayTreeRequest catches what the engine throws; only running out of memory for the outcome's own
        // message could escape, and the thread must still say it is done.
        try {
            outcome_ = traceRayTreeRequest(std::move(traced));
        } catch (...) {
            outcome_.reset();
        }
        finished_.store(true, std::memory_order_release);
    });
}

void RayTreeJob::holdNext(std::shared_future<void> gate) { gate_ = std::move(gate); }

bool RayTreeJob::running() const { return worker_.joinable() && !finished_.load(std::memory_order_acquire); }

std::optional<RayTreeOutcome> RayTreeJob::takeResult() {
    if (!worker_.joinable() || !finished_.load(std::memory_order_acquire)) return std::nullopt;
    joinWorker();
    if (!outcome_) {
        RayTreeOutcome failed;
        failed.error = "out of memory";
        return failed;
    }
    return std::exchange(outcome_, std::nullopt);
}

void RayTreeJob::joinWorker() {
    if (worker_.joinable()) worker_.join();
}

}  // namespace dropscope::gui
