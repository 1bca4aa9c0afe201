#pragma once
// The entry point the e2e fixtures share: a fixture takes a fixed number of arguments, prints its usage and
// exits 2 when given any other number, and reports an exception (an unreadable file, a malformed image) as
// its message and exit 1, so the script that runs it fails with the reason.

#include <cstdio>
#include <exception>

namespace photopic::test {

/// Runs `run()` (the fixture's exit status) when argv holds exactly `arguments` arguments after the program
/// name.
template <typename Run>
int fixtureMain(int argc, char** argv, int arguments, const char* usage, Run&& run) {
    if (argc != arguments + 1) {
        std::fprintf(stderr, "usage: %s %s\n", argv[0], usage);
        return 2;
    }
    try {
        return run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}

} // namespace photopic::test
