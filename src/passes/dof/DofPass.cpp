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
    , mComposite{CompositeProgram(makeComputeProgram("passes/dof/dof_composite.comp.glsl", bindingDefines())),
                 CompositeProgram(makeComputeProgram("passes/dof/dof_composite.comp.glsl",
                                                     bindingDefines({{"DOF_LISTED", "1"}})))}
    , mChanged(makeComputeProgram("passes/dof/dof_changed_tiles.comp.glsl", bindingDefines()))
    , mParameters("depth of field parameters") {}

std::span<const ResourceUse> DofPass::uses() const {
    return kUses;
}

DofPass::Targets DofPass::acquireTargets(Extent e, FrameResources& resources) {
    Targets t;
    t.full = e;
    t.half = {std::max(1, (e.width + 1) / 2), std::max(1, (e.height + 1) / 2)};
    t.tiles = {(t.half.width + kTileSize - 1) / kTileSize, (t.half.height + kTileSize - 1) / kTileSize};
    TexturePool& pool = resources.pool();
    t.coc = &pool.acquire(target(e, GL_R16F, "dof coc")).texture();
    t.farField = &pool.acquire(target(t.half, GL_RGBA16F, "dof far field")).texture();
    t.nearField = &pool.acquire(target(t.half, GL_RGBA16F, "dof near field")).texture();
    t.tileMax = &pool.acquire(target(t.tiles, GL_R16F, "dof near tiles")).texture();
    t.tileReach = &pool.acquire(target(t.tiles, GL_R16F, "dof near tiles (dilated)")).texture();
    t.farBlur = &pool.acquire(target(t.half, GL_RGBA16F, "dof far blur")).texture();
    t.nearBlur = &pool.acquire(target(t.half, GL_RGBA16F, "dof near blur")).texture();
    t.out = &pool.acquire(target(e, GL_RGBA16F, "depth of field")).texture();
    return t;
}

void DofPass::warnIfInvisible(const FrameContext& ctx, const CocModel& model) {
    if (ctx.settings.dof.mode != DofMode::Physical) {
        return;
    }
    // r(z) = scale / z + bias is monotonic in 1 / z: its largest size lies at the near plane or at infinity.
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

DofParameters DofPass::parameters(const FrameContext& ctx, const CocModel& model, const Targets& t) {
    const DofSettings& s = ctx.settings.dof;
    DofParameters p{};
    p.fullSize = glm::vec2(float(t.full.width), float(t.full.height));
    p.halfSize = glm::vec2(float(t.half.width), float(t.half.height));
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
    p.tileCount = glm::ivec2(t.tiles.width, t.tiles.height);
    // The near field's largest radius, in half-resolution pixels, reaches this many tiles.
    p.dilation = std::max(1, int(std::ceil(0.5f * s.maxCocRadius / float(kTileSize))));
    return p;
}

void DofPass::circlesOfConfusion(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    {
        ScopedGpuTimer timer(ctx.timers, "dof coc", double(t.full.width) * t.full.height * (4.0 + 2.0));
        mCoc.use();
        bind(mCocDepth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
        bind(mCocOut, *t.coc, ImageAccess::Write);
        dispatch(mCoc, t.full, Barrier::None);
    }
    memoryBarrier(Barrier::ComputeRead);
}

void DofPass::prepareFields(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    {
        ScopedGpuTimer timer(ctx.timers, "dof prepare",
                             double(t.full.width) * t.full.height * (8.0 + 2.0) +
                                 double(t.half.width) * t.half.height * 16.0);
        mPrepare.use();
        bind(mPrepareColor, *resources.texture(Resource::SceneColor), ImageAccess::Read);
        bind(mPrepareCoc, *t.coc, ImageAccess::Read);
        bind(mPrepareFar, *t.farField, ImageAccess::Write);
        bind(mPrepareNear, *t.nearField, ImageAccess::Write);
        dispatch(mPrepare, t.half, Barrier::None);
    }
    memoryBarrier(Barrier::ComputeRead);
}

void DofPass::nearTiles(const FrameContext& ctx, const Targets& t) {
    {
        ScopedGpuTimer timer(ctx.timers, "dof tiles", double(t.half.width) * t.half.height * 8.0);
        mTiles.use();
        bind(mTilesSource, *t.nearField);
        bind(mTilesOut, *t.tileMax, ImageAccess::Write);
        dispatch(mTiles, t.tiles, Barrier::TextureFetch);
        mDilate.use();
        bind(mDilateSource, *t.tileMax);
        bind(mDilateOut, *t.tileReach, ImageAccess::Write);
        dispatch(mDilate, t.tiles, Barrier::None);
    }
    memoryBarrier(Barrier::ComputeRead);
}

void DofPass::gather(const FrameContext& ctx, const Targets& t) {
    const double halfTexels = double(t.half.width) * t.half.height;
    {
        // The half-resolution field read once from memory (the disc's taps hit the cache), the blur written.
        ScopedGpuTimer timer(ctx.timers, "dof far", halfTexels * (8.0 + 8.0));
        mFar.use();
        bind(mFarField, *t.farField, ImageAccess::Read);
        bind(mFarTiles, *t.tileReach, ImageAccess::Read);
        bind(mFarOut, *t.farBlur, ImageAccess::Write);
        dispatch(mFar, t.half, Barrier::None);
    }
    {
        ScopedGpuTimer timer(ctx.timers, "dof near", halfTexels * (8.0 + 8.0));
        mNear.use();
        bind(mNearField, *t.nearField, ImageAccess::Read);
        bind(mNearTiles, *t.tileReach, ImageAccess::Read);
        bind(mNearOut, *t.nearBlur, ImageAccess::Write);
        dispatch(mNear, t.half, Barrier::None);
    }
    memoryBarrier(Barrier::ComputeRead);
}

void DofPass::listChangedTiles(const FrameContext& ctx, const Targets& t, Extent tiles) {
    const std::size_t count = std::size_t(tiles.width) * std::size_t(tiles.height);
    const std::size_t bytes = sizeof(GpuDofTileList) + count * sizeof(std::uint32_t);
    if (mList.size() < bytes) {
        mList = Buffer({.size = bytes, .flags = 0, .debugName = "dof composite tiles"});
    }
    const Groups full = pixelGroups(t.full);
    const std::uint32_t header[8] = {1, 1, 0, 0, full.x, full.y, 0, 0}; // GpuDofTileList
    static_assert(sizeof(header) == sizeof(GpuDofTileList));
    mList.clearWords(0, header, 8);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingTileList, mList.id());
    // Per tile its 64 CoCs and up to 36 near-field texels (mostly cache hits: counted once), an index out.
    ScopedGpuTimer timer(ctx.timers, "dof composite tiles",
                         double(t.full.width) * t.full.height * 2.0 +
                             double(t.half.width) * t.half.height * 8.0);
    mChanged.use();
    bind(mChangedCoc, *t.coc, ImageAccess::Read);
    bind(mChangedNear, *t.nearBlur, ImageAccess::Read);
    dispatch(mChanged, tiles, Barrier::IndirectDispatch);
}

void DofPass::useComposite(const CompositeProgram& c, const FrameResources& resources, const Targets& t) {
    c.program.use();
    bind(c.color, *resources.texture(Resource::SceneColor), ImageAccess::Read);
    bind(c.coc, *t.coc, ImageAccess::Read);
    bind(c.far, *t.farBlur, ImageAccess::Read);
    bind(c.near, *t.nearBlur);
    bind(c.out, *t.out, ImageAccess::Write);
}

void DofPass::composite(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    const Texture& scene = *resources.texture(Resource::SceneColor);
    // The tiles the composite leaves sharp are an image copy of the scene colour (at the memory's speed);
    // the composite runs over the others. Where the scene colour is not the output's format (a host's
    // colour standing in for it) it runs over every pixel, which converts.
    const bool listed = scene.format() == t.out->format();
    if (listed) {
        listChangedTiles(ctx, t,
                         {(t.full.width + kCompositeTileSize - 1) / kCompositeTileSize,
                          (t.full.height + kCompositeTileSize - 1) / kCompositeTileSize});
    }
    // Counted as if every tile changed (the list's length stays on the GPU).
    ScopedGpuTimer timer(ctx.timers, "dof composite",
                         double(t.full.width) * t.full.height * (8.0 + 2.0 + 8.0 + 8.0));
    if (!listed) {
        useComposite(mComposite[0], resources, t);
        dispatch(mComposite[0].program, t.full, Barrier::None);
        return;
    }
    memoryBarrier(Barrier::TextureFetchAndCopy);
    t.out->copyLevel0From(scene, t.full);
    useComposite(mComposite[1], resources, t);
    dispatchIndirect(mComposite[1].program, mList.id(), GLintptr(offsetof(GpuDofTileList, changedArgs)),
                     Barrier::None);
    // Where most tiles change, the classification handed the frame to the composite over every pixel (its
    // dispatch has no work groups otherwise).
    useComposite(mComposite[0], resources, t);
    dispatchIndirect(mComposite[0].program, mList.id(), GLintptr(offsetof(GpuDofTileList, fullArgs)),
                     Barrier::None);
}

void DofPass::execute(FrameContext& ctx, FrameResources& resources) {
    const CocModel model = cocModel(ctx.settings.dof, ctx.inputs.camera->lens, ctx.extent.height);
    warnIfInvisible(ctx, model);
    const Targets t = acquireTargets(ctx.extent, resources);
    mParameters.update(parameters(ctx, model, t));
    mParameters.bind(kBindingParameters);
    circlesOfConfusion(ctx, resources, t);
    prepareFields(ctx, resources, t);
    nearTiles(ctx, t);
    gather(ctx, t);
    composite(ctx, resources, t);
    resources.bind(Resource::SceneColor, *t.out);
    resources.bind(Resource::DofCoc, *t.coc);
}

} // namespace photopic
