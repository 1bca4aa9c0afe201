#pragma once
// -q, -v and --log-level, the same on every Photopic program that logs: how much the library's log says
// (core/Log.h) and whether a progress line may be drawn. Header-only: the programs that include it link
// CLI11, apps_common does not (a library-only build has no CLI11).

#include "core/Log.h"

#include <CLI/CLI.hpp>

#include <string>

namespace photopic {

struct Verbosity {
    bool quiet = false;   ///< -q: errors only, no progress line
    bool verbose = false; ///< -v: debug messages too
    std::string level;    ///< --log-level NAME: debug, info, warning or error; empty: info
};

/// Adds -q/--quiet, -v/--verbose and --log-level to `app`.
inline void addVerbosityOptions(CLI::App& app, Verbosity& verbosity) {
    app.add_flag("-q,--quiet", verbosity.quiet,
                 "print errors only: --log-level error; no progress line, no line per frame or summary "
                 "(what a command is asked to print, --info or a table, is still printed)");
    app.add_flag("-v,--verbose", verbosity.verbose, "print debug messages too: --log-level debug");
    app.add_option("--log-level", verbosity.level,
                   "the least severe message printed: debug, info (the default), warning or error")
        ->check(CLI::IsMember({"debug", "info", "warning", "error"}));
}

/// Sets the library's log level from the options: -q wins over -v, and either over --log-level (a script
/// that asks for quiet gets quiet, whatever else its command line says).
inline void applyVerbosity(const Verbosity& verbosity) {
    LogLevel level = LogLevel::Info;
    if (verbosity.quiet || (!verbosity.verbose && verbosity.level == "error")) {
        level = LogLevel::Error;
    } else if (verbosity.verbose || verbosity.level == "debug") {
        level = LogLevel::Debug;
    } else if (verbosity.level == "warning") {
        level = LogLevel::Warning;
    }
    setLogLevel(level);
}

} // namespace photopic
