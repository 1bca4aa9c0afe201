#include "Progress.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace photopic::cli {

namespace {

bool gEnabled = true;

/// Work shorter than this never draws a line: a progress line that flashes past is noise.
constexpr double kQuietSeconds = 1.0;
constexpr double kRedrawSeconds = 0.1;

std::string formatDuration(double seconds) {
    const long s = std::lround(seconds);
    if (s < 60) {
        return fmt::format("{} s", s);
    }
    if (s < 3600) {
        return fmt::format("{} min {:02d} s", s / 60, s % 60);
    }
    return fmt::format("{} h {:02d} min", s / 3600, (s % 3600) / 60);
}

} // namespace

void Progress::setEnabled(bool enabled) {
    gEnabled = enabled;
}

Progress::Progress(std::string label, std::size_t total, std::string unit)
    : mLabel(std::move(label))
    , mUnit(std::move(unit))
    , mTotal(total)
    , mTerminal(gEnabled && isatty(STDERR_FILENO) != 0)
    , mStart(std::chrono::steady_clock::now())
    , mLastDraw(mStart) {}

Progress::~Progress() {
    clear();
}

void Progress::advance(std::size_t count) {
    mDone += count;
    if (!mTerminal) {
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - mStart).count();
    const bool finished = mDone >= mTotal;
    if (elapsed < kQuietSeconds || finished ||
        (mShown && std::chrono::duration<double>(now - mLastDraw).count() < kRedrawSeconds)) {
        if (finished) {
            clear();
        }
        return;
    }
    mLastDraw = now;
    draw();
}

void Progress::draw() {
    const double elapsed = std::chrono::duration<double>(mLastDraw - mStart).count();
    const double rate = elapsed > 0.0 ? double(mDone) / elapsed : 0.0;
    std::string line = fmt::format("{}: {}/{} {}, {:.1f} {}/s", mLabel, mDone, mTotal, mUnit, rate, mUnit);
    if (rate > 0.0 && mDone < mTotal) {
        line += ", ETA " + formatDuration(double(mTotal - mDone) / rate);
    }
    // \r returns to the line's start and \x1b[K erases what a longer earlier line left.
    std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
    std::fflush(stderr);
    mShown = true;
}

void Progress::note(std::string_view text) {
    if (mTerminal) {
        std::fprintf(stderr, "\r%s: %.*s\x1b[K", mLabel.c_str(), int(text.size()), text.data());
        std::fflush(stderr);
        mShown = true;
    }
}

void Progress::clear() {
    if (mShown) {
        std::fputs("\r\x1b[K", stderr);
        std::fflush(stderr);
        mShown = false;
    }
}

} // namespace photopic::cli
