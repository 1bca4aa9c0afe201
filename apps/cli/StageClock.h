#pragma once
// Where a `photopic image` run's time goes, frame by frame (StageClock).

#include <chrono>
#include <cstddef>
#include <vector>

namespace photopic::cli {

/// Where a sequence run's main thread spends each frame, and how long each frame's decode took on the thread
/// that decoded it, printed at the debug level (-v) once the run ends: the medians tell a user (and the
/// CLI's throughput work) whether decode, the upload, the GPU, the read-back or the PNG encode bounds the
/// rate.
class StageClock {
public:
    enum Stage { DecodeWait, Upload, Process, ReadBack, WriteWait, Decode, kStages };

    StageClock()
        : mLast(std::chrono::steady_clock::now())
        , mBegin(mLast) {}

    /// Charges the time since the last mark to `stage`.
    void mark(Stage stage) {
        const auto now = std::chrono::steady_clock::now();
        mSamples[stage].push_back(std::chrono::duration<double, std::milli>(now - mLast).count());
        mLast = now;
    }

    /// A time measured elsewhere (`Decode`: on the thread that decoded the frame).
    void add(Stage stage, double ms) { mSamples[stage].push_back(ms); }

    /// Restarts the clock without charging anything (the set-up before the first frame).
    void restart(const char* what);

    /// The medians at the debug level (-v), once the run of `frames` frames ends.
    void report(std::size_t frames) const;

private:
    std::chrono::steady_clock::time_point mLast;
    std::chrono::steady_clock::time_point mBegin;
    std::vector<double> mSamples[kStages];
};

} // namespace photopic::cli
