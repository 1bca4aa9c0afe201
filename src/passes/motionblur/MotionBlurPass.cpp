#include "passes/motionblur/MotionBlurPass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace photopic {

namespace {

constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                 {Resource::Motion, Access::Read},
                                 {Resource::LinearDepth, Access::Read},
                                 {Resource::SceneColor, Access::Write},
                                 {Resource::VelocityTiles, Access::Write}};

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
    , mTiles(makeComputeProgram("passes/motionblur/motion_blur_tiles.comp.glsl",
                                bindingDefines({{"TILES_SHARED", mSharedTiles ? "1" : "0"}})))
    , mNeighbours(makeComputeProgram("passes/motionblur/motion_blur_neighbours.comp.glsl", bindingDefines()))
    , mGather(makeComputeProgram("passes/motionblur/motion_blur_gather.comp.glsl", bindingDefines()))
    , mStill(makeComputeProgram("passes/motionblur/motion_blur_gather.comp.glsl",
                                bindingDefines({{"MOTION_BLUR_STILL", "1"}})))
    , mParameters("motion blur parameters")
    , mNoTiles({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "velocity tiles (unused)"}) {}

std::span<const ResourceUse> MotionBlurPass::uses() const {
    return kUses;
}

bool MotionBlurPass::enabled(const FrameContext& ctx) const {
    return ctx.hdr && ctx.settings.motionBlur.enabled && ctx.settings.motionBlur.placement == mPlacement;
}

MotionBlurPass::Targets MotionBlurPass::acquireTargets(const FrameContext& ctx, FrameResources& resources,
                                                       Extent tiles) {
    const Extent e = ctx.extent;
    TexturePool& pool = resources.pool();
    Targets t;
    t.velocity = &pool.acquireNearest(e, GL_RG16F, "motion blur velocity");
    t.tileMax = &pool.acquireNearest(tiles, GL_RG16F, "velocity tile max");
    t.neighbourMax = &pool.acquireNearest(tiles, GL_RG16F, "velocity neighbour max");
    t.out = &pool.acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with motion blur"})
                 .texture();
    if (ctx.settings.debug.view == DebugView::VelocityTiles) {
        t.tilesView = &pool.acquireNearest(e, GL_RGBA16F, "velocity tiles (view)");
    }
    return t;
}

MotionBlurParameters MotionBlurPass::parameters(const FrameContext& ctx, Extent tiles, bool writeTiles) {
    const MotionBlurSettings& s = ctx.settings.motionBlur;
    const Extent e = ctx.extent;
    MotionBlurParameters p{};
    p.fullSize = glm::vec2(float(e.width), float(e.height));
    p.radiusScale = 0.5f * shutterFraction(s, ctx.inputs.camera, ctx.time.dt) * s.intensity;
    p.maxBlur = s.maxBlur;
    p.tileSize = s.tileSize;
    p.sampleCount = s.gatherCount();
    p.frame = std::uint32_t(ctx.time.frameIndex % 1024u);
    p.writeTiles = writeTiles ? 1 : 0;
    p.tileCount = glm::ivec2(tiles.width, tiles.height);
    return p;
}

void MotionBlurPass::tileVelocities(const FrameContext& ctx, const FrameResources& resources,
                                    const Targets& t, Extent tiles) {
    const Extent e = ctx.extent;
    const double texels = double(e.width) * e.height;
    {
        ScopedGpuTimer timer(ctx.timers, "motion blur prepare", texels * (4.0 + 4.0));
        mPrepare.use();
        bind(mPrepareMotion, *resources.texture(Resource::Motion));
        bind(mPrepareVelocity, *t.velocity, ImageAccess::Write);
        dispatch(mPrepare, e, Barrier::ComputeRead);
    }
    {
        ScopedGpuTimer timer(ctx.timers, "motion blur tile max", texels * 4.0);
        mTiles.use();
        bind(mTilesVelocity, *t.velocity, ImageAccess::Read);
        bind(mTilesTileMax, *t.tileMax, ImageAccess::Write);
        if (mSharedTiles) {
            dispatch(mTiles, Groups{GLuint(tiles.width), GLuint(tiles.height), 1}, Barrier::ComputeRead);
        } else {
            dispatch(mTiles, tiles, Barrier::ComputeRead);
        }
    }
    {
        ScopedGpuTimer timer(ctx.timers, "motion blur neighbour max",
                             double(tiles.width) * tiles.height * 40.0);
        mNeighbours.use();
        bind(mNeighboursTileMax, *t.tileMax, ImageAccess::Read);
        bind(mNeighboursNeighbourMax, *t.neighbourMax, ImageAccess::Write);
        dispatch(mNeighbours, tiles, Barrier::IndirectDispatch);
    }
}

void MotionBlurPass::resetLists(Extent tiles, int tileSize) {
    const std::size_t count = std::size_t(tiles.width) * std::size_t(tiles.height);
    const std::size_t bytes = sizeof(GpuMotionTileLists) + 2 * count * sizeof(std::uint32_t);
    if (mLists.size() < bytes) {
        mLists = Buffer({.size = bytes, .flags = 0, .debugName = "motion blur tile lists"});
    }
    // On the GPU: both dispatches (groups a tile side)^2 x 0 tiles, as GpuMotionTileLists lays them out.
    const auto side = std::uint32_t((tileSize + 7) / 8);
    const std::uint32_t header[8] = {side, side, 0, side, side, 0, 0, 0};
    static_assert(sizeof(header) == sizeof(GpuMotionTileLists));
    mLists.clearWords(0, header, 8);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingTileList, mLists.id());
}

void MotionBlurPass::runGather(const GatherProgram& program, const FrameResources& resources,
                               const Targets& t, GLintptr arguments) {
    program.program.use();
    bind(program.scene, *resources.texture(Resource::SceneColor), ImageAccess::Read);
    bind(program.velocity, *t.velocity, ImageAccess::Read);
    bind(program.depth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
    bind(program.neighbourMax, *t.neighbourMax, ImageAccess::Read);
    bind(program.out, *t.out, ImageAccess::Write);
    bind(program.tiles, t.tilesView ? *t.tilesView : mNoTiles, ImageAccess::Write);
    dispatchIndirect(program.program, mLists.id(), arguments, Barrier::None);
}

void MotionBlurPass::gather(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    const Extent e = ctx.extent;
    // Colour, velocity and depth, each read once from memory (the samples along a streak hit the cache), the
    // result (and the view) written; counted as if every tile moved (the lists' lengths stay on the GPU).
    ScopedGpuTimer timer(ctx.timers, "motion blur gather",
                         double(e.width) * e.height * (8.0 + 4.0 + 4.0 + 8.0 + (t.tilesView ? 8.0 : 0.0)));
    // The still tiles are the scene colour unchanged: a copy of the whole image, over which the gather writes
    // the moving tiles (a copy runs at the memory's speed, a dispatch over the still tiles did not). Where
    // the scene colour is not RGBA16F (a host's colour standing in for it) the still tiles' program converts.
    const Texture& scene = *resources.texture(Resource::SceneColor);
    const bool copied = scene.format() == t.out->format();
    if (copied) {
        t.out->copyLevel0From(scene, e);
    }
    runGather(mGather, resources, t, GLintptr(offsetof(GpuMotionTileLists, movingArgs)));
    if (!copied || t.tilesView) {
        // The still tiles' colour, and the debug view's tiles there.
        runGather(mStill, resources, t, GLintptr(offsetof(GpuMotionTileLists, stillArgs)));
    }
}

void MotionBlurPass::execute(FrameContext& ctx, FrameResources& resources) {
    const MotionBlurSettings& s = ctx.settings.motionBlur;
    const Extent e = ctx.extent;
    const Extent tiles{(e.width + s.tileSize - 1) / s.tileSize, (e.height + s.tileSize - 1) / s.tileSize};
    const Targets t = acquireTargets(ctx, resources, tiles);
    mParameters.update(parameters(ctx, tiles, t.tilesView != nullptr));
    mParameters.bind(kBindingParameters);
    resetLists(tiles, s.tileSize);
    tileVelocities(ctx, resources, t, tiles);
    gather(ctx, resources, t);
    resources.bind(Resource::SceneColor, *t.out);
    if (t.tilesView) {
        resources.bind(Resource::VelocityTiles, *t.tilesView);
    }
}

} // namespace photopic
