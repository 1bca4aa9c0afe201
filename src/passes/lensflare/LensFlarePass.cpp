#include "passes/lensflare/LensFlarePass.h"

#include "passes/Bindings.h"

#include <algorithm>

namespace photopic {

namespace {
constexpr GLenum kFormat = GL_RGBA16F;
} // namespace

LensFlarePass::LensFlarePass()
    : mPrefilter(makeComputeProgram("passes/lensflare/lensflare_prefilter.comp.glsl", bindingDefines()))
    , mFeatures(makeComputeProgram("passes/lensflare/lensflare_features.comp.glsl", bindingDefines()))
    , mPrefilterParameters("lens flare prefilter parameters")
    , mFeaturesParameters("lens flare features parameters") {}

std::span<const ResourceUse> LensFlarePass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::LensFlare, Access::Write}};
    return kUses;
}

void LensFlarePass::execute(FrameContext& ctx, FrameResources& resources) {
    resources.bind(Resource::LensFlare, execute({.scene = resources.texture(Resource::SceneColor),
                                                 .exposureState = resources.buffer(Resource::ExposureState),
                                                 .settings = &ctx.settings.lensFlare,
                                                 .divisor = ctx.tier.lensFlareDivisor,
                                                 .timers = ctx.timers}));
}

void LensFlarePass::resize(Extent extent) {
    if (extent == mExtent) {
        return;
    }
    mExtent = extent;
    mDivisor = 0;
}

void LensFlarePass::ensureTargets(int divisor) {
    if (divisor == mDivisor && mSource.valid()) {
        return;
    }
    mDivisor = divisor;
    const Extent e{std::max(1, mExtent.width / divisor), std::max(1, mExtent.height / divisor)};
    mSource = Texture({.extent = e, .format = kFormat, .debugName = "lens flare source"});
    mFlare = Texture({.extent = e, .format = kFormat, .debugName = "lens flare"});
}

const Texture& LensFlarePass::execute(const Inputs& in) {
    ensureTargets(std::max(1, in.divisor));
    const Extent e = mSource.extent();
    const double small = double(e.width) * e.height * bytesPerTexel(kFormat);
    DebugGroup group("lens flare");
    {
        const Extent se = in.scene->extent();
        ScopedGpuTimer timer(in.timers, "lens flare prefilter",
                             double(se.width) * se.height * bytesPerTexel(in.scene->format()) + small);
        // Four bilinear taps a quarter of a target texel from its centre cover the target texel's footprint
        // when it is 2x2 source texels; for larger divisors they subsample it, so a source smaller than the
        // gaps can be missed (flares come from suns and lamps, which are larger at these sizes).
        mPrefilterParameters.update({.targetTexel = {1.0f / float(e.width), 1.0f / float(e.height)},
                                     .sourceStep = {0.25f / float(e.width), 0.25f / float(e.height)},
                                     .threshold = in.settings->threshold});
        mPrefilterParameters.bind(kBindingParameters);
        mPrefilter.use();
        bindExposureStateForReading(*in.exposureState);
        bind(mPrefilterScene, *in.scene);
        bind(mPrefilterTarget, mSource, ImageAccess::Write);
        dispatch(mPrefilter, e, Barrier::ImageWrite);
    }
    {
        // The small source read once from memory (every ghost's taps hit the cache), the flare written.
        ScopedGpuTimer timer(in.timers, "lens flare features", small * 2.0);
        mFeaturesParameters.update({.targetTexel = {1.0f / float(e.width), 1.0f / float(e.height)},
                                    .ghosts = in.settings->ghosts,
                                    .ghostSpacing = in.settings->ghostSpacing,
                                    .haloRadius = in.settings->haloRadius,
                                    .intensity = in.settings->intensity,
                                    .aspect = float(mExtent.width) / float(mExtent.height)});
        mFeaturesParameters.bind(kBindingParameters);
        mFeatures.use();
        bind(mFeaturesSource, mSource);
        bind(mFeaturesTarget, mFlare, ImageAccess::Write);
        dispatch(mFeatures, e, Barrier::ImageWrite);
    }
    return mFlare;
}

} // namespace photopic
