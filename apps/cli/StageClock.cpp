// Where a `photopic image` run's time goes (StageClock.h).
#include "StageClock.h"

#include "Bench.h"

#include "core/Log.h"

#include <fmt/format.h>

#include <string>

namespace photopic::cli {

void StageClock::restart(const char* what) {
    const auto now = std::chrono::steady_clock::now();
    logDebug("image: {} {:.1f} ms", what, std::chrono::duration<double, std::milli>(now - mLast).count());
    mLast = now;
    mBegin = now;
}

void StageClock::report(std::size_t frames) const {
    static constexpr const char* kNames[kStages] = {"waiting for decode", "upload", "process", "read-back",
                                                    "waiting for encode", "decode"};
    std::string line;
    for (int s = 0; s < kStages; ++s) {
        if (mSamples[s].empty()) {
            continue;
        }
        // The decode is timed on the thread that decodes (the main thread only in a serial run).
        line += fmt::format("{}{} {:.2f}",
                            line.empty()  ? ""
                            : s == Decode ? "; "
                                          : ", ",
                            kNames[s], median(mSamples[s]));
    }
    const double total =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mBegin).count();
    logDebug("image: {} frames in {:.1f} ms ({:.2f} ms a frame, the last encodes included); medians per "
             "frame, ms: {} (on the decoding thread)",
             frames, total, frames > 0 ? total / double(frames) : 0.0, line);
}

} // namespace photopic::cli
