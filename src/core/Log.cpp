#include "core/Log.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <set>
#include <utility>

namespace photopic {

namespace {

std::mutex gMutex;
LogSink gSink;
LogLevel gLevel = LogLevel::Info;
std::set<std::string, std::less<>> gWarned;

std::string_view levelName(LogLevel level) {
    switch (level) {
    case LogLevel::Debug:
        return "debug";
    case LogLevel::Info:
        return "info";
    case LogLevel::Warning:
        return "warning";
    case LogLevel::Error:
        return "error";
    }
    return "";
}

} // namespace

LogSink setLogSink(LogSink sink) {
    std::lock_guard lock(gMutex);
    return std::exchange(gSink, std::move(sink));
}

void setLogLevel(LogLevel level) {
    std::lock_guard lock(gMutex);
    gLevel = level;
}

void logMessage(LogLevel level, std::string_view message) {
    LogSink sink;
    {
        std::lock_guard lock(gMutex);
        if (level < gLevel) {
            return;
        }
        sink = gSink;
    }
    if (sink) {
        sink(level, message);
    } else {
        std::fprintf(stderr, "photopic %.*s: %.*s\n", int(levelName(level).size()), levelName(level).data(),
                     int(message.size()), message.data());
    }
}

void warnOnce(std::string_view key, std::string_view message) {
    {
        std::lock_guard lock(gMutex);
        if (!gWarned.emplace(key).second) {
            return;
        }
    }
    logMessage(LogLevel::Warning, message);
}

namespace detail {
void assertFailed(const char* cond, const char* file, int line) {
    std::fprintf(stderr, "photopic: internal assertion failed: %s at %s:%d\n", cond, file, line);
    std::abort();
}
} // namespace detail

} // namespace photopic
