#include "gui/TraceJob.hpp"

#include "tally/StandardTallies.hpp"
#include "transport/OpticalScene.hpp"

#include <exception>
#include <utility>

namespace dropscope::gui {

namespace {

// Seconds between progress reports: ten a second moves a progress bar smoothly, at no cost to the run.
constexpr double kProgressInterval = 0.1;

}  // namespace

TraceJob::~TraceJob() {
    cancel();
    joinWorker();
}

void TraceJob::start(Scene scene, TraceSettings settings, std::optional<WavelengthBins> wavelengths) {
    cancel();
    joinWorker();
    outcome_.reset();
    stop_.store(false);
    finished_.store(false);
    buildingOctree_.store(true);
    done_.store(0);
    total_.store(settings.photons);
    seconds_.store(0.0);
    worker_ = std::thread([this, traced = std::move(scene), settings, wavelengths]() mutable {
        run(std::move(traced), settings, wavelengths);
    });
}

void TraceJob::cancel() { stop_.store(true, std::memory_order_relaxed); }

void TraceJob::discard() {
    cancel();
    joinWorker();
    outcome_.reset();
}

bool TraceJob::running() const { return worker_.joinable() && !finished_.load(std::memory_order_acquire); }

TraceJobProgress TraceJob::progress() const {
    return {buildingOctree_.load(std::memory_order_relaxed), done_.load(std::memory_order_relaxed),
            total_.load(std::memory_order_relaxed), seconds_.load(std::memory_order_relaxed)};
}

std::optional<TraceOutcome> TraceJob::takeResult() {
    if (!worker_.joinable() || !finished_.load(std::memory_order_acquire)) return std::nullopt;
    joinWorker();
    return std::exchange(outcome_, std::nullopt);
}

void TraceJob::joinWorker() {
    if (worker_.joinable()) worker_.join();
}

// On the worker thread: nothing here may escape, or std::thread would call std::terminate.
void TraceJob::run(Scene scene, const TraceSettings& settings, const std::optional<WavelengthBins>& wavelengths) {
    TraceOutcome outcome;
    try {
        const OpticalScene optical(scene);
        buildingOctree_.store(false, std::memory_order_relaxed);
        TraceControl control;
        control.stop = &stop_;
        control.interval = kProgressInterval;
        control.onProgress = [this](const TraceProgress& progress) {
            done_.store(progress.done, std::memory_order_relaxed);
            seconds_.store(progress.seconds, std::memory_order_relaxed);
        };
        outcome.result = runTrace(optical, scene.sources, settings,
                                  standardTallies(180, settings.transport.polarisation, wavelengths), control);
        done_.store(outcome.result.photons, std::memory_order_relaxed);
        seconds_.store(outcome.result.seconds, std::memory_order_relaxed);
    } catch (const std::exception& error) {
        outcome.error = error.what();
    } catch (...) {
        outcome.error = "the trace failed with an unknown error";
    }
    buildingOctree_.store(false, std::memory_order_relaxed);
    outcome.scene = std::move(scene);
    outcome_ = std::move(outcome);
    finished_.store(true, std::memory_order_release);
}

}  // namespace dropscope::gui
