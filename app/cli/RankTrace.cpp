#include "cli/RankTrace.hpp"

#include "run/RankResult.hpp"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#ifdef DROPSCOPE_WITH_MPI
#include <mpi.h>
#endif

namespace dropscope {

PhotonShare photonShare(std::uint64_t photons, int rank, int size) {
    __extension__ typedef unsigned __int128 Wide;  // N r overflows 64 bits for N near 2^64
    const auto bound = [&](int r) {
        return static_cast<std::uint64_t>(static_cast<Wide>(photons) * static_cast<Wide>(r) / static_cast<Wide>(size));
    };
    return {bound(rank), bound(rank + 1) - bound(rank)};
}

#ifdef DROPSCOPE_WITH_MPI

namespace {

using Clock = std::chrono::steady_clock;

enum Tag : int { kProgressTag = 1, kStopTag = 2, kResultTag = 3 };

// A progress message: photons traced so far, and these flags.
constexpr std::uint64_t kStopAsked = 1;
constexpr std::uint64_t kFinished = 2;

// MPI counts are int: a result is sent in pieces of at most this many bytes.
constexpr std::size_t kPieceBytes = std::size_t{1} << 30;

// While tracing, every rank but 0 sends rank 0 its count of photons traced (and whether it was asked to
// stop) about every TraceControl::interval; rank 0 sums them for the progress line and, once any rank
// asks to stop, tells every other rank to stop. Each rank's last message says it has finished. Only
// non-blocking calls while tracing, so no rank ever waits for another's photons.
class ProgressExchange {
public:
    explicit ProgressExchange(const Ranks& ranks) : ranks_(ranks), done_(static_cast<std::size_t>(ranks.size()), 0) {}

    // Rank 0: the messages that have come in; *stop is set when any rank asked to stop.
    void receive(std::atomic<bool>& stop) {
        while (true) {
            int waiting = 0;
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, kProgressTag, MPI_COMM_WORLD, &waiting, &status);
            if (!waiting) break;
            std::uint64_t message[2];
            MPI_Recv(message, 2, MPI_UINT64_T, status.MPI_SOURCE, kProgressTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            auto& done = done_[static_cast<std::size_t>(status.MPI_SOURCE)];
            done = std::max(done, message[0]);
            if (message[1] & kStopAsked) stop = true;
            if (message[1] & kFinished) ++finished_;
        }
    }
    // Rank 0: tells the other ranks to stop, once.
    void sendStops() {
        if (!stopRequests_.empty()) return;
        stopRequests_.resize(static_cast<std::size_t>(ranks_.size() - 1));
        for (int rank = 1; rank < ranks_.size(); ++rank) {
            MPI_Isend(nullptr, 0, MPI_BYTE, rank, kStopTag, MPI_COMM_WORLD, &stopRequests_[rank - 1]);
        }
    }
    bool othersFinished() const { return finished_ == ranks_.size() - 1; }
    std::uint64_t total(std::uint64_t ownDone) {
        done_[0] = ownDone;
        std::uint64_t sum = 0;
        for (const std::uint64_t done : done_) sum += done;
        return sum;
    }

    // The other ranks: reports `done`, unless the last report is still on its way; sets *stop when rank 0 said so.
    void report(std::uint64_t done, bool stopAsked, std::atomic<bool>& stop) {
        if (!stopReceived_) {
            int waiting = 0;
            MPI_Iprobe(0, kStopTag, MPI_COMM_WORLD, &waiting, MPI_STATUS_IGNORE);
            if (waiting) {
                MPI_Recv(nullptr, 0, MPI_BYTE, 0, kStopTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                stopReceived_ = true;
                stop = true;
            }
        }
        int sent = 1;
        if (pending_ != MPI_REQUEST_NULL) MPI_Test(&pending_, &sent, MPI_STATUS_IGNORE);
        if (!sent) return;
        outgoing_[0] = done;
        outgoing_[1] = stopAsked ? kStopAsked : std::uint64_t{0};
        MPI_Isend(outgoing_, 2, MPI_UINT64_T, 0, kProgressTag, MPI_COMM_WORLD, &pending_);
    }
    void reportFinished(std::uint64_t done, bool stopAsked) {
        MPI_Wait(&pending_, MPI_STATUS_IGNORE);
        outgoing_[0] = done;
        outgoing_[1] = kFinished | (stopAsked ? kStopAsked : std::uint64_t{0});
        MPI_Send(outgoing_, 2, MPI_UINT64_T, 0, kProgressTag, MPI_COMM_WORLD);
    }

    // Every rank, after rank 0 has every rank's last message: a stop rank 0 sent is received by every rank
    // that has not seen it yet, so no message is left over.
    void settleStops() {
        int stopsSent = stopRequests_.empty() ? 0 : 1;
        MPI_Bcast(&stopsSent, 1, MPI_INT, 0, MPI_COMM_WORLD);
        if (ranks_.root()) {
            MPI_Waitall(static_cast<int>(stopRequests_.size()), stopRequests_.data(), MPI_STATUSES_IGNORE);
        } else if (stopsSent && !stopReceived_) {
            MPI_Recv(nullptr, 0, MPI_BYTE, 0, kStopTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        }
    }

private:
    const Ranks& ranks_;
    std::vector<std::uint64_t> done_;  // rank 0: the latest count of each rank
    int finished_ = 0;
    std::vector<MPI_Request> stopRequests_;
    MPI_Request pending_ = MPI_REQUEST_NULL;
    std::uint64_t outgoing_[2] = {0, 0};
    bool stopReceived_ = false;
};

void sendResult(const TraceResult& result) {
    const std::vector<std::byte> bytes = packRankResult(result);
    const std::uint64_t size = bytes.size();
    MPI_Send(&size, 1, MPI_UINT64_T, 0, kResultTag, MPI_COMM_WORLD);
    for (std::size_t offset = 0; offset < bytes.size(); offset += kPieceBytes) {
        const std::size_t piece = std::min(kPieceBytes, bytes.size() - offset);
        MPI_Send(bytes.data() + offset, static_cast<int>(piece), MPI_BYTE, 0, kResultTag, MPI_COMM_WORLD);
    }
}

// Rank 0: each rank's result in rank order, merged as it arrives.
void mergeResults(const Ranks& ranks, TraceResult& result) {
    for (int rank = 1; rank < ranks.size(); ++rank) {
        std::uint64_t size = 0;
        MPI_Recv(&size, 1, MPI_UINT64_T, rank, kResultTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        std::vector<std::byte> bytes(size);
        for (std::size_t offset = 0; offset < bytes.size(); offset += kPieceBytes) {
            const std::size_t piece = std::min(kPieceBytes, bytes.size() - offset);
            MPI_Recv(bytes.data() + offset, static_cast<int>(piece), MPI_BYTE, rank, kResultTag, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
        }
        mergeRankResult(result, bytes);
    }
}

}  // namespace

TraceResult traceOnRanks(const Ranks& ranks, const OpticalScene& scene, const std::vector<Source>& sources,
                         const TraceSettings& settings, const TallySet& tallies, const TraceControl& control) {
    if (!ranks.parallel()) return runTrace(scene, sources, settings, tallies, control);

    const auto start = Clock::now();
    const PhotonShare share = photonShare(settings.photons, ranks.rank(), ranks.size());
    TraceSettings own = settings;
    own.firstPhoton = settings.firstPhoton + share.first;
    own.photons = share.count;

    ProgressExchange exchange(ranks);
    std::atomic<bool> stop{false};
    const auto signalled = [&] { return control.stop && control.stop->load(); };
    TraceControl ownControl;
    ownControl.stop = &stop;
    ownControl.interval = control.interval;
    ownControl.onProgress = [&](const TraceProgress& progress) {
        if (signalled()) stop = true;
        if (ranks.root()) {
            exchange.receive(stop);
            if (stop) exchange.sendStops();
            if (control.onProgress)
                control.onProgress({exchange.total(progress.done), settings.photons, progress.seconds});
        } else {
            exchange.report(progress.done, signalled(), stop);
        }
    };
    TraceResult result = runTrace(scene, sources, own, tallies, ownControl);

    if (ranks.root()) {
        // Wait for the other ranks' last messages, still showing progress and passing on a stop.
        auto lastReport = Clock::now();
        while (true) {
            if (signalled()) stop = true;
            exchange.receive(stop);
            if (stop) exchange.sendStops();
            if (exchange.othersFinished()) break;
            const auto now = Clock::now();
            if (control.onProgress && std::chrono::duration<double>(now - lastReport).count() >= control.interval) {
                lastReport = now;
                const double seconds = std::chrono::duration<double>(now - start).count();
                control.onProgress({exchange.total(result.photons), settings.photons, seconds});
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    } else {
        exchange.reportFinished(result.photons, signalled());
    }
    exchange.settleStops();

    if (!ranks.root()) {
        sendResult(result);
        return result;
    }
    mergeResults(ranks, result);
    result.requested = settings.photons;
    result.partial = result.photons < settings.photons;
    result.ranks = ranks.size();
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
}

#else

TraceResult traceOnRanks(const Ranks&, const OpticalScene& scene, const std::vector<Source>& sources,
                         const TraceSettings& settings, const TallySet& tallies, const TraceControl& control) {
    return runTrace(scene, sources, settings, tallies, control);
}

#endif

}  // namespace dropscope
