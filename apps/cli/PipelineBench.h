#pragma once
// `photopic bench` on the pipeline: a synthetic HDR frame or --input rendered N times after a warm-up, then
// for every pass the median GPU time, the bytes it moves and the bandwidth that implies against the same
// run's reference copy (CopyReference.h).

#include "Bench.h"
#include "BenchInputs3d.h"
#include "CopyReference.h"
#include "ImageInputs.h"
#include "PassTable.h"
#include "Progress.h"
#include "QueueAhead.h"

#include "gl/Context.h"
#include "pipeline/Pipeline.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace photopic::cli {

class PipelineBench {
public:
    explicit PipelineBench(const BenchOptions& options)
        : mOptions(options) {}
    int run();

private:
    /// The settings, the input, the GL context, the pipeline and the frame's 3D inputs.
    void prepare();
    /// The untimed frames; with --queue-ahead, the busy work calibrated on them.
    void warmUp();
    /// The timed frames, each pass between its own timestamps.
    void timePasses();
    /// The whole frame between one pair of timestamps, the passes' own timers off.
    void timeWholeFrame();
    /// The bandwidth references: the copies and the reduction.
    void measureReferences();
    void printSetup() const;
    void printReferences() const;
    /// The CPU's submission time, the queue's hold, the per-pass table and the whole frame's lines.
    void printTimings();
    /// --json FILE.
    void writeJson() const;
    /// One frame's submission; returns the CPU's milliseconds from beginFrame to execute's return.
    double submitFrame();
    /// "synthetic", or the --input file (mirrored to the frame's size when --size was given).
    [[nodiscard]] std::string inputName() const;
    [[nodiscard]] bool mirrored() const { return !mOptions.input.empty() && mOptions.sizeGiven; }
    /// "file" (an EXR --input's depth, normals, motion and camera) or "synthetic" (BenchInputs3d).
    [[nodiscard]] const char* inputs3dName() const { return mFileTextures ? "file" : "synthetic"; }

    const BenchOptions& mOptions;
    Settings mSettings;
    ImageF mImage;
    std::optional<HeadlessContext> mContext;
    std::unique_ptr<Pipeline> mPipeline;
    std::optional<Texture> mInput;
    std::optional<BenchInputs3d> mInputs3d;
    std::optional<InputTextures> mFileTextures; ///< an EXR --input's 3D layers on the GPU
    FrameInputs mInputs;
    std::uint64_t mFrame = 0;
    std::optional<Progress> mProgress;
    std::unique_ptr<QueueAhead> mAhead;
    std::vector<double> mWarmupSubmitMs;
    std::vector<double> mSubmitMs;
    PassSamples mSamples;
    double mWholeFrameMs = 0;
    double mAsSubmittedMs = 0;
    CopyReference mConstantCopy;
    CopyReference mCopy;
    CopyReference mReduction;
    PassTable mTable;
};

} // namespace photopic::cli
