#pragma once

#include <atomic>
#include <csignal>

namespace dropscope {

// Turns the first Ctrl-C (SIGINT) into a request to stop: while a guard is alive, SIGINT sets flag()
// instead of killing the process, and the handler is installed with SA_RESETHAND so the default
// action is back at once: a second Ctrl-C kills immediately. A SIGINT that is ignored when the guard
// is made (a background job of a non-interactive shell) stays ignored. With kAlsoTerminate, SIGTERM
// is taken the same way: mpirun passes a Ctrl-C on to its ranks as SIGTERM. The destructor restores
// the previous dispositions. One guard at a time: the flag is process-wide, as signals are.
class InterruptGuard {
public:
    enum Signals { kInterruptOnly, kAlsoTerminate };

    explicit InterruptGuard(Signals signals = kInterruptOnly);
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // For TraceControl::stop.
    const std::atomic<bool>& flag() const;
    bool interrupted() const { return flag().load(); }

private:
    struct Handled {
        int signal = 0;
        struct sigaction previous {};
        bool installed = false;
    };
    Handled handled_[2];
};

}  // namespace dropscope
