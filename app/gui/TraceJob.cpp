#include "gui/TraceJob.hpp"

#include "tally/OrderTally.hpp"
#include "tally/StandardTallies.hpp"
#include "transport/OpticalScene.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <future>
#include <utility>
#include <variant>

namespace dropscope::gui {

namespace {

// Seconds between progress reports: ten a second moves a progress bar smoothly, at no cost to the run.
constexpr double kProgressInterval = 0.1;
// Seconds a batch of photons lasts, after the first: the partial results refresh about twice a second, and the
// batches' set-up (per-thread tally copies, their merge) stays a small part of the run.
constexpr double kBatchSeconds = 0.5;
// Photons in the first batch, and the fewest in any: a few chunks of 256 per thread, to measure the rate by.
constexpr std::uint64_t kFirstBatch = 2048;
// The angular bins of the angular distribution and the ray orders.
constexpr int kAngularBins = 180;
// Seconds of Mie theory a trace may spend beside its photons, and at most this many sizes for a cloud: a live
// trace restarted by an edit waits for it. One size of x = 1000 in 180 bins takes about 15 ms, growing as x^2
// (docs/performance.md, "Mie"); a sphere larger than the budget is still computed, alone.
constexpr double kMieSeconds = 0.5;
constexpr double kMieSecondsAtX1000 = 0.015;
constexpr std::size_t kMaxMieSizes = 200;
// Beyond this x one sphere alone takes more than kMieSeconds: the app leaves it to dropscope mie.
constexpr double kMaxAppSizeParameter = 6000.0;

// How many of the cloud's sizes (largest x `largest`) the app averages Mie theory over.
std::size_t mieSizeBudget(double largest) {
    const double perSize = kMieSecondsAtX1000 * std::max(largest / 1000.0, 0.1) * std::max(largest / 1000.0, 0.1);
    return std::clamp<std::size_t>(static_cast<std::size_t>(kMieSeconds / perSize), 1, kMaxMieSizes);
}

// What the app counts: standardTallies, the ray orders and the scene's detectors with the energy budget.
TallySet appTallies(const Scene& scene, const TransportSettings& transport,
                    const std::optional<WavelengthBins>& bands) {
    const PolarisationModel polarisation = transport.polarisation;
    TallySet tallies = standardTallies(kAngularBins, polarisation, bands);
    tallies.add(std::make_unique<OrderTally>(kAngularBins, transport.diffraction != DiffractionModel::None));
    addDetectorTallies(tallies, scene, polarisation);
    return tallies;
}

// The next batch's photons: about kBatchSeconds at the rate of the last one, at least kFirstBatch.
std::uint64_t nextBatch(std::uint64_t lastPhotons, double lastSeconds, std::uint64_t remaining) {
    const double rate = static_cast<double>(lastPhotons) / std::max(lastSeconds, 1e-3);
    const auto photons = static_cast<std::uint64_t>(std::min(rate * kBatchSeconds, 1e15));
    return std::min(std::max(photons, kFirstBatch), remaining);
}

}  // namespace

TraceJob::~TraceJob() {
    cancel();
    joinWorker();
}

void TraceJob::start(Scene scene, TraceSettings settings, std::optional<WavelengthBins> wavelengths) {
    cancel();
    joinWorker();
    outcome_.reset();
    takePartial();
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
    takePartial();
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

std::optional<TracePartial> TraceJob::takePartial() {
    const std::lock_guard lock(partialMutex_);
    return std::exchange(partial_, std::nullopt);
}

void TraceJob::joinWorker() {
    if (worker_.joinable()) worker_.join();
}

void TraceJob::solveMie(const Scene& scene, TraceOutcome& outcome) {
    try {
        auto spheres = sphereSceneMie(scene);
        if (const auto* why = std::get_if<std::string>(&spheres)) {
            outcome.mieNote = *why;
            return;
        }
        SphereSceneMie& found = std::get<SphereSceneMie>(spheres);
        // Compared only where the trace is what Mie theory describes: light of the scene wavelength along one axis.
        for (const Source& source : scene.sources) {
            if (source.spectrum &&
                !(source.spectrum->kind() == Spectrum::Kind::Lines && source.spectrum->pointsNm().size() == 1 &&
                  source.spectrum->pointsNm().front().first == scene.wavelengthNm)) {
                outcome.mieNote = "a source has a spectrum; Mie theory here is for the scene wavelength alone";
                return;
            }
            if (source.divergenceDeg > 0.0) {
                outcome.mieNote = "a source diverges; Mie theory here is for a plane wave";
                return;
            }
            if (source.type == SourceType::PointSource) {
                outcome.mieNote = "a point source's light is not a plane wave";
                return;
            }
        }
        if (found.sizes.back() > kMaxAppSizeParameter) {
            char note[160];
            std::snprintf(note, sizeof note,
                          "x = %.6g is more than the app computes beside a trace (%.0f); dropscope "
                          "mie --scene does",
                          found.sizes.back(), kMaxAppSizeParameter);
            outcome.mieNote = note;
            return;
        }
        found.sizes = sizeSample(found.sizes, mieSizeBudget(found.sizes.back()));
        if (!mieCache_ || mieCache_->first.m != found.m || mieCache_->first.sizes != found.sizes) {
            mieCache_.reset();
            mieCache_.emplace(found, mieAverageOverSizes(found.m, found.sizes, static_cast<std::size_t>(kAngularBins)));
        }
        outcome.mieSpheres = std::move(found);
        outcome.mie = mieCache_->second;
    } catch (const std::exception& error) {
        outcome.mieNote = std::string("Mie theory failed: ") + error.what();
    }
}

// On the worker thread: nothing here may escape, or std::thread would call std::terminate.
void TraceJob::run(Scene scene, const TraceSettings& settings, const std::optional<WavelengthBins>& wavelengths) {
    TraceOutcome outcome;
    try {
        // Mie theory beside the photons: both use the cores, and neither waits for the other to start.
        auto mie = std::async(std::launch::async, [&] { solveMie(scene, outcome); });
        struct JoinMie {
            std::future<void>& future;
            ~JoinMie() {
                if (future.valid()) future.wait();
            }
        } joinMie{mie};
        const OpticalScene optical(scene, settings.transport.diffraction != DiffractionModel::None);
        const TallySet tallies = appTallies(scene, settings.transport, wavelengths);
        buildingOctree_.store(false, std::memory_order_relaxed);
        const auto start = std::chrono::steady_clock::now();
        const auto elapsed = [&] {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        };
        TraceResult& total = outcome.result;
        total.requested = settings.photons;
        total.tallies = tallies.emptyCopy();
        TraceSettings batch = settings;
        batch.photons = std::min(kFirstBatch, settings.photons);
        TraceControl control;
        control.stop = &stop_;
        control.interval = kProgressInterval;
        control.onProgress = [&](const TraceProgress& progress) {
            done_.store(total.photons + progress.done, std::memory_order_relaxed);
            seconds_.store(elapsed(), std::memory_order_relaxed);
        };
        while (true) {
            TraceResult part = runTrace(optical, scene.sources, batch, tallies, control);
            total.tallies.merge(part.tallies);
            total.photons += part.photons;
            total.threads = part.threads;
            for (PhotonPath& path : part.paths) total.paths.push_back(std::move(path));
            done_.store(total.photons, std::memory_order_relaxed);
            seconds_.store(elapsed(), std::memory_order_relaxed);
            if (part.partial || total.photons >= settings.photons) break;
            {
                TracePartial partial{total.tallies, total.photons, settings.photons};
                const std::lock_guard lock(partialMutex_);
                partial_ = std::move(partial);
            }
            batch.firstPhoton = total.photons;
            batch.photons = nextBatch(part.photons, part.seconds, settings.photons - total.photons);
        }
        total.partial = total.photons < settings.photons;
        total.seconds = elapsed();
        mie.get();
    } catch (const std::exception& error) {
        outcome.error = error.what();
    } catch (...) {
        outcome.error = "the trace failed with an unknown error";
    }
    takePartial();
    buildingOctree_.store(false, std::memory_order_relaxed);
    outcome.scene = std::move(scene);
    outcome_ = std::move(outcome);
    finished_.store(true, std::memory_order_release);
}

}  // namespace dropscope::gui
