#include "run/TraceRun.hpp"

#include "scene/WavelengthCoverage.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace {

// Photons are handed out in chunks through one atomic counter: few enough atomics to be free, small
// enough that a stop request or a progress report is never far away.
constexpr std::uint64_t kChunk = 256;

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Scores one photon's events and flights into a thread's tallies, and records its path if it has one.
class PhotonScorer final : public PhotonObserver {
public:
    PhotonScorer(TallySet& tallies, std::uint64_t photon, std::size_t source, std::vector<Event>* path)
        : tallies_(tallies), photon_(photon), source_(source), path_(path) {}

    void event(const Event& event, const PhotonState& state) override {
        if (path_) path_->push_back(event);
        tallies_.score(event, {photon_, source_, state});
    }
    void flight(const Flight& flight, const PhotonState& state) override {
        tallies_.scoreFlight(flight, {photon_, source_, state});
    }
    bool wantsFlights() const override { return tallies_.scoresFlights(); }

private:
    TallySet& tallies_;
    std::uint64_t photon_;
    std::size_t source_;
    std::vector<Event>* path_;
};

}  // namespace

TraceResult runTrace(const OpticalScene& scene, const std::vector<Source>& sources, const TraceSettings& settings,
                     const TallySet& tallies, const TraceControl& control) {
    if (sources.empty()) throw std::invalid_argument("the scene has no light sources");
    const bool polarised = settings.transport.polarisation == PolarisationModel::Stokes;
    if (polarised && settings.transport.fresnel != FresnelModel::Exact) {
        throw std::invalid_argument("Schlick's approximation is unpolarised: trace it without polarisation");
    }
    for (std::size_t i = 0; i < sources.size(); ++i) {
        try {
            checkPolarisation(sources[i]);
            checkDivergence(sources[i]);
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument("source " + std::to_string(i) + ": " + error.what());
        }
    }
    if (const auto problem = findWavelengthCoverageProblem(scene.media(), sources, scene.wavelengthNm())) {
        throw std::invalid_argument("medium " + scene.media()[problem->medium].name + " " +
                                    opticalQuantityKey(problem->quantity) + ": " + problem->message +
                                    " (the light of source " + std::to_string(problem->source) + ")");
    }
    std::vector<Spectrum> spectra;
    for (const Source& source : sources) spectra.push_back(sourceSpectrum(source, scene.wavelengthNm()));

    TraceResult result;
    result.requested = settings.photons;
    const int requestedThreads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
    result.tallies = tallies.emptyCopy();
    // One empty copy of the tallies per thread, made here so a Tally need not be safe to copy from
    // several threads at once; merged after the threads end.
    std::vector<TallySet> locals;
    for (int thread = 0; thread < requestedThreads; ++thread) locals.push_back(tallies.emptyCopy());
    // Paths of photons [first, first + recorded), at paths[photon - first].
    const std::uint64_t first = settings.firstPhoton;
    const std::uint64_t recorded = settings.paths > first ? std::min(settings.paths - first, settings.photons) : 0;
    // A traced photon's path starts with its emission, so an empty one was never traced (stopped run).
    std::vector<PhotonPath> paths(recorded);

    const auto start = Clock::now();
    std::atomic<std::uint64_t> nextChunk{0};
    std::atomic<std::uint64_t> done{0};
    std::exception_ptr failure;
    std::atomic<bool> failed{false};
    const auto stopRequested = [&] {
        return failed.load(std::memory_order_relaxed) ||
               (control.stop && control.stop->load(std::memory_order_relaxed));
    };

    int threadsUsed = 1;
#pragma omp parallel num_threads(requestedThreads)
    {
#pragma omp single nowait
        threadsUsed = omp_get_num_threads();  // OMP_THREAD_LIMIT and the like may give fewer
        try {
            TallySet& local = locals[static_cast<std::size_t>(omp_get_thread_num())];
            double lastReport = 0.0;
            while (!stopRequested()) {
                const std::uint64_t begin = kChunk * nextChunk.fetch_add(1, std::memory_order_relaxed);
                if (begin >= settings.photons) break;
                const std::uint64_t end = std::min(begin + kChunk, settings.photons);
                for (std::uint64_t k = begin; k < end; ++k) {
                    const std::uint64_t photon = first + k;
                    const std::size_t sourceIndex = photon % sources.size();
                    const Source& source = sources[sourceIndex];
                    PhotonRandom random(settings.seed, photon);
                    PhotonRandom sourceRandom(settings.seed, photon, PhotonRandom::kSourceStream);
                    Ray emitted = emitPhoton(source, random);
                    const EmittedLight light = emitLight(source, spectra[sourceIndex], sourceRandom);
                    if (source.divergenceDeg > 0.0) emitted.direction = light.direction;
                    std::optional<Polarisation> polarisation;
                    if (polarised) polarisation = emittedPolarisation(source, emitted.direction);
                    std::vector<Event>* events = nullptr;
                    if (k < recorded) {
                        paths[k].photon = photon;
                        paths[k].source = sourceIndex;
                        paths[k].wavelengthNm = light.wavelengthNm;
                        events = &paths[k].events;
                    }
                    PhotonScorer scorer(local, photon, sourceIndex, events);
                    // Beams and rays: scattering angles from their axis, so a divergent beam's spread shows.
                    std::optional<Direction> axis;
                    if (source.type != SourceType::PointSource) axis = source.direction;
                    const PhotonOutcome outcome = tracePhoton(scene, emitted, random, settings.transport, &scorer,
                                                              polarisation, light.wavelengthNm, axis);
                    if (k < recorded) paths[k].fate = outcome.fate;
                }
                done.fetch_add(end - begin, std::memory_order_relaxed);
                if (omp_get_thread_num() == 0 && control.onProgress) {
                    const double now = secondsSince(start);
                    if (now - lastReport >= control.interval) {
                        lastReport = now;
                        control.onProgress({done.load(std::memory_order_relaxed), settings.photons, now});
                    }
                }
            }
        } catch (...) {
#pragma omp critical(dropscope_trace_failure)
            if (!failure) failure = std::current_exception();
            failed = true;
        }
    }
    if (failure) std::rethrow_exception(failure);
    for (const TallySet& local : locals) result.tallies.merge(local);
    result.threads = threadsUsed;

    result.seconds = secondsSince(start);
    result.photons = done.load();
    result.partial = result.photons < settings.photons;
    for (PhotonPath& path : paths) {
        if (!path.events.empty()) result.paths.push_back(std::move(path));
    }
    return result;
}

}  // namespace dropscope
