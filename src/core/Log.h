#pragma once
// One log for the library: a sink the host may replace (default: stderr), and warnOnce for degradations that
// must be visible but not repeated every frame (a missing capability is logged once, never silent).

#include <fmt/format.h>

#include <functional>
#include <string>
#include <string_view>

namespace photopic {

enum class LogLevel { Debug, Info, Warning, Error };

using LogSink = std::function<void(LogLevel, std::string_view)>;

/// Replaces the sink (nullptr restores stderr). Returns the previous one.
LogSink setLogSink(LogSink sink);
/// Messages below this level are dropped (default Info).
void setLogLevel(LogLevel level);
void logMessage(LogLevel level, std::string_view message);
/// Logs `message` at Warning the first time `key` is seen in this process, never again.
void warnOnce(std::string_view key, std::string_view message);

template <class... Args>
void logDebug(fmt::format_string<Args...> f, Args&&... args) {
    logMessage(LogLevel::Debug, fmt::format(f, std::forward<Args>(args)...));
}
template <class... Args>
void logInfo(fmt::format_string<Args...> f, Args&&... args) {
    logMessage(LogLevel::Info, fmt::format(f, std::forward<Args>(args)...));
}
template <class... Args>
void logWarning(fmt::format_string<Args...> f, Args&&... args) {
    logMessage(LogLevel::Warning, fmt::format(f, std::forward<Args>(args)...));
}
template <class... Args>
void logError(fmt::format_string<Args...> f, Args&&... args) {
    logMessage(LogLevel::Error, fmt::format(f, std::forward<Args>(args)...));
}

} // namespace photopic

/// Internal invariant check: on failure logs the condition and location, then aborts. Not for user input.
#define PHOTOPIC_ASSERT(cond)                                                                                \
    do {                                                                                                     \
        if (!(cond)) {                                                                                       \
            ::photopic::detail::assertFailed(#cond, __FILE__, __LINE__);                                     \
        }                                                                                                    \
    } while (false)

namespace photopic::detail {
[[noreturn]] void assertFailed(const char* cond, const char* file, int line);
}
