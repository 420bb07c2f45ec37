#pragma once

#include <atomic>
#include <csignal>

namespace dropscope {

// Turns the first Ctrl-C (SIGINT) into a request to stop: while a guard is alive, SIGINT sets flag()
// instead of killing the process, and the handler is installed with SA_RESETHAND so the default
// action is back at once: a second Ctrl-C kills immediately. A SIGINT that is ignored when the guard
// is made (a background job of a non-interactive shell) stays ignored. The destructor restores the
// previous disposition. One guard at a time: the flag is process-wide, as signals are.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // For TraceControl::stop.
    const std::atomic<bool>& flag() const;
    bool interrupted() const { return flag().load(); }

private:
    struct sigaction previous_ {};
    bool installed_ = false;
};

}  // namespace dropscope
