#pragma once
// How the bench times GPU work: `--queue-ahead`'s busy work (QueueAhead), one timed run (timedRun) and the
// median of many (medianTimed).

#include "Bench.h"

#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <vector>

namespace photopic::cli {

/// `--queue-ahead`: untimed GPU work (gl/gpu_busy.comp.glsl) submitted before each timed frame and lasting
/// longer than the CPU takes to submit the frame, so the GPU reaches the frame with all of its commands
/// queued and the frame's timestamps hold the GPU's own work, not the gaps where it waited for the CPU (a
/// frame submitted to an idle GPU runs as fast as the CPU hands it over). Whether that held is checked on
/// every timed frame: the GPU clock when the CPU had submitted the whole frame
/// (glGetInteger64v(GL_TIMESTAMP), which waits for nothing) must be earlier than the busy work's end
/// timestamp.
class QueueAhead {
public:
    QueueAhead();

    /// Lengthens the busy work until one run, submitted and waited for, takes at least `ms` of wall time (at
    /// most kMaxMs): it must outlast the CPU's submission of a frame, which runs on the wall clock. Each step
    /// aims a quarter past the target, so the last run stays under 1.25 times it. The chain grows to
    /// kMaxIterations, then the number of groups (Mesa's llvmpipe ends a shader loop after 65535 iterations).
    void calibrate(double ms);
    /// The busy work and a timestamp at its end, after a barrier (so the frame's first pass cannot overlap
    /// it), then a flush (so the GPU starts on it while the CPU submits the frame).
    void submit();
    /// Right after the CPU has submitted the timed work.
    void markSubmitted() { glGetInteger64v(GL_TIMESTAMP, &mSubmittedAt); }
    /// After the timed work has finished on the GPU: counts whether the GPU was still on the busy work when
    /// the CPU had submitted it.
    void settle();
    [[nodiscard]] double busyMs() const { return mBusyMs; }
    [[nodiscard]] int held() const { return mHeld; }
    [[nodiscard]] int timed() const { return mTimed; }

private:
    static constexpr std::size_t kInvocations = 64; // one group's (gl/gpu_busy.comp.glsl)
    static constexpr double kMaxMs = 40.0;
    static constexpr GLuint kMaxIterations = 65535;
    static constexpr GLuint kMaxGroups = 1u << 20;
    Program mProgram;
    Buffer mSink;
    Query mEnd;
    GLuint mIterations = 4096;
    GLuint mGroups = 1;
    double mBusyMs = 0;
    GLint64 mSubmittedAt = -1;
    int mHeld = 0, mTimed = 0;
};

/// One timed run: `submit` issues the timed work (behind the busy work, with `ahead`), `collect` takes its
/// results once the GPU has done it; with `ahead`, whether the queue stayed ahead is counted.
template <class Submit, class Collect>
void timedRun(QueueAhead* ahead, Submit&& submit, Collect&& collect) {
    if (ahead) {
        ahead->submit();
    }
    submit();
    if (ahead) {
        ahead->markSubmitted();
    }
    collect();
    if (ahead) {
        ahead->settle();
    }
}

/// The median time of `work` over `frames` runs, each between one pair of GPU timestamps collected before the
/// next run (the wall time around it with --sync); `afterEach` runs between runs, outside the timestamps.
/// With `ahead`, its busy work precedes each run, outside the timestamps (timedRun).
template <class Work, class AfterEach>
double medianTimed(const BenchOptions& options, QueueAhead* ahead, Work&& work, AfterEach&& afterEach) {
    GpuTimers timers;
    timers.setSynchronous(options.sync);
    std::vector<double> ms;
    for (int i = 0; i < options.frames; ++i) {
        timedRun(
            ahead,
            [&] {
                timers.beginFrame();
                {
                    ScopedGpuTimer timer(&timers, "timed");
                    work();
                }
                timers.endFrame();
            },
            [&] {
                for (const auto& frame : timers.drain()) {
                    for (const PassTiming& t : frame) {
                        ms.push_back(options.sync ? t.wallMs : t.gpuMs);
                    }
                }
            });
        afterEach();
    }
    return median(ms);
}

} // namespace photopic::cli
