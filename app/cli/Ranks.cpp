#include "cli/Ranks.hpp"

#include "cli/BadInput.hpp"
#include "cli/Cli.hpp"
#include "cli/RayCsv.hpp"
#include "scene/MachineMemory.hpp"
#include "scene/SceneLoader.hpp"

#include <algorithm>
#include <cstdlib>
#include <ostream>
#include <stdexcept>
#include <string>

#ifdef DROPSCOPE_WITH_MPI
#include <mpi.h>
#endif

namespace dropscope {

namespace {

// Set by the launchers MPI programs are started with: Open MPI's mpirun, a PMIx launcher (srun --mpi=pmix,
// prun), PMI-1/2 (MPICH's hydra, srun --mpi=pmi2), MVAPICH. A plain `dropscope trace` starts no MPI at all: no
// singleton start-up, no daemon.
bool launchedByMpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK", "MV2_COMM_WORLD_SIZE"}) {
        if (std::getenv(name)) return true;
    }
    return false;
}

#ifndef DROPSCOPE_WITH_MPI
// The processes a launcher says it started, where it says so.
long launchedProcesses() {
    long most = 1;
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MV2_COMM_WORLD_SIZE"}) {
        if (const char* value = std::getenv(name)) most = std::max(most, std::strtol(value, nullptr, 10));
    }
    return most;
}
#endif

}  // namespace

int launcherRank() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", "MV2_COMM_WORLD_RANK"}) {
        if (const char* value = std::getenv(name)) return static_cast<int>(std::strtol(value, nullptr, 10));
    }
    return 0;
}

Ranks::Ranks() {
    if (!launchedByMpi()) return;
#ifdef DROPSCOPE_WITH_MPI
    int already = 0;
    int finished = 0;
    MPI_Initialized(&already);
    MPI_Finalized(&finished);
    // MPI starts once per process: a second trace in the same process (the in-process tests run under a
    // launcher) runs alone.
    if (already || finished) return;
    int provided = 0;
    // Only the main thread calls MPI: the progress and stop messages go from OpenMP's thread 0 of the
    // photon loop, which is the main thread.
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    initialised_ = true;
    if (provided < MPI_THREAD_FUNNELED) {
        MPI_Finalize();
        initialised_ = false;
        throw std::runtime_error("this MPI library cannot be called from a threaded program (MPI_THREAD_FUNNELED)");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // The ranks on this node share its memory: each estimate is held to its share (docs/limits.md).
    MPI_Comm node = MPI_COMM_NULL;
    int onThisNode = 1;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node) == MPI_SUCCESS) {
        MPI_Comm_size(node, &onThisNode);
        MPI_Comm_free(&node);
    }
    shareMachineMemory(onThisNode);
#else
    // N copies of a whole run would all write the same files at once.
    if (const long processes = launchedProcesses(); processes > 1) {
        throw BadInputError("started as " + std::to_string(processes) +
                            " processes by an MPI launcher, but this dropscope was built without MPI: each would "
                            "trace every photon into the same --out (install libopenmpi-dev and rebuild; "
                            "docs/scaling.md)");
    }
#endif
}

Ranks::~Ranks() {
    shareMachineMemory(1);
#ifdef DROPSCOPE_WITH_MPI
    if (initialised_) MPI_Finalize();
#endif
}

int exitStatusOf(const std::exception_ptr& failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const std::exception&) {
        std::ostream nowhere(nullptr);  // the status alone; the failing rank says the message
        return reportFailure(failure, nowhere);
    } catch (...) {
        return kExitInternalError;
    }
}

void Ranks::together(const std::function<void()>& step) const {
    std::exception_ptr failure;
    try {
        step();
    } catch (...) {
        failure = std::current_exception();
    }
    if (!parallel()) {
        if (failure) std::rethrow_exception(failure);
        return;
    }
#ifdef DROPSCOPE_WITH_MPI
    int lowestFailing = failure ? rank_ : size_;
    MPI_Allreduce(MPI_IN_PLACE, &lowestFailing, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (lowestFailing == size_) return;
    int status = failure ? exitStatusOf(failure) : kExitBadInput;
    MPI_Bcast(&status, 1, MPI_INT, lowestFailing, MPI_COMM_WORLD);
    if (lowestFailing == rank_) std::rethrow_exception(failure);
    throw RankFailed{status};
#endif
}

void Ranks::abort(int status) const {
#ifdef DROPSCOPE_WITH_MPI
    if (initialised_) MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::_Exit(status);
}

}  // namespace dropscope
