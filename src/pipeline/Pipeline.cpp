#include "pipeline/Pipeline.h"

#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "passes/sanitize/SanitizePass.h"
#include "passes/tonemap/TonemapPass.h"

#include <cmath>

namespace photopic {

struct Pipeline::Passes {
    std::unique_ptr<SanitizePass> sanitize; ///< HDR path only
    TonemapPass tonemap;
};

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
    }
}

Pipeline::~Pipeline() = default;

void Pipeline::setSettings(const Settings& settings) {
    mSettings = settings;
}

void Pipeline::resize(Extent extent) {
    if (extent == mExtent) {
        return;
    }
    mExtent = extent;
    if (mPasses->sanitize) {
        mPasses->sanitize->resize(extent);
    }
    mPasses->tonemap.resize(extent);
}

const Texture& Pipeline::execute(const FrameInputs& inputs, const FrameTime& time) {
    resize(inputs.color->extent());
    mTimers.beginFrame();

    // 1. sanitise (HDR path; the LDR path sanitises inside its single pass)
    const Texture* scene = inputs.color;
    if (mPasses->sanitize) {
        scene = &mPasses->sanitize->execute({.color = inputs.color, .timers = &mTimers});
    }

    // 4. exposure state: manual exposure only until metering exists.
    GpuExposureState state;
    state.manualEV = mSettings.tonemapping.exposure;
    state.exposure = std::exp2(state.manualEV);
    state.initialized = 1;
    mExposureState.update(&state, sizeof(state));

    // 7 + 9. composite and tone map, once.
    const TonemapPass::Inputs tonemapInputs{.scene = scene,
                                            .exposureState = &mExposureState,
                                            .tonemapping = &mSettings.tonemapping,
                                            .output = &mSettings.output,
                                            .frameIndex = time.frameIndex,
                                            .timers = &mTimers};
    const Texture& display = mPasses->tonemap.execute(tonemapInputs);
    mLastScene = scene;
    mLastFrame = time.frameIndex;
    mTimers.endFrame();
    return display;
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
