#include "cli/InterruptGuard.hpp"

namespace dropscope {

namespace {

// A signal handler may only touch lock-free atomics (and volatile sig_atomic_t).
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> interruptRequested{false};

extern "C" void onInterrupt(int) { interruptRequested.store(true); }

}  // namespace

InterruptGuard::InterruptGuard(Signals signals) {
    interruptRequested.store(false);
    handled_[0].signal = SIGINT;
    handled_[1].signal = signals == kAlsoTerminate ? SIGTERM : 0;
    for (Handled& handled : handled_) {
        if (handled.signal == 0) continue;
        if (::sigaction(handled.signal, nullptr, &handled.previous) != 0 || handled.previous.sa_handler == SIG_IGN) {
            continue;
        }
        struct sigaction action {};
        action.sa_handler = onInterrupt;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESETHAND;  // the next such signal gets the default action: kill
        handled.installed = ::sigaction(handled.signal, &action, nullptr) == 0;
    }
}

InterruptGuard::~InterruptGuard() {
    for (Handled& handled : handled_) {
        if (handled.installed) ::sigaction(handled.signal, &handled.previous, nullptr);
    }
}

const std::atomic<bool>& InterruptGuard::flag() const { return interruptRequested; }

}  // namespace dropscope
