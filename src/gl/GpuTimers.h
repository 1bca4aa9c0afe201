#pragma once
// N-buffered GPU timestamps around each pass: results are collected frames later, when the driver says they
// are available, so timing never stalls the pipeline.

#include "gl/Objects.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace photopic {

struct PassTiming {
    std::string name;
    double gpuMs = 0;      ///< GPU time between the pass's start and end timestamps
    double bytesMoved = 0; ///< estimated bytes read + written by the pass (formats x sizes)
    double wallMs = -1; ///< synchronous mode only: glFinish-bracketed wall time of the pass (-1: not taken)
};

class GpuTimers {
public:
    static constexpr int kFramesInFlight = 4;

    GpuTimers() = default;
    /// Starts a frame: harvests the oldest frame's queries if they are available (never waits).
    void beginFrame();
    /// Brackets one pass. Passes must not nest. `bytesMoved` is the pass's estimated traffic.
    void begin(std::string_view name, double bytesMoved = 0);
    void end();
    void endFrame();

    /// Debug/benchmark mode: every begin() and end() also calls glFinish() and reads a steady clock, so each
    /// pass gets a wall time that holds all of its work and none of its predecessors'. Stalls every pass: a
    /// measurement tool for drivers whose timestamps miss deferred work (Mesa llvmpipe runs a draw when its
    /// scene is flushed, possibly after the pass's end timestamp), never for a frame loop.
    void setSynchronous(bool synchronous) { mSynchronous = synchronous; }
    /// Off: beginFrame() opens nothing and every begin()/end() is a no-op, so a frame issues no timestamp of
    /// its own (a benchmark that brackets whole frames with its own timers measures the frame without them).
    void setEnabled(bool enabled) { mEnabled = enabled; }
    [[nodiscard]] bool synchronous() const { return mSynchronous; }

    /// The most recent frame whose results have arrived (empty until one has).
    [[nodiscard]] const std::vector<PassTiming>& latest() const { return mLatest; }
    /// Frame number (0-based count of endFrame calls) `latest()` belongs to, or -1.
    [[nodiscard]] std::int64_t latestFrame() const { return mLatestFrame; }
    /// Blocks until every outstanding frame has reported (benchmarks and tests only), returning each frame's
    /// passes: at most the newest kKeptFrames since the last drain, so a frame loop that never drains holds
    /// a bounded amount, however long it runs.
    std::vector<std::vector<PassTiming>> drain();
    /// The frames whose results have arrived since the last drain() or collect(), oldest first; never waits
    /// (a frame still in flight comes in a later call).
    std::vector<std::vector<PassTiming>> collect();
    static constexpr std::size_t kKeptFrames = 256;

private:
    struct Slot {
        std::vector<Query> starts, ends;
        std::vector<std::string> names;
        std::vector<double> bytes;
        std::vector<double> wallMs;
        int used = 0;
        std::int64_t frame = -1;
        bool pending = false;
    };
    bool harvest(Slot& slot, bool wait);
    Query& queryAt(std::vector<Query>& queries, int index);

    std::array<Slot, kFramesInFlight> mSlots;
    int mCurrent = 0;
    std::int64_t mFrameCounter = 0;
    bool mOpen = false;
    bool mSynchronous = false;
    bool mEnabled = true;
    std::chrono::steady_clock::time_point mWallStart;
    std::vector<PassTiming> mLatest;
    std::int64_t mLatestFrame = -1;
    std::vector<std::vector<PassTiming>> mHarvested;
};

/// Scoped begin/end on a possibly-null timer set.
class ScopedGpuTimer {
public:
    ScopedGpuTimer(GpuTimers* timers, std::string_view name, double bytesMoved = 0)
        : mTimers(timers) {
        if (mTimers) {
            mTimers->begin(name, bytesMoved);
        }
    }
    ~ScopedGpuTimer() {
        if (mTimers) {
            mTimers->end();
        }
    }
    ScopedGpuTimer(const ScopedGpuTimer&) = delete;
    ScopedGpuTimer& operator=(const ScopedGpuTimer&) = delete;

private:
    GpuTimers* mTimers;
};

} // namespace photopic
