#include "cli/Ranks.hpp"

#include "cli/Cli.hpp"

#include <cstdlib>
#include <stdexcept>

#ifdef DROPSCOPE_WITH_MPI
#include <mpi.h>
#endif

namespace dropscope {

namespace {

#ifdef DROPSCOPE_WITH_MPI
// Set by the launchers MPI programs are started with: Open MPI's mpirun, a PMIx launcher (srun --mpi=pmix,
// prun), and PMI-1/2 (MPICH's hydra, srun --mpi=pmi2). A plain `dropscope trace` starts no MPI at all: no
// singleton start-up, no daemon.
bool launchedByMpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
        if (std::getenv(name)) return true;
    }
    return false;
}
#endif

}  // namespace

Ranks::Ranks() {
#ifdef DROPSCOPE_WITH_MPI
    if (!launchedByMpi()) return;
    int already = 0;
    MPI_Initialized(&already);
    if (already) throw std::logic_error("MPI is already initialised: one Ranks at a time");
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
#endif
}

Ranks::~Ranks() {
#ifdef DROPSCOPE_WITH_MPI
    if (initialised_) MPI_Finalize();
#endif
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
    if (lowestFailing == rank_) std::rethrow_exception(failure);
    throw RankFailed{kExitBadInput};
#endif
}

void Ranks::abort(int status) const {
#ifdef DROPSCOPE_WITH_MPI
    if (initialised_) MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::_Exit(status);
}

}  // namespace dropscope
