#include "passes/volumetric/VolumetricLightPass.h"

#include "core/VolumetricLight.h"
#include "passes/Bindings.h"

#include <cmath>

namespace photopic {

namespace {

GLuint groups(int size) {
    return GLuint((size + 7) / 8);
}

constexpr ResourceUse kUses[] = {
    {Resource::SceneColor, Access::Read},      {Resource::LinearDepth, Access::Read},
    {Resource::Camera, Access::Read},          {Resource::SunDirection, Access::Read},
    {Resource::Motion, Access::ReadOptional},  {Resource::SceneColor, Access::Write},
    {Resource::VolumetricLight, Access::Write}};

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
    p.samples = s.samples;
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

} // namespace

VolumetricLightPass::VolumetricLightPass()
    : mPrepare(makeComputeProgram("passes/volumetric/volumetric_light_prepare.comp.glsl", bindingDefines()))
    , mScatter(makeComputeProgram("passes/volumetric/volumetric_light_scatter.comp.glsl", bindingDefines()))
    , mResolve(makeComputeProgram("passes/volumetric/volumetric_light_resolve.comp.glsl", bindingDefines()))
    , mComposite(
          makeComputeProgram("passes/volumetric/volumetric_light_composite.comp.glsl", bindingDefines()))
    , mParameters("volumetric light parameters")
    , mNoView({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "volumetric light view (unused)"}) {}

std::span<const ResourceUse> VolumetricLightPass::uses() const {
    return kUses;
}

void VolumetricLightPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const Extent half{(e.width + 1) / 2, (e.height + 1) / 2};
    mHistory.ensure(half, GL_RGBA16F, "volumetric light");
    const Texture& source =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "volumetric light source"})
            .texture();
    const Texture& raw = resources.pool()
                             .acquire({.extent = half,
                                       .format = GL_RGBA16F,
                                       .minFilter = GL_NEAREST,
                                       .magFilter = GL_NEAREST,
                                       .debugName = "volumetric light (this frame)"})
                             .texture();
    const Texture& out =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with volumetric light"})
            .texture();
    const bool writeView = ctx.settings.debug.view == DebugView::VolumetricLight;
    const Texture* view = nullptr;
    if (writeView) {
        view = &resources.pool()
                    .acquire({.extent = e,
                              .format = GL_RGBA16F,
                              .minFilter = GL_NEAREST,
                              .magFilter = GL_NEAREST,
                              .debugName = "volumetric light view"})
                    .texture();
    }
    const Texture* motion = resources.texture(Resource::Motion);
    const bool hasHistory = mHistory.valid() && !ctx.resetHistory;
    const VolumetricLightParameters p = parametersFor(ctx, half, hasHistory, motion != nullptr, writeView);
    mParameters.update(p);
    mParameters.bind(kBindingParameters);

    const Texture& scene = *resources.texture(Resource::SceneColor);
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    const double full = double(e.width) * e.height;
    const double halfTexels = double(half.width) * half.height;
    glBindTextureUnit(0, scene.id());
    glBindTextureUnit(1, depth.id());
    {
        // Colour and depth in, one RGBA16F texel out.
        ScopedGpuTimer timer(ctx.timers, "volumetric light source", full * (8.0 + 4.0 + 8.0));
        mPrepare.use();
        glBindImageTexture(0, source.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(groups(e.width), groups(e.height), 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // The full-resolution source read once from memory (the samples along each ray hit the cache), one
        // half-resolution texel out.
        ScopedGpuTimer timer(ctx.timers, "volumetric light march", full * 8.0 + halfTexels * 8.0);
        mScatter.use();
        glBindTextureUnit(2, source.id());
        glBindImageTexture(0, raw.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(groups(half.width), groups(half.height), 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // This frame's march (a tile with its border), motion, the history, the output.
        ScopedGpuTimer timer(ctx.timers, "volumetric light resolve", halfTexels * (8.0 + 8.0 + 8.0 + 8.0));
        mResolve.use();
        glBindTextureUnit(3, raw.id());
        glBindTextureUnit(4, mHistory.previous() ? mHistory.previous()->id() : raw.id());
        glBindTextureUnit(5, motion ? motion->id() : depth.id());
        glBindImageTexture(0, mHistory.current().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(groups(half.width), groups(half.height), 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // The colour in and out, the accumulated light (upsampled), the view when it is on.
        ScopedGpuTimer timer(ctx.timers, "volumetric light composite",
                             full * (8.0 + 8.0 + (writeView ? 8.0 : 0.0)) + halfTexels * 8.0);
        mComposite.use();
        glBindTextureUnit(6, mHistory.current().id());
        glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glBindImageTexture(1, view ? view->id() : mNoView.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(groups(e.width), groups(e.height), 1);
    }
    mHistory.advance();
    resources.bind(Resource::SceneColor, out);
    if (view) {
        resources.bind(Resource::VolumetricLight, *view);
    }
}

} // namespace photopic
