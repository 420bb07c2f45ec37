#include "cli/InterruptGuard.hpp"

namespace dropscope {

namespace {

// A signal handler may only touch lock-free atomics (and volatile sig_atomic_t).
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> interruptRequested{false};

extern "C" void onInterrupt(int) { interruptRequested.store(true); }

}  // namespace

InterruptGuard::InterruptGuard() {
    interruptRequested.store(false);
    if (::sigaction(SIGINT, nullptr, &previous_) != 0 || previous_.sa_handler == SIG_IGN) return;
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // the next SIGINT gets the default action: kill
    installed_ = ::sigaction(SIGINT, &action, nullptr) == 0;
}

InterruptGuard::~InterruptGuard() {
    if (installed_) ::sigaction(SIGINT, &previous_, nullptr);
}

const std::atomic<bool>& InterruptGuard::flag() const { return interruptRequested; }

}  // namespace dropscope
