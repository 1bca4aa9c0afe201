#include "pipeline/Pipeline.h"

#include "core/Log.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "passes/Bindings.h"
#include "passes/debug/DebugViewPass.h"
#include "passes/exposure/ExposurePass.h"
#include "passes/metering/MeteringPass.h"
#include "passes/sanitize/SanitizePass.h"
#include "passes/tonemap/TonemapPass.h"

#include <cmath>
#include <cstring>

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

MeteringPass::Weights meteringWeights(const AutoExposureSettings& ae, bool haveMask) {
    if (!ae.enabled) {
        return MeteringPass::Weights::None;
    }
    switch (ae.metering) {
    case MeteringMode::Average:
        return MeteringPass::Weights::Average;
    case MeteringMode::Histogram:
        return MeteringPass::Weights::None;
    case MeteringMode::Spot:
        return MeteringPass::Weights::Spot;
    case MeteringMode::Center:
        return MeteringPass::Weights::Center;
    case MeteringMode::Mask:
        if (!haveMask) {
            try {
                warnOnce(
                    "metering.mask.missing",
                    "autoExposure.metering is \"mask\" but no mask image is loaded; metering the average");
            } catch (...) { // logging must not take the frame down
            }
            return MeteringPass::Weights::Average;
        }
        return MeteringPass::Weights::Mask;
    }
    return MeteringPass::Weights::Average;
}

} // namespace

struct Pipeline::Passes {
    std::unique_ptr<SanitizePass> sanitize; ///< HDR path only
    MeteringPass metering;
    ExposurePass exposure;
    TonemapPass tonemap;
    DebugViewPass debug;
};

Pipeline::Pipeline(const PipelineCreateInfo& info)
    : mSettings(info.settings)
    , mCaps(detectCapabilities(info.forceLdr))
    , mPasses(std::make_unique<Passes>())
    , mTelemetryRecord(
          {.size = kTelemetryBytes, .flags = 0, .data = nullptr, .debugName = "exposure telemetry"})
    , mRing(kTelemetryBytes, kTelemetrySlots, "exposure telemetry")
    , mKeepHistory(info.keepTelemetryHistory) {
    const GpuExposureState initial;
    mExposureState = Buffer({.size = sizeof(GpuExposureState),
                             .flags = GL_DYNAMIC_STORAGE_BIT,
                             .data = &initial,
                             .debugName = "exposure state"});
    if (mCaps.path == ColorPath::Hdr) {
        mPasses->sanitize = std::make_unique<SanitizePass>();
    }
    loadMask();
}

Pipeline::~Pipeline() = default;

void Pipeline::setSettings(const Settings& settings) {
    mSettings = settings;
    loadMask();
}

void Pipeline::loadMask() {
    const std::string& path = mSettings.autoExposure.mask.path;
    if (path == mMaskPath) {
        return;
    }
    if (path.empty()) {
        mMask = {};
    } else {
        // Set-up boundary: an unreadable mask throws IoError naming the file.
        mMask = makeTexture(readImage(path), "metering mask");
    }
    mMaskPath = path;
}

void Pipeline::resize(Extent extent) {
    if (extent == mExtent) {
        return;
    }
    mExtent = extent;
    if (mPasses->sanitize) {
        mPasses->sanitize->resize(extent);
    }
    mPasses->metering.resize(extent);
    mPasses->tonemap.resize(extent);
    mPasses->debug.resize(extent);
    mResetExposure = true; // DESIGN.md: snap on resize
}

const Texture& Pipeline::execute(const FrameInputs& inputs, const FrameTime& time) {
    resize(inputs.color->extent());
    mTimers.beginFrame();
    const AutoExposureSettings& ae = mSettings.autoExposure;
    const DebugView view = mSettings.debug.view;

    // 1. sanitise (HDR path; the LDR path sanitises inside its single pass)
    const Texture* scene = inputs.color;
    if (mPasses->sanitize) {
        scene = &mPasses->sanitize->execute({.color = inputs.color, .timers = &mTimers});
    }

    // 4. metering and adaptation, on the GPU. The histogram is built when exposure or a debug view needs it
    // (seed 004: the histogram view works with auto exposure off).
    const bool histogram = (ae.enabled && ae.metering == MeteringMode::Histogram) ||
                           view == DebugView::Histogram ||
                           (view == DebugView::Metering && ae.metering == MeteringMode::Histogram);
    const MeteringPass::Weights weights = meteringWeights(ae, mMask.valid());
    const MeteringPass::Outputs metered = mPasses->metering.execute({.scene = scene,
                                                                     .mask = mMask.valid() ? &mMask : nullptr,
                                                                     .settings = &ae,
                                                                     .histogram = histogram,
                                                                     .weights = weights,
                                                                     .timers = &mTimers});
    mPasses->exposure.execute({.histogram = metered.histogram,
                               .metering = metered.metering,
                               .exposureState = &mExposureState,
                               .settings = &ae,
                               .metered = ae.enabled,
                               .histogramBuilt = histogram,
                               .reset = mResetExposure,
                               .dt = time.dt,
                               .manualEV = mSettings.tonemapping.exposure,
                               .timers = &mTimers});
    mResetExposure = false;

    // Telemetry: the state and the bins into one record, on the GPU, then into the ring (never waited on
    // here).
    glCopyNamedBufferSubData(mExposureState.id(), mTelemetryRecord.id(), 0, 0, sizeof(GpuExposureState));
    glCopyNamedBufferSubData(metered.histogram->id(), mTelemetryRecord.id(), 0, sizeof(GpuExposureState),
                             GLsizeiptr(kGpuHistogramBytes));
    pollTelemetry(); // frees finished slots first
    mRing.enqueue(mTelemetryRecord, 0, time.frameIndex);

    const DebugViewPass::Inputs debugInputs{.view = view,
                                            .scene = scene,
                                            .display = nullptr,
                                            .mask = mMask.valid() ? &mMask : nullptr,
                                            .bloom = nullptr,
                                            .exposureState = &mExposureState,
                                            .histogram = metered.histogram,
                                            .autoExposure = &ae,
                                            .timers = &mTimers};
    mLastScene = scene;
    mLastFrame = time.frameIndex;

    // 8. scene-value debug views replace the image and are shown as they are (no tone mapping).
    if (DebugViewPass::isSceneView(view)) {
        const Texture& debug = mPasses->debug.execute(debugInputs);
        mTimers.endFrame();
        return debug;
    }

    // 7 + 9. composite and tone map, once.
    const TonemapPass::Inputs tonemapInputs{.scene = scene,
                                            .exposureState = &mExposureState,
                                            .tonemapping = &mSettings.tonemapping,
                                            .output = &mSettings.output,
                                            .frameIndex = time.frameIndex,
                                            .timers = &mTimers};
    const Texture* display = &mPasses->tonemap.execute(tonemapInputs);

    // 12. overlays.
    if (view == DebugView::Histogram) {
        DebugViewPass::Inputs overlay = debugInputs;
        overlay.display = display;
        display = &mPasses->debug.execute(overlay);
    }
    mTimers.endFrame();
    return *display;
}

void Pipeline::keep(const ExposureTelemetry& record) {
    mTelemetry = record;
    if (mKeepHistory) {
        mHistory.push_back(record);
    }
}

void Pipeline::pollTelemetry() {
    if (mKeepHistory) {
        for (const auto& r : mRing.pollAll()) {
            keep(decodeTelemetry(r.tag, r.bytes));
        }
    } else if (const auto r = mRing.pollNewest()) {
        keep(decodeTelemetry(r->tag, r->bytes));
    }
}

const ExposureTelemetry& Pipeline::telemetry() {
    pollTelemetry();
    return mTelemetry;
}

std::vector<ExposureTelemetry> Pipeline::drainTelemetry() {
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

const Texture& Pipeline::sceneReferred() {
    if (!mCaps.rgba32fRenderable) {
        throw GlError("the scene-referred (EXR) output needs RGBA32F render targets, which this GPU lacks");
    }
    return mPasses->tonemap.renderScene({.scene = mLastScene,
                                         .exposureState = &mExposureState,
                                         .tonemapping = &mSettings.tonemapping,
                                         .output = &mSettings.output,
                                         .frameIndex = mLastFrame,
                                         .timers = nullptr});
}

Image8 processImage(Pipeline& pipeline, const ImageF& image, const FrameTime& time) {
    const Texture input = makeTexture(image, "input");
    return readTexture8(pipeline.execute({.color = &input}, time));
}

} // namespace photopic
