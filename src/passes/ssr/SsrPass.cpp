#include "passes/ssr/SsrPass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <bit>

namespace photopic {

namespace {

constexpr int kMaxPyramidLevels = 7; // as many as ssr_pyramid.comp.glsl writes
/// Mip levels of the history the glossy cones read.
constexpr int kHistoryLevels = 6; // as many as ssr_history.comp.glsl writes

int mipLevels(Extent e, int most) {
    const auto smaller = unsigned(std::max(1, std::min(e.width, e.height)));
    return std::min(most, int(std::bit_width(smaller)));
}

} // namespace

int depthPyramidLevels(Extent e) noexcept {
    return mipLevels(e, kMaxPyramidLevels);
}

Extent depthPyramidExtent(Extent e) noexcept {
    const int cell = 1 << (depthPyramidLevels(e) - 1);
    return {(e.width + cell - 1) / cell * cell, (e.height + cell - 1) / cell * cell};
}

Extent depthPyramidAtlasExtent(Extent e) noexcept {
    const Extent size0 = depthPyramidExtent(e);
    return {size0.width + (depthPyramidLevels(e) > 1 ? size0.width / 2 : 0), size0.height};
}

DepthPyramidPass::DepthPyramidPass()
    : mProgram(makeComputeProgram("passes/ssr/ssr_pyramid.comp.glsl",
                                  bindingDefines({{"PYRAMID_ONE_DISPATCH", mOneDispatch ? "1" : "0"}}))) {}

std::span<const ResourceUse> DepthPyramidPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::LinearDepth, Access::Read},
                                            {Resource::DepthPyramid, Access::Write}};
    return kUses;
}

void DepthPyramidPass::execute(FrameContext& ctx, FrameResources& resources) {
    const int levels = depthPyramidLevels(ctx.extent);
    const Extent size0 = depthPyramidExtent(ctx.extent);
    // One level holding them all (ssr_pyramid.h.glsl): every read of it is an image load at level 0.
    const Texture& pyramid =
        resources.pool().acquireNearest(depthPyramidAtlasExtent(ctx.extent), GL_RG32F, "ssr depth pyramid");
    // Level 0 reads a depth and writes its pair (nearest, farthest); the rest of the chain writes a third of
    // level 0's pairs again.
    ScopedGpuTimer timer(ctx.timers, "ssr depth pyramid",
                         double(size0.width) * size0.height * (4.0 + 8.0 + 8.0 / 3.0));
    mProgram.use();
    glProgramUniform2i(mProgram.id(), 1, size0.width, size0.height);
    if (mOneDispatch) {
        glProgramUniform1i(mProgram.id(), 0, levels);
        bind(mLinearDepth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
        bind(mPyramid, pyramid, ImageAccess::Write);
        // A work group per 64 x 64 tile of level 0; the trace loads the levels.
        dispatch(mProgram, Groups{GLuint((size0.width + 63) / 64), GLuint((size0.height + 63) / 64), 1},
                 Barrier::ImageAccess);
    } else {
        for (int level = 0; level < levels; ++level) {
            bind(mLinearDepth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
            bind(mPyramid, pyramid, ImageAccess::ReadWrite);
            glProgramUniform1i(mProgram.id(), 0, level);
            // The next level reads what this one wrote.
            dispatch(mProgram, Extent{size0.width >> level, size0.height >> level}, Barrier::ImageAccess);
        }
    }
    resources.bind(Resource::DepthPyramid, pyramid);
}

SsrHistoryPass::SsrHistoryPass()
    : mProgram(makeComputeProgram("passes/ssr/ssr_history.comp.glsl",
                                  bindingDefines({{"HISTORY_ONE_DISPATCH", mOneDispatch ? "1" : "0"}}))) {}

std::span<const ResourceUse> SsrHistoryPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read}};
    return kUses;
}

void SsrHistoryPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const int levels = mipLevels(e, kHistoryLevels);
    if (!mHistory.valid() || mHistory.extent() != e) {
        mHistory = Texture({.extent = e,
                            .format = GL_RGBA16F,
                            .levels = levels,
                            .minFilter = GL_LINEAR_MIPMAP_LINEAR,
                            .magFilter = GL_LINEAR,
                            .debugName = "ssr history"});
        mValid = false;
    }
    {
        // One colour read, and written with its mips (a third more).
        ScopedGpuTimer timer(ctx.timers, "ssr history", double(e.width) * e.height * (8.0 + 8.0 * 4.0 / 3.0));
        mProgram.use();
        const Texture& scene = *resources.texture(Resource::SceneColor);
        if (mOneDispatch) {
            glProgramUniform1i(mProgram.id(), 0, levels);
            bind(mScene, scene, ImageAccess::Read);
            for (int level = 0; level < int(mLevelSlots.size()); ++level) {
                // A level the texture does not have: its slot holds level 0, which the shader does not
                // write there.
                bind(mLevelSlots[std::size_t(level)], mHistory, ImageAccess::Write,
                     level < levels ? level : 0);
            }
            // A work group per 32 x 32 tile of level 0; the next frame's resolve samples the chain.
            dispatch(mProgram, Groups{GLuint((e.width + 31) / 32), GLuint((e.height + 31) / 32), 1},
                     Barrier::TextureFetch);
        } else {
            for (int level = 0; level < levels; ++level) {
                glProgramUniform1i(mProgram.id(), 0, level);
                bind(mScene, scene, ImageAccess::Read);
                bind(mBelow, mHistory, ImageAccess::Read, std::max(level - 1, 0)); // unread at level 0
                bind(mTarget, mHistory, ImageAccess::Write, level);
                // The next level loads this one; after the last, the next frame's resolve samples them.
                dispatch(mProgram, Extent{std::max(e.width >> level, 1), std::max(e.height >> level, 1)},
                         level + 1 < levels ? Barrier::ImageAccess : Barrier::TextureFetch);
            }
        }
    }
    mValid = true;
}

void SsrHistoryPass::publishState(FrameResources& resources) const {
    if (const Texture* last = previous()) {
        resources.bind(Resource::SsrHistory, *last);
    }
}

SsrPass::SsrPass()
    : mParameters("ssr parameters") {}

std::span<const ResourceUse> SsrPass::uses() const {
    static constexpr ResourceUse kUses[] = {
        {Resource::SceneColor, Access::Read},      {Resource::DepthPyramid, Access::Read},
        {Resource::LinearDepth, Access::Read},     {Resource::Camera, Access::Read},
        {Resource::Normals, Access::ReadOptional}, {Resource::Material, Access::ReadOptional},
        {Resource::Motion, Access::ReadOptional},  {Resource::SsrHistory, Access::ReadOptional},
        {Resource::SceneColor, Access::Write},     {Resource::Reflections, Access::Write}};
    return kUses;
}

SsrPass::Targets SsrPass::acquireTargets(Extent e, bool half, bool reflections, FrameResources& resources) {
    TexturePool& pool = resources.pool();
    const auto hitTexture = [&](Extent extent, const char* name) {
        return &pool.acquireNearest(extent, GL_RGBA32F, name);
    };
    // One hit per pixel; at half resolution the blocks' hits first, from which each pixel finds its own.
    Targets t;
    t.hits = hitTexture(e, "ssr hits");
    t.blockHits = half ? hitTexture({(e.width + 1) / 2, (e.height + 1) / 2}, "ssr block hits") : nullptr;
    t.sceneOut =
        &pool.acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with reflections"})
             .texture();
    if (reflections) {
        t.reflections =
            &pool.acquire({.extent = e, .format = GL_RGBA16F, .debugName = "ssr reflections"}).texture();
    }
    return t;
}

const Texture* SsrPass::history(const FrameContext& ctx, const FrameResources& resources) {
    const Texture* history = ctx.resetHistory ? nullptr : resources.texture(Resource::SsrHistory);
    return history != nullptr && history->extent() == ctx.extent ? history : nullptr;
}

SsrParameters SsrPass::parameters(const FrameContext& ctx, const FrameResources& resources,
                                  Extent traceExtent) const {
    const SsrSettings& s = ctx.settings.ssr;
    const Camera& camera = *ctx.inputs.camera;
    const Extent e = ctx.extent;
    SsrParameters p{};
    p.projection = camera.projection;
    p.reprojection = camera.prevViewProjection * glm::inverse(camera.view);
    viewRays(camera.projection, p.rayNear, p.rayFar);
    p.fullSize = glm::vec2(float(e.width), float(e.height));
    p.traceSize = glm::vec2(float(traceExtent.width), float(traceExtent.height));
    p.thickness = s.thickness;
    p.maxDistance = s.maxDistance;
    p.roughnessCutoff = s.roughnessCutoff;
    p.edgeFade = s.edgeFade * float(std::min(e.width, e.height));
    p.intensity = s.intensity;
    p.maxSteps = s.stepCount();
    p.levels = depthPyramidLevels(e);
    const Extent pyramidSize = depthPyramidExtent(e);
    p.pyramidSize = glm::ivec2(pyramidSize.width, pyramidSize.height);
    p.normals = normalsSource(ctx, resources);
    p.hasMaterial = resources.texture(Resource::Material) ? 1 : 0;
    p.hasHistory = history(ctx, resources) ? 1 : 0;
    p.hasMotion = resources.texture(Resource::Motion) ? 1 : 0;
    p.half = s.halfResolution() ? 1 : 0;
    return p;
}

const SsrPass::TraceProgram& SsrPass::traceProgram(int normals, bool refine) {
    ShaderDefines defines{{"SSR_NORMALS", std::to_string(normals)}};
    if (refine) {
        defines.emplace_back("REFINE", "1");
    }
    return mTraces.get(std::size_t(refine ? 3 : 0) + std::size_t(normals), defines);
}

void SsrPass::bindTrace(const TraceProgram& trace, const FrameResources& resources, const Texture& hits) {
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    const Texture* normals = resources.texture(Resource::Normals);
    const Texture* material = resources.texture(Resource::Material);
    trace.program.use();
    bind(trace.depth, depth, ImageAccess::Read);
    bind(trace.normals, normals ? *normals : depth);
    bind(trace.material, material ? *material : depth);
    bind(trace.pyramid, *resources.texture(Resource::DepthPyramid), ImageAccess::Read);
    bind(trace.hits, hits, ImageAccess::Write);
}

void SsrPass::trace(const FrameContext& ctx, const FrameResources& resources, const Targets& t,
                    Extent traceExtent) {
    const Extent e = ctx.extent;
    const double pixels = double(e.width) * e.height;
    const double tracePixels = double(traceExtent.width) * traceExtent.height;
    const bool half = t.blockHits != nullptr;
    // Depth, normal and material at the origin, the pyramid (4/3 of a full-resolution RG32F) read once from
    // memory, the hit written; at half resolution the blocks' hits also written and read.
    const double inputs = pixels * (4.0 + (resources.texture(Resource::Normals) ? 8.0 : 0.0) +
                                    (resources.texture(Resource::Material) ? 8.0 : 0.0) + 8.0 * 4.0 / 3.0);
    ScopedGpuTimer timer(ctx.timers, "ssr trace",
                         inputs + pixels * 16.0 + (half ? 2.0 * tracePixels * 16.0 : 0.0));
    const int normals = normalsSource(ctx, resources);
    const TraceProgram& march = traceProgram(normals, false);
    bindTrace(march, resources, half ? *t.blockHits : *t.hits);
    dispatch(march.program, traceExtent, half ? Barrier::ImageAccess : Barrier::None);
    if (half) {
        const TraceProgram& refine = traceProgram(normals, true);
        bindTrace(refine, resources, *t.hits);
        bind(refine.blockHits, *t.blockHits, ImageAccess::Read);
        dispatch(refine.program, e, Barrier::None);
    }
}

void SsrPass::resolve(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    const Extent e = ctx.extent;
    const Texture* history = SsrPass::history(ctx, resources);
    const Texture* motion = resources.texture(Resource::Motion);
    const Texture* material = resources.texture(Resource::Material);
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    const Texture& scene = *resources.texture(Resource::SceneColor);
    // The hits, the scene colour, the history, motion and material where present, each once; the scene
    // colour out, and the reflections for the debug view.
    ScopedGpuTimer timer(ctx.timers, "ssr resolve",
                         double(e.width) * e.height *
                             (16.0 + 8.0 + (history ? 8.0 : 0.0) + (motion ? 4.0 : 0.0) +
                              (material ? 8.0 : 0.0) + 8.0 + (t.reflections ? 8.0 : 0.0)));
    const ResolveProgram& r =
        resolveProgram(motion != nullptr, history != nullptr, material != nullptr, t.reflections != nullptr);
    r.program.use();
    bind(r.depth, depth, ImageAccess::Read);
    bind(r.scene, scene, ImageAccess::Read);
    bind(r.history, history ? *history : scene);
    bind(r.hits, *t.hits, ImageAccess::Read);
    bind(r.motion, motion ? *motion : depth);
    bind(r.material, material ? *material : depth);
    bind(r.outScene, *t.sceneOut, ImageAccess::Write);
    if (t.reflections != nullptr) {
        bind(r.outReflections, *t.reflections, ImageAccess::Write);
    }
    dispatch(r.program, e, Barrier::None);
}

const SsrPass::ResolveProgram& SsrPass::resolveProgram(bool motion, bool history, bool material,
                                                       bool reflections) {
    return mResolves.get((motion ? 1u : 0u) | (history ? 2u : 0u) | (material ? 4u : 0u) |
                             (reflections ? 8u : 0u),
                         {{"SSR_MOTION", motion ? "1" : "0"},
                          {"SSR_HISTORY", history ? "1" : "0"},
                          {"SSR_MATERIAL", material ? "1" : "0"},
                          {"SSR_REFLECTIONS", reflections ? "1" : "0"}});
}

void SsrPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const bool half = ctx.settings.ssr.halfResolution();
    const Extent traceExtent = half ? Extent{(e.width + 1) / 2, (e.height + 1) / 2} : e;
    const Targets t = acquireTargets(e, half, ctx.settings.debug.view == DebugView::Ssr, resources);
    mParameters.update(parameters(ctx, resources, traceExtent));
    mParameters.bind(kBindingParameters);
    trace(ctx, resources, t, traceExtent);
    memoryBarrier(Barrier::ImageAccess);
    resolve(ctx, resources, t);
    resources.bind(Resource::SceneColor, *t.sceneOut);
    if (t.reflections != nullptr) {
        resources.bind(Resource::Reflections, *t.reflections);
    }
}

} // namespace photopic
