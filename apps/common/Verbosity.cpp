#include "common/Verbosity.h"

#include "core/Log.h"

#include <CLI/CLI.hpp>

namespace photopic {

void addVerbosityOptions(CLI::App& app, Verbosity& verbosity) {
    app.add_flag("-q,--quiet", verbosity.quiet,
                 "print only errors and the results: --log-level error, and no progress line");
    app.add_flag("-v,--verbose", verbosity.verbose, "print debug messages too: --log-level debug");
    app.add_option("--log-level", verbosity.level,
                   "the least severe message printed: debug, info (the default), warning or error")
        ->check(CLI::IsMember({"debug", "info", "warning", "error"}));
}

void applyVerbosity(const Verbosity& verbosity) {
    // -q wins over -v, and either over --log-level: a script that asks for quiet gets quiet.
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
