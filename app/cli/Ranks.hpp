#pragma once

#include <exception>
#include <functional>

namespace dropscope {

// The processes of one `dropscope trace` started by an MPI launcher (mpirun, srun: docs/scaling.md). MPI is
// initialised only when the program was built with it (DROPSCOPE_WITH_MPI) and the environment shows such a
// launch; otherwise this is the one rank 0 of 1, and nothing here talks to anyone. One at a time per process.
class Ranks {
public:
    Ranks();
    ~Ranks();
    Ranks(const Ranks&) = delete;
    Ranks& operator=(const Ranks&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool root() const { return rank_ == 0; }
    bool parallel() const { return size_ > 1; }
    // Started by an MPI launcher and running with MPI (even as one rank): its stderr is a pipe to the
    // launcher, and mpirun passes a Ctrl-C on as SIGTERM.
    bool launched() const { return initialised_; }

    // Runs `step` on every rank, then all learn whether it threw anywhere: on the lowest rank whose step
    // threw the exception is rethrown (so its message is printed once), every other rank then throws
    // RankFailed with the exit status that exception gives (exitStatusOf). A failure of one rank can then
    // never leave the others waiting for it.
    void together(const std::function<void()>& step) const;
    // Ends every rank at once with `status` (MPI_Abort): for a failure of one rank while the others may be
    // waiting for its messages, which no exit of this rank alone would end. Only when parallel().
    [[noreturn]] void abort(int status) const;

private:
    int rank_ = 0;
    int size_ = 1;
    bool initialised_ = false;
};

// The rank an MPI launcher gave this process in its environment (before MPI starts, and in a build without
// MPI); 0 when not started by one.
int launcherRank();

// The exit status runCli gives an exception: kExitBadInput for bad input, kExitInternalError otherwise.
int exitStatusOf(const std::exception_ptr& failure);

// Thrown by Ranks::together on the ranks whose own step went well (or failed after a lower rank's): the
// lower rank has said what went wrong, so this rank ends quietly with `status`.
struct RankFailed {
    int status;
};

}  // namespace dropscope
