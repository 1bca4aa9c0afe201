#pragma once
// SIGINT, SIGTERM and SIGHUP during a run: the handler only notes the signal; the frame loops check it
// between frames (throwIfInterrupted) and unwind like a failure, so the frame in flight is dropped, every
// temporary is removed and the run's outputs are taken back by the same rule as a failed run. A second
// signal of the same kind ends the process at once.

#include <csignal>

namespace photopic::cli {

/// Thrown by throwIfInterrupted. Not a std::exception, so that no handler of errors turns it into another
/// exit status on the way up: main() catches it and exits with 128 + the signal's number.
struct Interrupted {
    int signal = 0;
};

/// Installs the handlers for as long as it lives (a run that writes outputs holds one; RunOutputs does), and
/// puts the previous ones back after. A signal outside such a run has its default action; a signal the
/// process was started with ignored (nohup's SIGHUP, a background job's SIGINT) stays ignored.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;

private:
    struct sigaction mPrevious[3]; ///< SIGINT, SIGTERM, SIGHUP as they were
};
/// The signal received so far, or 0.
[[nodiscard]] int pendingInterrupt();
/// Throws Interrupted when a signal has been received.
void throwIfInterrupted();
/// "SIGTERM" for a message.
[[nodiscard]] const char* signalName(int signal);

} // namespace photopic::cli
