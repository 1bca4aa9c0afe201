#include "passes/volumetriclight/VolumetricLightPass.h"

#include "core/Log.h"
#include "core/VolumetricLight.h"
#include "passes/Bindings.h"

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

constexpr ResourceUse kUses[] = {
    {Resource::SceneColor, Access::Read},     {Resource::LinearDepth, Access::Read},
    {Resource::Camera, Access::Read},         {Resource::SunDirection, Access::Read},
    {Resource::Motion, Access::ReadOptional}, {Resource::SunShadowMap, Access::ReadOptional},
    {Resource::SceneColor, Access::Write},    {Resource::VolumetricLight, Access::Write}};

VolumetricLightParameters parametersFor(const FrameContext& ctx, Extent half, bool hasHistory, bool hasMotion,
                                        bool writeView) {
    const VolumetricLightSettings& s = ctx.settings.volumetricLight;
    const SunOnScreen sun = sunOnScreen(*ctx.inputs.camera, *ctx.inputs.sunDirection);
    VolumetricLightParameters p{};
    p.sunUv = sun.inFront ? sun.uv : glm::vec2(0.5f);
    p.halfSize = glm::vec2(float(half.width), float(half.height));
    p.fullSize = glm::vec2(float(ctx.extent.width), float(ctx.extent.height));
    p.density = s.density;
    // decay 0: only a sample at t = 0 counts (exp2(-0) = 1); avoids log2(0) * 0.
    p.logDecay = s.decay > 0.0f ? 64.0f * std::log2(s.decay) : -1e30f;
    p.scale = s.intensity * s.weight * s.exposure * sun.fade;
    p.historyWeight = VolumetricLightPass::kHistoryWeight;
    p.samples = s.sampleCount();
    p.frame = std::uint32_t(ctx.time.frameIndex % 1024u);
    p.hasHistory = hasHistory ? 1 : 0;
    p.hasMotion = hasMotion ? 1 : 0;
    p.writeView = writeView ? 1 : 0;
    p.active = sun.fade > 0.0f ? 1 : 0;
    // A file's sky written as the far plane's depth comes back a rounding error short of it (the linear
    // depth pass takes depths at or beyond far as the sky): anything this close to far is the sky too.
    const float far = ctx.inputs.camera->farPlane;
    p.skyDepth = std::isinf(far) ? far : far * (1.0f - 1e-4f);
    return p;
}

VolumetricShadowParameters shadowParametersFor(const FrameContext& ctx, Extent low, int factor,
                                               bool hasHistory, bool writeView) {
    const VolumetricLightSettings& s = ctx.settings.volumetricLight;
    const Camera& camera = *ctx.inputs.camera;
    const SunShadowMap& shadow = ctx.inputs.sunShadow;
    VolumetricShadowParameters p{};
    p.worldToShadowClip = shadow.worldToClip;
    p.inverseView = glm::inverse(camera.view);
    p.prevViewProjection = camera.prevViewProjection;
    p.projection = glm::vec4(1.0f / camera.projection[0][0], 1.0f / camera.projection[1][1],
                             camera.projection[2][0], camera.projection[2][1]);
    p.light = glm::vec4(shadow.illuminance * s.decay, s.anisotropy);
    p.toSun = glm::vec4(glm::normalize(*ctx.inputs.sunDirection), 0.0f);
    p.lowSize = glm::vec2(float(low.width), float(low.height));
    p.fullSize = glm::vec2(float(ctx.extent.width), float(ctx.extent.height));
    p.extinction = s.density * s.scattering;
    p.maxDistance = s.maxDistance;
    p.historyWeight = VolumetricLightPass::kHistoryWeight;
    const float far = camera.farPlane;
    p.skyDepth = std::isinf(far) ? far : far * (1.0f - 1e-4f);
    p.samples = s.sampleCount();
    p.frame = std::uint32_t(ctx.time.frameIndex % 1024u);
    p.hasHistory = hasHistory ? 1 : 0;
    p.writeView = writeView ? 1 : 0;
    p.factor = factor;
    p.intensity = s.intensity;
    return p;
}

/// Where either mode's composite writes: the scene colour with the light added, and the debug view's image
/// when that view is on.
struct CompositeTargets {
    const Texture& out;
    const Texture* view = nullptr;
};

CompositeTargets acquireCompositeTargets(const FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const Texture& out =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with volumetric light"})
            .texture();
    if (ctx.settings.debug.view != DebugView::VolumetricLight) {
        return {out};
    }
    return {out, &resources.pool().acquireNearest(e, GL_RGBA16F, "volumetric light view")};
}

void publish(FrameResources& resources, const CompositeTargets& targets) {
    resources.bind(Resource::SceneColor, targets.out);
    if (targets.view != nullptr) {
        resources.bind(Resource::VolumetricLight, *targets.view);
    }
}

} // namespace

VolumetricLightPass::VolumetricLightPass()
    : mPrepare(
          makeComputeProgram("passes/volumetriclight/volumetric_light_prepare.comp.glsl", bindingDefines()))
    , mScatter(
          makeComputeProgram("passes/volumetriclight/volumetric_light_scatter.comp.glsl", bindingDefines()))
    , mResolve(
          makeComputeProgram("passes/volumetriclight/volumetric_light_resolve.comp.glsl", bindingDefines()))
    , mComposite(
          makeComputeProgram("passes/volumetriclight/volumetric_light_composite.comp.glsl", bindingDefines()))
    , mParameters("volumetric light parameters")
    , mNoView({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "volumetric light view (unused)"})
    , mShadowMarch(
          makeComputeProgram("passes/volumetriclight/volumetric_shadow_march.comp.glsl", bindingDefines()))
    , mShadowResolve(
          makeComputeProgram("passes/volumetriclight/volumetric_shadow_resolve.comp.glsl", bindingDefines()))
    , mShadowComposite(makeComputeProgram("passes/volumetriclight/volumetric_shadow_composite.comp.glsl",
                                          bindingDefines()))
    , mShadowParameters("volumetric light (shadow map) parameters")
    , mShadowSampler(Sampler::depthCompare("volumetric light sun shadow map")) {}

std::span<const ResourceUse> VolumetricLightPass::uses() const {
    return kUses;
}

void VolumetricLightPass::execute(FrameContext& ctx, FrameResources& resources) {
    const VolumetricLightMode mode = ctx.settings.volumetricLight.mode;
    const Texture* shadowMap = resources.texture(Resource::SunShadowMap);
    if (mode == VolumetricLightMode::ShadowMap && shadowMap == nullptr) {
        warnOnce("volumetric-light-no-shadow-map",
                 "volumetricLight.mode = shadowmap without a sun shadow map (FrameInputs::sunShadow): the "
                 "screen-space rays run instead");
    }
    const bool march = marchesShadowMap(mode, shadowMap != nullptr);
    if (!march && !(sunOnScreen(*ctx.inputs.camera, *ctx.inputs.sunDirection).fade > 0.0f)) {
        warnOnce(
            "volumetric-light-sun-off-screen",
            "volumetricLight.enabled: the sun is behind the camera or off the screen, so the screen-space "
            "rays add no light (mode shadowmap with a sun shadow map lights the air without seeing it)");
    }
    if (march != mLastRanShadowMap) {
        invalidateHistory(); // the other mode's history holds something else
        mLastRanShadowMap = march;
    }
    if (march) {
        executeShadowMap(ctx, resources, *shadowMap);
    } else {
        executeScreen(ctx, resources);
    }
}

void VolumetricLightPass::shadowMarch(const FrameContext& ctx, const FrameResources& resources,
                                      const Texture& shadowMap, const Texture& raw, Extent low) {
    const int samples = ctx.settings.volumetricLight.sampleCount();
    // One depth per texel, `samples` shadow-map lookups (a 2x2 comparison of 4-byte depths, mostly cached),
    // the light and depth out.
    ScopedGpuTimer timer(ctx.timers, "volumetric light march (shadow map)",
                         double(low.width) * low.height * (4.0 + samples * 16.0 + 8.0 + 4.0));
    mShadowMarch.use();
    bind(mMarchDepth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
    bind(mMarchShadowMap, shadowMap, mShadowSampler);
    bind(mMarchOut, raw, ImageAccess::Write);
    bind(mMarchLowDepth, mShadowDepth.current(), ImageAccess::Write);
    dispatch(mShadowMarch, low, Barrier::None);
    bindSampler(mMarchShadowMap, nullptr);
    unbind(mMarchShadowMap);
}

void VolumetricLightPass::shadowResolve(const FrameContext& ctx, const Texture& raw, Extent low) {
    // This frame's march and depths (a tile with its border), the history's light and depths, the output.
    ScopedGpuTimer timer(ctx.timers, "volumetric light resolve (shadow map)",
                         double(low.width) * low.height * (8.0 + 4.0 + 4 * (8.0 + 4.0) + 8.0));
    mShadowResolve.use();
    const Texture& current = mShadowDepth.current();
    bind(mShadowResolveRaw, raw, ImageAccess::Read);
    bind(mShadowResolveHistory, mShadowLight.previous() ? *mShadowLight.previous() : raw, ImageAccess::Read);
    bind(mShadowResolveLowDepth, current, ImageAccess::Read);
    bind(mShadowResolvePrevLowDepth, mShadowDepth.previous() ? *mShadowDepth.previous() : current,
         ImageAccess::Read);
    bind(mShadowResolveOut, mShadowLight.current(), ImageAccess::Write);
    dispatch(mShadowResolve, low, Barrier::None);
}

void VolumetricLightPass::shadowComposite(const FrameContext& ctx, const FrameResources& resources,
                                          const Texture& out, const Texture* view, Extent low) {
    const Extent e = ctx.extent;
    // The colour and depth in, the colour out, four texels of light and depth, the view when it is on.
    ScopedGpuTimer timer(ctx.timers, "volumetric light composite (shadow map)",
                         double(e.width) * e.height * (8.0 + 4.0 + 8.0 + (view ? 8.0 : 0.0)) +
                             double(low.width) * low.height * 12.0);
    mShadowComposite.use();
    bind(mShadowCompositeScene, *resources.texture(Resource::SceneColor), ImageAccess::Read);
    bind(mShadowCompositeDepth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
    bind(mShadowCompositeLowDepth, mShadowDepth.current(), ImageAccess::Read);
    bind(mShadowCompositeAccumulated, mShadowLight.current(), ImageAccess::Read);
    bind(mShadowCompositeOut, out, ImageAccess::Write);
    bind(mShadowCompositeView, view ? *view : mNoView, ImageAccess::Write);
    dispatch(mShadowComposite, e, Barrier::None);
}

void VolumetricLightPass::executeShadowMap(FrameContext& ctx, FrameResources& resources,
                                           const Texture& shadowMap) {
    const Extent e = ctx.extent;
    const int factor = ctx.settings.volumetricLight.resolution == VolumetricLightResolution::Quarter ? 4 : 2;
    const Extent low{(e.width + factor - 1) / factor, (e.height + factor - 1) / factor};
    mShadowLight.ensure(low, GL_RGBA16F, "volumetric light (shadow map)");
    mShadowDepth.ensure(low, GL_R32F, "volumetric light (shadow map) depth");
    const Texture& raw =
        resources.pool().acquireNearest(low, GL_RGBA16F, "volumetric light march (this frame)");
    const CompositeTargets targets = acquireCompositeTargets(ctx, resources);
    const bool hasHistory =
        mShadowLight.valid() && mShadowDepth.valid() && !ctx.resetHistory && !ctx.inputs.camera->cut;
    mShadowParameters.update(shadowParametersFor(ctx, low, factor, hasHistory, targets.view != nullptr));
    mShadowParameters.bind(kBindingParameters);
    shadowMarch(ctx, resources, shadowMap, raw, low);
    memoryBarrier(Barrier::ImageAccess);
    shadowResolve(ctx, raw, low);
    memoryBarrier(Barrier::ImageAccess);
    shadowComposite(ctx, resources, targets.out, targets.view, low);
    mShadowLight.advance();
    mShadowDepth.advance();
    publish(resources, targets);
}

void VolumetricLightPass::lightSource(const FrameContext& ctx, const FrameResources& resources,
                                      const Texture& source) {
    const Extent e = ctx.extent;
    // Colour and depth in, one RGBA16F texel out.
    ScopedGpuTimer timer(ctx.timers, "volumetric light source",
                         double(e.width) * e.height * (8.0 + 4.0 + 8.0));
    mPrepare.use();
    bind(mPrepareScene, *resources.texture(Resource::SceneColor));
    bind(mPrepareDepth, *resources.texture(Resource::LinearDepth));
    bind(mPrepareSource, source, ImageAccess::Write);
    dispatch(mPrepare, e, Barrier::None);
}

void VolumetricLightPass::scatter(const FrameContext& ctx, const Texture& source, const Texture& raw,
                                  Extent half) {
    const Extent e = ctx.extent;
    // The full-resolution source read once from memory (the samples along each ray hit the cache), one
    // half-resolution texel out.
    ScopedGpuTimer timer(ctx.timers, "volumetric light march",
                         double(e.width) * e.height * 8.0 + double(half.width) * half.height * 8.0);
    mScatter.use();
    bind(mScatterSource, source);
    bind(mScatterOut, raw, ImageAccess::Write);
    dispatch(mScatter, half, Barrier::None);
}

void VolumetricLightPass::resolve(const FrameContext& ctx, const FrameResources& resources,
                                  const Texture& raw, Extent half) {
    const Texture* motion = resources.texture(Resource::Motion);
    // This frame's march (a tile with its border), motion, the history, the output.
    ScopedGpuTimer timer(ctx.timers, "volumetric light resolve",
                         double(half.width) * half.height * (8.0 + 8.0 + 8.0 + 8.0));
    mResolve.use();
    bind(mResolveRaw, raw);
    bind(mResolveHistory, mHistory.previous() ? *mHistory.previous() : raw);
    bind(mResolveMotion, motion ? *motion : *resources.texture(Resource::LinearDepth));
    bind(mResolveOut, mHistory.current(), ImageAccess::Write);
    dispatch(mResolve, half, Barrier::None);
}

void VolumetricLightPass::composite(const FrameContext& ctx, const FrameResources& resources,
                                    const Texture& out, const Texture* view, Extent half) {
    const Extent e = ctx.extent;
    // The colour in and out, the accumulated light (upsampled), the view when it is on.
    ScopedGpuTimer timer(ctx.timers, "volumetric light composite",
                         double(e.width) * e.height * (8.0 + 8.0 + (view ? 8.0 : 0.0)) +
                             double(half.width) * half.height * 8.0);
    mComposite.use();
    bind(mCompositeScene, *resources.texture(Resource::SceneColor));
    bind(mCompositeLight, mHistory.current());
    bind(mCompositeOut, out, ImageAccess::Write);
    bind(mCompositeView, view ? *view : mNoView, ImageAccess::Write);
    dispatch(mComposite, e, Barrier::None);
}

void VolumetricLightPass::executeScreen(FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const Extent half{(e.width + 1) / 2, (e.height + 1) / 2};
    mHistory.ensure(half, GL_RGBA16F, "volumetric light");
    const Texture& source =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "volumetric light source"})
            .texture();
    const Texture& raw = resources.pool().acquireNearest(half, GL_RGBA16F, "volumetric light (this frame)");
    const CompositeTargets targets = acquireCompositeTargets(ctx, resources);
    const bool hasHistory = mHistory.valid() && !ctx.resetHistory;
    mParameters.update(parametersFor(ctx, half, hasHistory, resources.texture(Resource::Motion) != nullptr,
                                     targets.view != nullptr));
    mParameters.bind(kBindingParameters);
    lightSource(ctx, resources, source);
    memoryBarrier(Barrier::TextureFetch);
    scatter(ctx, source, raw, half);
    memoryBarrier(Barrier::TextureFetch);
    resolve(ctx, resources, raw, half);
    memoryBarrier(Barrier::TextureFetch);
    composite(ctx, resources, targets.out, targets.view, half);
    mHistory.advance();
    publish(resources, targets);
}

} // namespace photopic
