#include "passes/dof/DofPass.h"

#include "core/DepthOfField.h"
#include "core/Log.h"
#include "passes/Bindings.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                 {Resource::LinearDepth, Access::Read},
                                 {Resource::Camera, Access::Read},
                                 {Resource::SceneColor, Access::Write},
                                 {Resource::DofCoc, Access::Write}};

int rings(DofQuality q) {
    switch (q) {
    case DofQuality::Low:
        return 2;
    case DofQuality::High:
        return 4;
    default:
        return 3;
    }
}

TextureCreateInfo target(Extent e, GLenum format, const char* name) {
    return {.extent = e, .format = format, .debugName = name};
}

} // namespace

DofPass::DofPass()
    : mCoc(makeComputeProgram("passes/dof/dof_coc.comp.glsl", bindingDefines()))
    , mPrepare(makeComputeProgram("passes/dof/dof_prepare.comp.glsl", bindingDefines()))
    , mTiles(makeComputeProgram("passes/dof/dof_tiles.comp.glsl", bindingDefines()))
    , mDilate(makeComputeProgram("passes/dof/dof_tiles.comp.glsl", bindingDefines({{"DILATE", "1"}})))
    , mFar(makeComputeProgram("passes/dof/dof_gather.comp.glsl", bindingDefines()))
    , mNear(makeComputeProgram("passes/dof/dof_gather.comp.glsl", bindingDefines({{"NEAR", "1"}})))
    , mComposite(makeComputeProgram("passes/dof/dof_composite.comp.glsl", bindingDefines()))
    , mParameters("depth of field parameters") {}

std::span<const ResourceUse> DofPass::uses() const {
    return kUses;
}

void DofPass::execute(FrameContext& ctx, FrameResources& resources) {
    const DepthOfFieldSettings& s = ctx.settings.dof;
    const Extent e = ctx.extent;
    const Extent half{std::max(1, (e.width + 1) / 2), std::max(1, (e.height + 1) / 2)};
    const Extent tiles{(half.width + kTileSize - 1) / kTileSize, (half.height + kTileSize - 1) / kTileSize};
    const CocModel model = cocModel(s, ctx.inputs.camera->lens, e.height);
    if (s.mode == DofMode::Physical) {
        // r(z) = scale / z + bias is monotonic in 1 / z: its largest size lies at the near plane or at
        // infinity.
        const float largest =
            std::max(std::abs(model.bias), std::abs(model.scale / ctx.inputs.camera->nearPlane + model.bias));
        if (largest < 0.1f) {
            const Lens& lens = ctx.inputs.camera->lens;
            warnOnce(
                "dof-invisible",
                fmt::format("dof.enabled: the lens (f/{:g}, {:g} mm, focus {:g}) blurs nothing visibly: its "
                            "largest circle of confusion is {:.3f} pixels, under a tenth of a pixel at every "
                            "depth",
                            lens.fNumber, lens.focalLengthMm, lens.focusDistance, largest));
        }
    }

    DofParameters p{};
    p.fullSize = glm::vec2(float(e.width), float(e.height));
    p.halfSize = glm::vec2(float(half.width), float(half.height));
    p.cocScale = model.scale;
    p.cocBias = model.bias;
    p.focalDistance = s.focalDistance;
    p.focalRange = s.focalRange;
    p.bokehRadius = s.bokehRadius;
    p.maxCoc = s.maxCocRadius;
    p.artistic = s.mode == DofMode::Artistic ? 1 : 0;
    p.kernel = s.kernel == DofKernel::Hexagon ? 1 : 0;
    p.rings = rings(s.quality);
    p.tileSize = kTileSize;
    p.tileCount = glm::ivec2(tiles.width, tiles.height);
    // The near field's largest radius, in half-resolution pixels, reaches this many tiles.
    p.dilation = std::max(1, int(std::ceil(0.5f * s.maxCocRadius / float(kTileSize))));
    mParameters.update(p);
    mParameters.bind(kBindingParameters);

    TexturePool& pool = resources.pool();
    const Texture& coc = pool.acquire(target(e, GL_R16F, "dof coc")).texture();
    const Texture& farField = pool.acquire(target(half, GL_RGBA16F, "dof far field")).texture();
    const Texture& nearField = pool.acquire(target(half, GL_RGBA16F, "dof near field")).texture();
    const Texture& tileMax = pool.acquire(target(tiles, GL_R16F, "dof near tiles")).texture();
    const Texture& tileReach = pool.acquire(target(tiles, GL_R16F, "dof near tiles (dilated)")).texture();
    const Texture& farBlur = pool.acquire(target(half, GL_RGBA16F, "dof far blur")).texture();
    const Texture& nearBlur = pool.acquire(target(half, GL_RGBA16F, "dof near blur")).texture();
    const Texture& out = pool.acquire(target(e, GL_RGBA16F, "depth of field")).texture();
    const Texture& color = *resources.texture(Resource::SceneColor);
    const Texture& depth = *resources.texture(Resource::LinearDepth);

    const double texels = double(e.width) * e.height;
    const double halfTexels = double(half.width) * half.height;
    {
        ScopedGpuTimer timer(ctx.timers, "dof coc", texels * (4.0 + 2.0));
        mCoc.use();
        glBindTextureUnit(0, depth.id());
        glBindImageTexture(0, coc.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
        dispatchPixels(e);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        ScopedGpuTimer timer(ctx.timers, "dof prepare", texels * (8.0 + 2.0) + halfTexels * 16.0);
        mPrepare.use();
        glBindTextureUnit(0, color.id());
        glBindTextureUnit(1, coc.id());
        glBindImageTexture(0, farField.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glBindImageTexture(1, nearField.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchPixels(half);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        ScopedGpuTimer timer(ctx.timers, "dof tiles", halfTexels * 8.0);
        mTiles.use();
        glBindTextureUnit(0, nearField.id());
        glBindImageTexture(0, tileMax.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
        dispatchPixels(tiles);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        mDilate.use();
        glBindTextureUnit(0, tileMax.id());
        glBindImageTexture(0, tileReach.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
        dispatchPixels(tiles);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // The half-resolution field read once from memory (the disc's taps hit the cache), the blur written.
        ScopedGpuTimer timer(ctx.timers, "dof far", halfTexels * (8.0 + 8.0));
        mFar.use();
        glBindTextureUnit(0, farField.id());
        glBindTextureUnit(1, tileReach.id());
        glBindImageTexture(0, farBlur.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchPixels(half);
    }
    {
        ScopedGpuTimer timer(ctx.timers, "dof near", halfTexels * (8.0 + 8.0));
        mNear.use();
        glBindTextureUnit(0, nearField.id());
        glBindTextureUnit(1, tileReach.id());
        glBindImageTexture(0, nearBlur.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchPixels(half);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        ScopedGpuTimer timer(ctx.timers, "dof composite", texels * (8.0 + 2.0 + 8.0 + 8.0));
        mComposite.use();
        glBindTextureUnit(0, color.id());
        glBindTextureUnit(1, coc.id());
        glBindTextureUnit(2, farBlur.id());
        glBindTextureUnit(3, nearBlur.id());
        glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchPixels(e);
    }
    resources.bind(Resource::SceneColor, out);
    resources.bind(Resource::DofCoc, coc);
}

} // namespace photopic
