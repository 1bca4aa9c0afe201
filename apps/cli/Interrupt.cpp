#include "Interrupt.h"

#include <csignal>
#include <iterator>
#include <type_traits>

namespace photopic::cli {

namespace {

volatile std::sig_atomic_t gSignal = 0;

extern "C" void noteSignal(int signal) {
    if (gSignal == signal) {
        // Asked twice: the default action (the process ends now, its outputs as they stand).
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    gSignal = signal;
}

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

} // namespace

InterruptScope::InterruptScope()
    : mPrevious{} {
    static_assert(std::size(kSignals) == std::extent_v<decltype(mPrevious)>);
    struct sigaction action {};
    action.sa_handler = noteSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART; // reads and writes in progress complete; the loops look between frames
    for (std::size_t i = 0; i < std::size(kSignals); ++i) {
        sigaction(kSignals[i], nullptr, &mPrevious[i]);
        // A signal the parent ignores stays ignored: SIGHUP under nohup, SIGINT for a shell's background job.
        if (mPrevious[i].sa_handler != SIG_IGN) {
            sigaction(kSignals[i], &action, nullptr);
        }
    }
}

InterruptScope::~InterruptScope() {
    for (std::size_t i = 0; i < std::size(kSignals); ++i) {
        sigaction(kSignals[i], &mPrevious[i], nullptr);
    }
}

int pendingInterrupt() {
    return gSignal;
}

void throwIfInterrupted() {
    if (const int signal = gSignal; signal != 0) {
        throw Interrupted{signal};
    }
}

const char* signalName(int signal) {
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    case SIGHUP:
        return "SIGHUP";
    default:
        return "a signal";
    }
}

} // namespace photopic::cli
