#include "passes/exposure/ExposurePass.h"

#include "core/Log.h"
#include "core/PhysicalExposure.h"
#include "passes/Bindings.h"
#include "passes/metering/MeteringPass.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <span>

namespace photopic {

namespace {

/// Readback slots: deep enough that a host polling once a frame never drops a frame on a GPU a few frames
/// behind.
constexpr int kTelemetrySlots = 16;
constexpr std::size_t kTelemetryBytes = sizeof(GpuExposureState) + kGpuHistogramBytes;

ExposureTelemetry decodeTelemetry(std::uint64_t frame, std::span<const std::byte> bytes) {
    GpuExposureState s;
    std::memcpy(&s, bytes.data(), sizeof(s));
    ExposureTelemetry t;
    t.valid = true;
    t.frame = frame;
    t.frameLuminance = s.frameLuminance;
    t.meteredLuminance = s.meteredLuminance;
    t.targetLog2 = s.targetLog2;
    t.appliedLog2 = s.appliedLog2;
    t.exposure = s.exposure;
    t.manualEV = s.manualEV;
    t.autoEnabled = s.autoEnabled != 0;
    t.adapting = s.adapting != 0;
    t.initialized = s.initialized != 0;
    t.minLuminance = s.minLuminance;
    t.maxLuminance = s.maxLuminance;
    t.histogramCount = s.histogramCount;
    t.histogramLowLog2 = s.histogramLowLog2;
    t.histogramHighLog2 = s.histogramHighLog2;
    t.histogramAverageLog2 = s.histogramAverageLog2;
    std::memcpy(t.histogram.data(), bytes.data() + sizeof(GpuExposureState), kGpuHistogramBytes);
    return t;
}

const GpuExposureState kInitialState{};

} // namespace

ExposurePass::ExposurePass(bool keepHistory)
    : mProgram(makeComputeProgram("passes/exposure/exposure_adapt.comp.glsl", bindingDefines()))
    , mParameters("exposure parameters")
    , mState({.size = sizeof(GpuExposureState),
              .flags = GL_DYNAMIC_STORAGE_BIT,
              .data = &kInitialState,
              .debugName = "exposure state"})
    , mRecord({.size = kTelemetryBytes, .flags = 0, .data = nullptr, .debugName = "exposure telemetry"})
    , mRing(kTelemetryBytes, kTelemetrySlots, "exposure telemetry")
    , mKeepHistory(keepHistory) {}

std::span<const ResourceUse> ExposurePass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::Histogram, Access::Read},
                                            {Resource::Metering, Access::Read},
                                            {Resource::ExposureState, Access::Write}};
    return kUses;
}

void ExposurePass::execute(FrameContext& ctx, FrameResources& resources) {
    const Buffer& histogram = *resources.buffer(Resource::Histogram);
    // exposure.mode = physical: the camera's EV100 joins the manual EV and auto exposure becomes a correction
    // around it (core/PhysicalExposure.h); without a camera the frame stays manual.
    PhysicalExposureInputs exposure{*ctx.autoExposure, ctx.settings.tonemapping.exposure};
    if (ctx.settings.exposure.mode == ExposureMode::Physical) {
        if (ctx.inputs.camera != nullptr && resources.has(Resource::Camera)) {
            exposure = physicalExposure(*ctx.autoExposure, ctx.settings.tonemapping.exposure,
                                        ctx.inputs.camera->lens, ctx.time.dt);
        } else {
            try {
                warnOnce("exposure.physical.camera",
                         "exposure.mode is physical but the frame has no camera: manual exposure");
            } catch (...) { // logging must not take the frame down
            }
        }
    }
    execute({.histogram = &histogram,
             .metering = resources.buffer(Resource::Metering),
             .exposureState = &mState,
             .settings = &exposure.autoExposure,
             .metered = MeteringPass::metered(ctx.settings, mKeepHistory),
             .histogramBuilt = MeteringPass::histogramWanted(ctx.settings, mKeepHistory),
             .reset = ctx.resetExposure,
             .dt = ctx.time.dt,
             .manualEV = exposure.manualEV,
             .appliedOverride = ctx.exposureOverrideLog2,
             .timers = ctx.timers});
    resources.bind(Resource::ExposureState, mState);

    // Telemetry: the state and the bins into one record, on the GPU, then into the ring (never waited on).
    glCopyNamedBufferSubData(mState.id(), mRecord.id(), 0, 0, sizeof(GpuExposureState));
    glCopyNamedBufferSubData(histogram.id(), mRecord.id(), 0, sizeof(GpuExposureState),
                             GLsizeiptr(kGpuHistogramBytes));
    pollTelemetry(); // frees finished slots first
    if (mKeepHistory && mRing.full()) {
        // Every frame's record is wanted (a telemetry file, a test): when the CPU runs a whole ring ahead of
        // the GPU (a GPU does; a software renderer finishes each frame as it is flushed), wait for the frames
        // in flight rather than drop this one.
        for (const auto& r : mRing.drain()) {
            keep(decodeTelemetry(r.tag, r.bytes));
        }
    }
    mRing.enqueue(mRecord, 0, ctx.time.frameIndex);
}

void ExposurePass::keep(const ExposureTelemetry& record) {
    mTelemetry = record;
    if (mKeepHistory) {
        mHistory.push_back(record);
    }
}

void ExposurePass::pollTelemetry() {
    if (mKeepHistory) {
        for (const auto& r : mRing.pollAll()) {
            keep(decodeTelemetry(r.tag, r.bytes));
        }
    } else if (const auto r = mRing.pollNewest()) {
        keep(decodeTelemetry(r->tag, r->bytes));
    }
}

const ExposureTelemetry& ExposurePass::telemetry() {
    pollTelemetry();
    return mTelemetry;
}

std::vector<ExposureTelemetry> ExposurePass::drainTelemetry() {
    pollTelemetry();
    for (const auto& r : mRing.drain()) {
        const ExposureTelemetry t = decodeTelemetry(r.tag, r.bytes);
        mTelemetry = t;
        mHistory.push_back(t);
    }
    std::vector<ExposureTelemetry> out(mHistory.begin(), mHistory.end());
    mHistory.clear();
    return out;
}

namespace {

/// The adaptation kernel's parameter block for `in`.
ExposureParameters adaptationParameters(const ExposurePass::Inputs& in) noexcept {
    const AutoExposureSettings& s = *in.settings;
    // Settings validation caps the curve at kMaxCompensationCurvePoints; the clamp keeps an unvalidated
    // struct from overrunning the shader's array.
    const std::size_t curveCount = std::min(s.compensationCurve.size(), kMaxCompensationCurvePoints);
    ExposureParameters parameters{.autoEnabled = s.enabled ? 1 : 0,
                                  .metered = in.metered ? 1 : 0,
                                  .histogramBuilt = in.histogramBuilt ? 1 : 0,
                                  .meteringMode = int(s.metering),
                                  .reset = in.reset ? 1 : 0,
                                  .dt = in.dt,
                                  .manualEV = in.manualEV,
                                  .keyValue = s.keyValue,
                                  .compensationEV = s.compensationEV,
                                  .minEV = s.minEV,
                                  .maxEV = s.maxEV,
                                  .curveCount = int(curveCount),
                                  .adaptation = int(s.adaptation),
                                  .tauBrighten = s.tauBrighten,
                                  .tauDarken = s.tauDarken,
                                  .speedUp = s.speedUp,
                                  .speedDown = s.speedDown,
                                  .transitionEV = s.transitionEV,
                                  .deadbandEV = s.deadbandEV,
                                  .maxDt = s.maxDt,
                                  .log2Min = s.histogramLog2Min,
                                  .log2Max = s.histogramLog2Max,
                                  .lowPercent = s.lowPercent,
                                  .highPercent = s.highPercent,
                                  .overrideApplied = in.appliedOverride ? 1 : 0,
                                  .overrideLog2 = in.appliedOverride.value_or(0.0f)};
    for (std::size_t i = 0; i < curveCount; ++i) {
        parameters.curve[i].x = s.compensationCurve[i].x;
        parameters.curve[i].y = s.compensationCurve[i].y;
    }
    return parameters;
}

} // namespace

void ExposurePass::execute(const Inputs& in) noexcept {
    DebugGroup group("exposure adaptation");
    const AutoExposureSettings& s = *in.settings;
    // Auto exposure off, nothing metered, no reset: the kernel writes the manual exposure and zeros, from the
    // manual EV alone. When the last dispatch was such a frame on this buffer with this EV, the buffer
    // already holds what this one would write, and the dispatch is skipped (the bracket stays, empty, for the
    // timings' table).
    const bool idle = !s.enabled && !in.metered && !in.histogramBuilt && !in.reset && !in.appliedOverride;
    const std::uint32_t evBits = std::bit_cast<std::uint32_t>(in.manualEV);
    const bool unchanged = idle && mIdleBuffer == in.exposureState->id() && mIdleManualEvBits == evBits;
    ScopedGpuTimer timer(in.timers, "exposure adaptation",
                         unchanged ? 0.0 : double(sizeof(GpuExposureState)) * 2 + 1024);
    if (unchanged) {
        return;
    }
    mIdleBuffer = idle ? in.exposureState->id() : 0;
    mIdleManualEvBits = evBits;
    mParameters.update(adaptationParameters(in));
    mParameters.bind(kBindingParameters);

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingHistogram, in.histogram->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingMetering, in.metering->id());
    mProgram.use();
    // Later passes read the state as a uniform block (bindExposureStateForReading), the next frame's
    // adaptation as a storage buffer; the readback copies it.
    dispatch(mProgram, Groups{}, Barrier::StorageAsUniform);
}

} // namespace photopic
