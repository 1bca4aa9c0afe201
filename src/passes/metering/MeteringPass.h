#pragma once
// Metering (frame order: docs/architecture.md): reads the sanitised HDR image before exposure and leaves, on
// the GPU, the 256-bin histogram, the frame's min/max meterable luminance and the weighted geometric mean
// that the adaptation pass (passes/exposure/) turns into exposure. Nothing is read back here.
// Tests: tests/gl/test_metering_gpu.cpp, tests/gl/test_autoexposure_gpu.cpp.

#include "core/settings/AutoExposureSettings.h"
#include "passes/FramePass.h"

#include <array>

#include <cstddef>
#include <cstdint>
#include <string>

namespace photopic {

/// std140 mirror of metering.comp.glsl's parameter block.
struct MeteringParameters {
    std::int32_t buildHistogram = 0; ///< 1: bin every pixel
    std::int32_t weights = -1;       ///< -1: no weighted mean; else kMeterAverage, kMeterCenter or kMeterMask
    float log2Min = 0.0f;
    float log2Max = 0.0f;
};
static_assert(sizeof(MeteringParameters) == 16);
static_assert(offsetof(MeteringParameters, weights) == 4 && offsetof(MeteringParameters, log2Min) == 8 &&
              offsetof(MeteringParameters, log2Max) == 12);

/// std140 mirror of metering_reduce.comp.glsl's parameter block.
struct MeteringReduceParameters {
    std::int32_t spot = 0;          ///< 1: meter the spot taps instead of the partials
    std::int32_t groups = 0;        ///< partials written by the metering dispatch
    float spotUv[2] = {0.5f, 0.5f}; ///< image UV, v down
    float spotRadius = 0.0f;
    std::int32_t spotTaps = 0;
    std::int32_t rowsPerGroup = 1; ///< partials per block: 1 (histogram shader) or 16 (row shader)
    std::int32_t padding = 0;
};
static_assert(sizeof(MeteringReduceParameters) == 32);
static_assert(offsetof(MeteringReduceParameters, groups) == 4 &&
              offsetof(MeteringReduceParameters, spotUv) == 8 &&
              offsetof(MeteringReduceParameters, spotRadius) == 16 &&
              offsetof(MeteringReduceParameters, spotTaps) == 20 &&
              offsetof(MeteringReduceParameters, rowsPerGroup) == 24);

class MeteringPass final : public FramePass {
public:
    /// Which weighted mean the pass computes (core/Metering.h). `None` skips it (histogram metering, or auto
    /// exposure off with only the histogram wanted by a debug view).
    enum class Weights { None, Average, Spot, Center, Mask };

    struct Inputs {
        const Texture* scene = nullptr; ///< sanitised HDR colour (any float format)
        const Texture* mask = nullptr;  ///< grey weight image for Weights::Mask (required then)
        const AutoExposureSettings* settings = nullptr;
        bool histogram = false; ///< bin every pixel this frame
        Weights weights = Weights::None;
        /// The frame computes a reading (MeteringPass::metered): the subject probe may write one into the
        /// header after this pass. A frame with nothing metered, no reading and no histogram leaves the
        /// buffers as it found them, so one after another clears them only once.
        bool metered = true;
        GpuTimers* timers = nullptr;
    };
    struct Outputs {
        const Buffer* histogram = nullptr; ///< 256 uint bins, cleared and filled this frame
        const Buffer* metering = nullptr;  ///< GpuMeteringHeader + partials
    };

    MeteringPass();
    /// Which shader computes the weighted mean (see mRowsWithoutHistogram; with a histogram too, the row
    /// shader runs beside the histogram kernel); tests run both.
    void setRowShaderWithoutHistogram(bool rows) { mRowsWithoutHistogram = rows; }
    [[nodiscard]] std::string_view name() const override { return "metering"; }
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// Loads the mask image that `autoExposure.mask.path` names (throws IoError naming the file).
    void configure(const Settings& settings) override;
    /// Sizes the partial-sum buffer for `extent` (one vec2 per row of each 16x16 block).
    void resize(Extent extent) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// The histogram is built when exposure or a debug view needs it (the histogram view works with auto
    /// exposure off). The exposure pass asks the same question to know whether the bins are this frame's.
    /// `forTelemetry`: the host keeps every frame's telemetry, so the frame is metered in the configured mode
    /// even with auto exposure off (the readings are reported; exposure stays manual).
    [[nodiscard]] static bool histogramWanted(const Settings& settings, bool forTelemetry = false) noexcept;
    /// Whether the frame computes a reading for exposure (auto exposure on, or telemetry wanted).
    [[nodiscard]] static bool metered(const Settings& settings, bool forTelemetry) noexcept {
        return settings.autoExposure.enabled || forTelemetry;
    }
    /// Meter every frame in the configured mode even with auto exposure off (a host that keeps every
    /// frame's telemetry: the CLI's --telemetry).
    void setMeterForTelemetry(bool meter) { mMeterForTelemetry = meter; }
    [[nodiscard]] bool metersForTelemetry() const { return mMeterForTelemetry; }
    /// The weighted mean this frame's settings ask for when the frame is `metered` (see metered()); the
    /// subject probe writes its own reading.
    [[nodiscard]] static Weights weightsFor(const AutoExposureSettings& ae, bool metered,
                                            bool haveMask) noexcept;

    /// Clears the bins and the min/max, then meters: nothing more when neither a histogram nor a mean is
    /// wanted, else one metering dispatch plus, for a mean, one reduction dispatch. Without a histogram the
    /// metering dispatch is the barrier-free row shader, which gives the same reading bit for bit.
    Outputs execute(const Inputs& in) noexcept;
    [[nodiscard]] Outputs outputs() const { return {&mHistogram, &mMetering}; }

    static constexpr int kGroupSize = 16;
    /// Pixels each invocation of the histogram-only kernel bins (metering_histogram.comp.glsl's RUN).
    static constexpr int kHistogramRun = 8;

private:
    /// Clears the bins and the header unless they hold their cleared state and this frame writes nothing.
    void clear(bool idle);
    /// The histogram and partial-sum dispatches; returns the rows a partial sum covers.
    int meter(const Inputs& in, int weightsIndex);
    /// The reduction of the partial sums to the reading.
    void reduce(const Inputs& in, int rowsPerGroup);

    Program mMeter;
    /// No histogram: one invocation per block row, no barriers; one variant per weighting (WEIGHTS: -1 none,
    /// or the mode's index), since a CPU rasteriser computes every weight a uniform branch could choose.
    std::array<Program, 4> mMeterRows;
    /// The histogram and the extremes without a weighted mean: runs of pixels per invocation, the same bins
    /// and extremes as mMeter (metering_histogram.comp.glsl).
    Program mMeterHistogram;
    Program mReduce;
    /// The scene and the mask: every metering program that reads one declares it on the same unit.
    SamplerSlot mScene = mMeter.sampler("uScene");
    SamplerSlot mMaskSlot = mMeter.sampler("uMask");
    ParameterBlock<MeteringParameters> mMeterParameters;
    ParameterBlock<MeteringReduceParameters> mReduceParameters;
    Buffer mHistogram;
    Buffer mMetering;
    Buffer mMeteringReset; ///< the header each frame starts from (copied on the GPU)
    /// The row shader for the weighted mean (beside the histogram kernel when a histogram is wanted too), on
    /// a software renderer only: it and the block shader give the same reading bit for bit, but a software
    /// renderer pays for the block shader's workgroup barriers in CPU time, while a GPU pays for the row
    /// shader's uncoalesced reads (the figures are in docs/bench/LOG.md).
    bool mRowsWithoutHistogram = false;
    bool mMeterForTelemetry = false;
    /// The bins and the header hold their cleared state and nothing has written them since (the last frame
    /// metered nothing and had no reading): the next such frame need not clear them again.
    bool mCleared = false;
    Texture mMask;
    std::string mMaskPath;
    Extent mExtent;
    int mGroupsX = 0;
    int mGroupsY = 0;
};

} // namespace photopic
