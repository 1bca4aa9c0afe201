#include "pipeline/Pipeline.h"

#include "core/Log.h"
#include "core/Quality.h"
#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "passes/bloom/BloomPass.h"
#include "passes/display/DisplayEffectsPass.h"
#include "passes/fxaa/FxaaPass.h"
#include "passes/lensflare/LensFlarePass.h"
#include "passes/sanitize/SanitizePass.h"
#include "passes/tonemap/TonemapPass.h"

#include <cmath>

namespace photopic {

struct Pipeline::Passes {
    // HDR path only (null on a GPU without RGBA16F render targets).
    std::unique_ptr<SanitizePass> sanitize;
    std::unique_ptr<BloomPass> bloom;
    std::unique_ptr<LensFlarePass> lensFlare;
    // Both paths.
    TonemapPass tonemap;
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
        tier.lensFlare = legacy.lensFlare;
    }
    return tier;
}

void warnAboutTier(const Capabilities& caps, Quality quality) {
    if (quality == Quality::Legacy && caps.path == ColorPath::Hdr) {
        warnOnce("quality-legacy", "quality=legacy: running the LDR (RGBA8) path although the GPU renders "
                                   "RGBA16F; bloom and lens flare are off and values above 1 clip before "
                                   "tone mapping");
    }
}

} // namespace

Pipeline::Pipeline(const PipelineCreateInfo& info)
    : mSettings(info.settings)
    , mCaps(detectCapabilities(info.forceLdr))
    , mPasses(std::make_unique<Passes>())
    , mExposureState({.size = sizeof(GpuExposureState),
                      .flags = GL_DYNAMIC_STORAGE_BIT,
                      .data = nullptr,
                      .debugName = "exposure state"}) {
    if (mCaps.path == ColorPath::Hdr) {
        mPasses->sanitize = std::make_unique<SanitizePass>();
        mPasses->bloom = std::make_unique<BloomPass>();
        mPasses->lensFlare = std::make_unique<LensFlarePass>();
    }
    warnAboutTier(mCaps, mSettings.quality);
}

Pipeline::~Pipeline() = default;

void Pipeline::setSettings(const Settings& settings) {
    mSettings = settings;
    warnAboutTier(mCaps, mSettings.quality);
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
    mPasses->tonemap.resize(extent);
    mPasses->fxaa.resize(extent);
    mPasses->displayEffects.resize(extent);
}

const Texture& Pipeline::execute(const FrameInputs& inputs, const FrameTime& time) {
    resize(inputs.color->extent());
    mTimers.beginFrame();
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    const bool hdr = tier.hdrPath && mPasses->sanitize;

    // 1. sanitise (HDR path; the LDR path sanitises inside its single pass)
    const Texture* scene = inputs.color;
    if (hdr) {
        scene = &mPasses->sanitize->execute({.color = inputs.color, .timers = &mTimers});
    }

    // 4. exposure state: manual exposure only until metering exists.
    GpuExposureState state;
    state.manualEV = mSettings.tonemapping.exposure;
    state.exposure = std::exp2(state.manualEV);
    state.initialized = 1;
    mExposureState.update(&state, sizeof(state));

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

    // 7 + 9. composite, grade and tone map, once.
    const TonemapPass::Inputs tonemapInputs{.scene = scene,
                                            .exposureState = &mExposureState,
                                            .tonemapping = &mSettings.tonemapping,
                                            .output = &mSettings.output,
                                            .bloom = bloom,
                                            .bloomSettings = &mSettings.bloom,
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

    mLastScene = scene;
    mLastBloom = bloom;
    mLastFrame = time.frameIndex;
    mTimers.endFrame();
    return *display;
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
                                         .grading = &mSettings.colorGrading,
                                         .frameIndex = mLastFrame,
                                         .timers = nullptr});
}

PipelineTelemetry Pipeline::telemetry() const {
    PipelineTelemetry t;
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
