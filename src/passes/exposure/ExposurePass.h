#pragma once
// Exposure target and adaptation (right after metering; docs/architecture.md): one compute invocation reads
// the frame's metering and updates the GPU exposure state (GpuExposureState) that every later pass reads.
// Same frame, no CPU round trip. With auto exposure off it still runs: it writes exposure = 2^manualEV and
// the histogram statistics a debug view may need.
// Tests: tests/gl/test_autoexposure_gpu.cpp, tests/e2e/autoexposure.sh.

#include "core/settings/AutoExposureSettings.h"
#include "gl/ReadbackRing.h"
#include "passes/FramePass.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace photopic {

/// std140 mirror of exposure_adapt.comp.glsl's parameter block.
struct ExposureParameters {
    /// One uCurve element: std140 pads each vec2 of an array to 16 bytes.
    struct CurvePoint {
        float x = 0.0f;
        float y = 0.0f;
        float padding[2] = {};
    };
    std::int32_t autoEnabled = 0;
    std::int32_t metered = 0;        ///< 1: metering ran for exposure this frame (a reading may exist)
    std::int32_t histogramBuilt = 0; ///< 1: the bins hold this frame's histogram
    std::int32_t meteringMode = 0;   ///< core MeteringMode
    std::int32_t reset = 0;          ///< 1: resetExposure() or resize: the next valid reading snaps
    float dt = 0.0f;
    float manualEV = 0.0f;
    float keyValue = 0.0f;
    float compensationEV = 0.0f;
    float minEV = 0.0f;
    float maxEV = 0.0f;
    float padding0 = 0.0f;
    CurvePoint curve[kMaxCompensationCurvePoints] = {};
    std::int32_t curveCount = 0;
    std::int32_t adaptation = 0;
    float tauBrighten = 0.0f;
    float tauDarken = 0.0f;
    float speedUp = 0.0f;
    float speedDown = 0.0f;
    float transitionEV = 0.0f;
    float deadbandEV = 0.0f;
    float maxDt = 0.0f;
    float log2Min = 0.0f;
    float log2Max = 0.0f;
    float lowPercent = 0.0f;
    float highPercent = 0.0f;
    std::int32_t overrideApplied = 0; ///< 1: overrideLog2 replaces the adapted auto exposure
    float overrideLog2 = 0.0f;        ///< EV
    float padding1 = 0.0f;
};
static_assert(kMaxCompensationCurvePoints == 16, "exposure_adapt.comp.glsl declares uCurve[16]");
static_assert(sizeof(ExposureParameters::CurvePoint) == 16);
static_assert(sizeof(ExposureParameters) == 368);
static_assert(offsetof(ExposureParameters, reset) == 16 && offsetof(ExposureParameters, maxEV) == 40 &&
              offsetof(ExposureParameters, curve) == 48 && offsetof(ExposureParameters, curveCount) == 304 &&
              offsetof(ExposureParameters, maxDt) == 336 &&
              offsetof(ExposureParameters, highPercent) == 352 &&
              offsetof(ExposureParameters, overrideApplied) == 356 &&
              offsetof(ExposureParameters, overrideLog2) == 360);

/// One frame's exposure as the GPU computed it, read back through the ring (never blocking the frame).
struct ExposureTelemetry {
    bool valid = false;         ///< false until the first frame's record has arrived
    std::uint64_t frame = 0;    ///< FrameTime::frameIndex of the frame it came from
    float frameLuminance = 0;   ///< this frame's metered luminance, 0 when it had no reading
    float meteredLuminance = 0; ///< the last valid reading (what the target follows)
    float targetLog2 = 0;       ///< EV, auto exposure's target
    float appliedLog2 = 0;      ///< EV, auto exposure's adapted value
    float exposure = 1;         ///< total multiplier applied to the frame (manual x auto)
    float manualEV = 0;
    bool autoEnabled = false;
    bool adapting = false;
    bool initialized = false;
    float minLuminance = 0; ///< smallest meterable pixel luminance (0 when nothing was metered)
    float maxLuminance = 0;
    std::uint32_t histogramCount = 0; ///< pixels binned (0: no histogram this frame)
    float histogramLowLog2 = 0;       ///< percentile window, bin centres
    float histogramHighLog2 = 0;
    float histogramAverageLog2 = 0;
    std::array<std::uint32_t, 256> histogram{}; ///< this frame's bins (replaced whole, never accumulated)
};

class ExposurePass final : public FramePass {
public:
    struct Inputs {
        const Buffer* histogram = nullptr; ///< MeteringPass output (bins)
        const Buffer* metering = nullptr;  ///< MeteringPass output (header + partials)
        Buffer* exposureState = nullptr;   ///< GpuExposureState, read and written
        const AutoExposureSettings* settings = nullptr;
        bool metered = false;        ///< metering ran for exposure this frame
        bool histogramBuilt = false; ///< the bins hold this frame's histogram
        bool reset = false;          ///< snap to the next valid reading
        float dt = 0.0f;             ///< s, from the caller
        float manualEV = 0.0f;       ///< tonemapping.exposure
        /// EV: the auto exposure planned for this frame (Pipeline::setExposureOverride), applied in place of
        /// the adapted value; the frame is still metered and its target reported.
        std::optional<float> appliedOverride{};
        GpuTimers* timers = nullptr;
    };
    /// `keepHistory`: keep every frame's telemetry until drainTelemetry() (offline sequences); else only the
    /// newest is kept.
    explicit ExposurePass(bool keepHistory = false);
    [[nodiscard]] std::string_view name() const override { return "exposure adaptation"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// Telemetry goes into a readback ring every frame, whether or not anything downstream reads exposure.
    [[nodiscard]] bool hasSideEffects() const override { return true; }
    void execute(FrameContext& ctx, FrameResources& resources) override;
    /// The adaptation kernel alone (benchmarks, tests).
    void execute(const Inputs& in) noexcept;

    /// The GPU exposure state every later pass reads (GpuExposureState).
    [[nodiscard]] const Buffer& state() const { return mState; }
    /// `exposure`: the state as the last frame left it, until this frame's adaptation rewrites it (passes
    /// before metering, TAA, weight with the exposure the frame will most nearly be shown at).
    void publishState(FrameResources& resources) const override {
        resources.bind(Resource::ExposureState, mState);
    }
    /// The newest telemetry that has arrived, without blocking; the last result again when nothing new has
    /// finished (a continuity cache); `valid` is false before the first.
    const ExposureTelemetry& telemetry();
    /// Blocks until every frame in flight has reported; every record not yet drained, oldest first.
    std::vector<ExposureTelemetry> drainTelemetry();
    /// The newest record polled so far, without polling.
    [[nodiscard]] const ExposureTelemetry& lastTelemetry() const { return mTelemetry; }
    [[nodiscard]] std::uint64_t droppedTelemetry() const { return mRing.dropped(); }
    void setTelemetryReadyOverride(std::function<bool()> ready) { mRing.setReadyOverride(std::move(ready)); }

private:
    void pollTelemetry();
    void keep(const ExposureTelemetry& record);

    Program mProgram;
    ParameterBlock<ExposureParameters> mParameters;
    Buffer mState;
    Buffer mRecord; ///< GpuExposureState + bins, copied on the GPU, then into the ring
    ReadbackRing mRing;
    ExposureTelemetry mTelemetry;
    std::deque<ExposureTelemetry> mHistory;
    bool mKeepHistory = false;
    /// The state buffer and manual EV (its bits) of the last dispatch that metered nothing with auto exposure
    /// off and no reset: such a dispatch writes a state that depends on the manual EV alone, so the next one
    /// with the same EV on the same buffer would write what the buffer holds, and is skipped.
    GLuint mIdleBuffer = 0;
    std::uint32_t mIdleManualEvBits = 0;
};

} // namespace photopic
