#include "passes/motionblur/MotionBlurPass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                 {Resource::Motion, Access::Read},
                                 {Resource::LinearDepth, Access::Read},
                                 {Resource::SceneColor, Access::Write},
                                 {Resource::VelocityTiles, Access::Write}};

TextureCreateInfo transient(Extent e, GLenum format, const char* name) {
    return {
        .extent = e, .format = format, .minFilter = GL_NEAREST, .magFilter = GL_NEAREST, .debugName = name};
}

} // namespace

float shutterFraction(const MotionBlurSettings& settings, const Camera* camera, float dt) noexcept {
    if (settings.shutterSource == ShutterSource::Camera && camera != nullptr) {
        const Lens& lens = camera->lens;
        if (lens.exposureTimeS > 0.0f && dt > 0.0f && std::isfinite(dt)) {
            return lens.exposureTimeS / dt;
        }
        return lens.shutterAngleDeg / 360.0f;
    }
    return settings.shutterAngle / 360.0f;
}

MotionBlurPass::MotionBlurPass(MotionBlurPlacement placement)
    : mPlacement(placement)
    , mPrepare(makeComputeProgram("passes/motionblur/motion_blur_prepare.comp.glsl", bindingDefines()))
    , mTiles(makeComputeProgram("passes/motionblur/motion_blur_tiles.comp.glsl", bindingDefines()))
    , mNeighbours(makeComputeProgram("passes/motionblur/motion_blur_neighbours.comp.glsl", bindingDefines()))
    , mGather(makeComputeProgram("passes/motionblur/motion_blur_gather.comp.glsl", bindingDefines()))
    , mParameters("motion blur parameters")
    , mNoTiles({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "velocity tiles (unused)"}) {}

std::span<const ResourceUse> MotionBlurPass::uses() const {
    return kUses;
}

bool MotionBlurPass::enabled(const FrameContext& ctx) const {
    return ctx.hdr && ctx.settings.motionBlur.enabled && ctx.settings.motionBlur.placement == mPlacement;
}

void MotionBlurPass::execute(FrameContext& ctx, FrameResources& resources) {
    const MotionBlurSettings& s = ctx.settings.motionBlur;
    const Extent e = ctx.extent;
    const Extent tiles{(e.width + s.tileSize - 1) / s.tileSize, (e.height + s.tileSize - 1) / s.tileSize};
    const Texture& velocity =
        resources.pool().acquire(transient(e, GL_RG16F, "motion blur velocity")).texture();
    const Texture& tileMax =
        resources.pool().acquire(transient(tiles, GL_RG16F, "velocity tile max")).texture();
    const Texture& neighbourMax =
        resources.pool().acquire(transient(tiles, GL_RG16F, "velocity neighbour max")).texture();
    const Texture& out =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with motion blur"})
            .texture();
    const bool writeTiles = ctx.settings.debug.view == DebugView::VelocityTiles;
    const Texture* tilesView = nullptr;
    if (writeTiles) {
        tilesView = &resources.pool().acquire(transient(e, GL_RGBA16F, "velocity tiles (view)")).texture();
    }

    MotionBlurParameters p{};
    p.fullSize = glm::vec2(float(e.width), float(e.height));
    p.radiusScale = 0.5f * shutterFraction(s, ctx.inputs.camera, ctx.time.dt) * s.intensity;
    p.maxBlur = s.maxBlur;
    p.tileSize = s.tileSize;
    p.sampleCount = s.sampleCount;
    p.frame = std::uint32_t(ctx.time.frameIndex % 1024u);
    p.writeTiles = writeTiles ? 1 : 0;
    p.tileCount = glm::ivec2(tiles.width, tiles.height);
    mParameters.update(p);
    mParameters.bind(kBindingParameters);

    const double texels = double(e.width) * e.height;
    const Texture& motion = *resources.texture(Resource::Motion);
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    {
        ScopedGpuTimer timer(ctx.timers, "motion blur prepare", texels * (4.0 + 4.0));
        mPrepare.use();
        glBindTextureUnit(0, motion.id());
        glBindImageTexture(0, velocity.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
        dispatchPixels(e);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        ScopedGpuTimer timer(ctx.timers, "motion blur tile max", texels * 4.0);
        mTiles.use();
        glBindTextureUnit(0, velocity.id());
        glBindImageTexture(0, tileMax.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
        dispatchPixels(tiles);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        ScopedGpuTimer timer(ctx.timers, "motion blur neighbour max",
                             double(tiles.width) * tiles.height * 40.0);
        mNeighbours.use();
        glBindTextureUnit(0, tileMax.id());
        glBindImageTexture(0, neighbourMax.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
        dispatchPixels(tiles);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // Colour, velocity and depth, each read once from memory (the samples along a streak hit the cache),
        // the result (and the view) written.
        ScopedGpuTimer timer(ctx.timers, "motion blur gather",
                             texels * (8.0 + 4.0 + 4.0 + 8.0 + (writeTiles ? 8.0 : 0.0)));
        mGather.use();
        glBindTextureUnit(0, resources.texture(Resource::SceneColor)->id());
        glBindTextureUnit(1, velocity.id());
        glBindTextureUnit(2, depth.id());
        glBindTextureUnit(3, neighbourMax.id());
        glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glBindImageTexture(1, tilesView ? tilesView->id() : mNoTiles.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                           GL_RGBA16F);
        dispatchPixels(e);
    }
    resources.bind(Resource::SceneColor, out);
    if (tilesView) {
        resources.bind(Resource::VelocityTiles, *tilesView);
    }
}

} // namespace photopic
