#include "pipeline/Pipeline.h"

#include "core/Log.h"
#include "core/Quality.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "passes/Bindings.h"
#include "passes/bloom/BloomPass.h"
#include "passes/debug/DebugViewPass.h"
#include "passes/display/DisplayEffectsPass.h"
#include "passes/exposure/ExposurePass.h"
#include "passes/fxaa/FxaaPass.h"
#include "passes/lensflare/LensFlarePass.h"
#include "passes/metering/MeteringPass.h"
#include "passes/probe/ProbePass.h"
#include "passes/sanitize/SanitizePass.h"
#include "passes/tonemap/TonemapPass.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace photopic {

namespace {

/// Readback slots: deep enough that a host polling once a frame never drops a frame on a GPU a few frames
/// behind.
constexpr int kTelemetrySlots = 16;
constexpr std::size_t kTelemetryBytes = sizeof(GpuExposureState) + kGpuHistogramBytes;
/// Probe readback slots: probes run at probe.hz, a few frames apart; a GPU a few frames behind never fills
/// it.
constexpr int kProbeSlots = 8;

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
    case MeteringMode::Subject:
        return MeteringPass::Weights::None; // the probe pass writes the reading
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
    // HDR path only (null on a GPU without RGBA16F render targets).
    std::unique_ptr<SanitizePass> sanitize;
    std::unique_ptr<BloomPass> bloom;
    std::unique_ptr<LensFlarePass> lensFlare;
    // Both paths.
    MeteringPass metering;
    ProbePass probe;
    ExposurePass exposure;
    TonemapPass tonemap;
    DebugViewPass debug;
    FxaaPass fxaa;
    DisplayEffectsPass displayEffects;
};

namespace {

/// The tier frames run at: the settings' tier, or the legacy tier's effects when the GPU forces LDR.
QualityTier effectiveTier(const Capabilities& caps, Quality quality) {
    QualityTier tier = qualityTier(quality);
    if (caps.path == ColorPath::Ldr) {
        const QualityTier legacy = qualityTier(Quality::Legacy);
        tier.hdrPath = false;
        tier.bloom = legacy.bloom;
        tier.glow = legacy.glow;
        tier.lensFlare = legacy.lensFlare;
    }
    return tier;
}

void warnAboutTier(const Capabilities& caps, Quality quality) {
    if (quality == Quality::Legacy && caps.path == ColorPath::Hdr) {
        warnOnce("quality-legacy",
                 "quality=legacy: running the LDR (RGBA8) path although the GPU renders "
                 "RGBA16F; the bloom chain is replaced by a single cheap glow, lens flare is "
                 "off and values above 1 clip before tone mapping");
    }
}

} // namespace

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
        mPasses->bloom = std::make_unique<BloomPass>();
        mPasses->lensFlare = std::make_unique<LensFlarePass>();
    }
    mPasses->tonemap.prepare(mSettings.tonemapping, mSettings.colorGrading, legacyGlow());
    loadMask();
    configureSubjects();
    warnAboutTier(mCaps, mSettings.quality);
}

Pipeline::~Pipeline() = default;

void Pipeline::setSettings(const Settings& settings) {
    mSettings = settings;
    mPasses->tonemap.prepare(mSettings.tonemapping, mSettings.colorGrading, legacyGlow());
    loadMask();
    configureSubjects();
    warnAboutTier(mCaps, mSettings.quality);
}

void Pipeline::configureSubjects() {
    mSubjects.setSettings(mSettings.subjects);
    mPending.resize(std::size_t(std::max(mSettings.subjects.maxSubjects, 1)));
    mPendingCount = std::min(mPendingCount, mPending.size());
    if (mPasses->probe.capacity() != mSubjects.capacity() || mProbeRing.slotCount() == 0) {
        mPasses->probe.setCapacity(mSubjects.capacity());
        mProbeRing = ReadbackRing(mPasses->probe.bytes(), kProbeSlots, "subject probes");
    }
}

const AutoExposureSettings& Pipeline::runSubjects(const FrameInputs& inputs, const FrameTime& time,
                                                  const Texture& scene, const Buffer& metering) {
    const bool pending = inputs.subjects.empty();
    mSubjects.beginFrame(time.dt, pending ? mPendingCentre : inputs.viewCentreWorld);
    for (const Subject& s :
         pending ? std::span<const Subject>(mPending.data(), mPendingCount) : inputs.subjects) {
        mSubjects.addSubject(s);
    }
    mPendingCount = 0;
    const std::span<const ProbeRequest> requests = mSubjects.scheduleProbes();
    pollProbes(); // results of earlier frames into this frame's contexts (never waits)

    const AutoExposureSettings& ae = mSettings.autoExposure;
    const bool subjectMetering = ae.enabled && ae.metering == MeteringMode::Subject;
    const SubjectContext* subject = mSubjects.subjectContext();
    const SubjectSettings::Probe& p = mSettings.subjects.probe;
    if (!requests.empty() || subjectMetering) {
        mPasses->probe.execute({.scene = &scene,
                                .requests = requests,
                                .taps = p.taps,
                                .radius = p.radius,
                                .active = subject != nullptr,
                                .selectedId = subject ? subject->id : 0u,
                                .deadbandEV = p.deadbandEV,
                                .timeS = mSubjects.time(),
                                .metering = subjectMetering ? &metering : nullptr,
                                .timers = &mTimers});
        if (!requests.empty()) {
            mProbeRing.enqueue(mPasses->probe.results(), 0, time.frameIndex);
        }
    }
    // Outdoors coupling of the subject of the view (seed 000: tighter maxEV, faster adaptation outdoors); the
    // copy reuses mCoupled's storage, so the frame does not allocate.
    if (subjectMetering && subject && mSettings.subjects.outdoorsCoupling.enabled) {
        mCoupled = outdoorsCoupledSettings(ae, mSettings.subjects.outdoorsCoupling, subject->outdoors);
        return mCoupled;
    }
    return ae;
}

void Pipeline::setSubjects(std::span<const Subject> subjects, glm::vec2 viewCentreWorld) noexcept {
    mPendingCount = std::min(subjects.size(), mPending.size());
    std::copy_n(subjects.begin(), mPendingCount, mPending.begin());
    mPendingCentre = viewCentreWorld;
}

void Pipeline::pollProbes() noexcept {
    const std::size_t capacity = mPasses->probe.capacity();
    mProbeRing.pollEach([&](const ReadbackRing::Result& r) {
        GpuProbeHeader header;
        std::memcpy(&header, r.bytes.data(), sizeof(header));
        const std::size_t count = std::min<std::size_t>(header.count, capacity);
        for (std::size_t i = 0; i < count; ++i) {
            GpuProbeEntry e;
            std::memcpy(&e, r.bytes.data() + sizeof(header) + i * sizeof(GpuProbeEntry), sizeof(e));
            mSubjects.recordProbe(e.id, e.luma, header.timeS);
        }
    });
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
        mPasses->bloom->resize(extent);
        mPasses->lensFlare->resize(extent);
    }
    mPasses->metering.resize(extent);
    mPasses->tonemap.resize(extent);
    mPasses->debug.resize(extent);
    mPasses->fxaa.resize(extent);
    mPasses->displayEffects.resize(extent);
    mResetExposure = true; // DESIGN.md: snap on resize
}

glm::vec2 Pipeline::beginFrame(const FrameTime& time, const Camera* camera) {
    (void)time;
    (void)camera;
    return glm::vec2(0.0f);
}

const LightingOutputs& Pipeline::renderLighting(const FrameInputs& inputs, const FrameTime& time) {
    (void)inputs;
    (void)time;
    mLighting = {};
    return mLighting;
}

const Texture& Pipeline::execute(const FrameInputs& inputs, const FrameTime& time) {
    resize(inputs.color->extent());
    mTimers.beginFrame();
    const AutoExposureSettings& ae = mSettings.autoExposure;
    const DebugView view = mSettings.debug.view;
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    const bool hdr = tier.hdrPath && mPasses->sanitize;

    // 1. sanitise (HDR path; the LDR path sanitises inside its single pass)
    const Texture* scene = inputs.color;
    if (hdr) {
        scene = &mPasses->sanitize->execute({.color = inputs.color, .timers = &mTimers});
    }

    // 4. metering, subject probes and adaptation, on the GPU. The histogram is built when exposure or a debug
    // view needs it (seed 004: the histogram view works with auto exposure off).
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
    // The probes read the same sanitised image; with subject metering they write the reading.
    const AutoExposureSettings& frameAe = runSubjects(inputs, time, *scene, *metered.metering);
    mPasses->exposure.execute({.histogram = metered.histogram,
                               .metering = metered.metering,
                               .exposureState = &mExposureState,
                               .settings = &frameAe,
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
    // Contexts: target from each subject's probed luma, applied from the newest exposure that came back.
    // The base settings: the tracker applies each subject's own outdoors coupling.
    mSubjects.updateExposure(mSettings.autoExposure, mTelemetry.appliedLog2);

    // 6. bloom on exposed colour.
    const Texture* bloom = nullptr;
    mBloomLevels = 0;
    if (hdr && tier.bloom && mSettings.bloom.enabled) {
        const int mips = mSettings.bloom.mipCount > 0 ? mSettings.bloom.mipCount : tier.bloomMips;
        bloom = &mPasses->bloom->execute({.scene = scene,
                                          .exposureState = &mExposureState,
                                          .settings = &mSettings.bloom,
                                          .firstDivisor = tier.bloomFirstDivisor,
                                          .mipCount = mips,
                                          .timers = &mTimers});
        mBloomLevels = mPasses->bloom->levels();
    }

    const DebugViewPass::Inputs debugInputs{.view = view,
                                            .scene = scene,
                                            .display = nullptr,
                                            .mask = mMask.valid() ? &mMask : nullptr,
                                            .bloom = bloom,
                                            .exposureState = &mExposureState,
                                            .histogram = metered.histogram,
                                            .autoExposure = &ae,
                                            .timers = &mTimers};
    mLastScene = scene;
    mLastBloom = bloom;
    mLastFrame = time.frameIndex;

    // 8. scene-value debug views replace the image and are shown as they are (no tone mapping).
    if (DebugViewPass::isSceneView(view)) {
        const Texture& debug = mPasses->debug.execute(debugInputs);
        mTimers.endFrame();
        return debug;
    }

    // 7 + 9. composite, grade and tone map, once.
    const TonemapPass::Inputs tonemapInputs{.scene = scene,
                                            .exposureState = &mExposureState,
                                            .tonemapping = &mSettings.tonemapping,
                                            .output = &mSettings.output,
                                            .bloom = bloom,
                                            .bloomSettings = &mSettings.bloom,
                                            .glow = !hdr && legacyGlow(),
                                            .grading = &mSettings.colorGrading,
                                            .frameIndex = time.frameIndex,
                                            .timers = &mTimers};
    const Texture* display = &mPasses->tonemap.execute(tonemapInputs);

    // 10. FXAA on display-referred values.
    if (tier.fxaa && mSettings.fxaa.enabled) {
        display =
            &mPasses->fxaa.execute({.display = display, .settings = &mSettings.fxaa, .timers = &mTimers});
    }

    // 11. lens flare from the HDR image, then the fused display effects.
    const Texture* flare = nullptr;
    if (hdr && tier.lensFlare && mSettings.lensFlare.enabled) {
        flare = &mPasses->lensFlare->execute({.scene = scene,
                                              .exposureState = &mExposureState,
                                              .settings = &mSettings.lensFlare,
                                              .divisor = tier.lensFlareDivisor,
                                              .timers = &mTimers});
    }
    const bool grain = tier.grain && mSettings.grain.enabled;
    if (flare || grain || mSettings.vignette.enabled || mSettings.dazzle.enabled) {
        const GrainSettings grainSettings{.enabled = grain, .intensity = mSettings.grain.intensity};
        display = &mPasses->displayEffects.execute({.display = display,
                                                    .exposureState = &mExposureState,
                                                    .flare = flare,
                                                    .glare = bloom,
                                                    .vignette = &mSettings.vignette,
                                                    .chromaticAberration = tier.chromaticAberration,
                                                    .grain = &grainSettings,
                                                    .dazzle = &mSettings.dazzle,
                                                    .frameIndex = time.frameIndex,
                                                    .timers = &mTimers});
    }

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
                                         .bloom = mLastBloom,
                                         .bloomSettings = &mSettings.bloom,
                                         .glow = mLastBloom == nullptr && legacyGlow(),
                                         .grading = &mSettings.colorGrading,
                                         .frameIndex = mLastFrame,
                                         .timers = nullptr});
}

bool Pipeline::legacyGlow() const {
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    return !(tier.hdrPath && mPasses->sanitize) && tier.glow && mSettings.bloom.enabled;
}

PipelineStatus Pipeline::status() const {
    PipelineStatus t;
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    t.quality = mSettings.quality;
    if (tier.hdrPath && mCaps.path == ColorPath::Hdr) {
        t.path = ColorPath::Hdr;
        t.pathReason = mCaps.pathReason;
    } else {
        t.path = ColorPath::Ldr;
        t.pathReason = mCaps.path == ColorPath::Ldr ? mCaps.pathReason : "quality=legacy runs the LDR path";
    }
    t.bloomLevels = mBloomLevels;
    t.passes = mTimers.latest();
    return t;
}

Image8 processImage(Pipeline& pipeline, const ImageF& image, const FrameTime& time) {
    const Texture input = makeTexture(image, "input");
    return readTexture8(pipeline.execute({.color = &input}, time));
}

} // namespace photopic
