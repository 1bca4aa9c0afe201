#pragma once
// -q, -v and --log-level, the same on every Photopic program that logs: how much the library's log says
// (core/Log.h) and whether a progress line may be drawn.

#include <string>

namespace CLI {
class App;
}

namespace photopic {

struct Verbosity {
    bool quiet = false;   ///< -q: errors only, no progress line
    bool verbose = false; ///< -v: debug messages too
    std::string level;    ///< --log-level NAME: debug, info, warning or error; empty: info
};

/// Adds -q/--quiet, -v/--verbose and --log-level to `app`.
void addVerbosityOptions(CLI::App& app, Verbosity& verbosity);

/// Sets the library's log level from the options.
void applyVerbosity(const Verbosity& verbosity);

} // namespace photopic
