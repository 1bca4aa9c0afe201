#include "passes/gtao/GtaoPass.h"

#include "passes/Bindings.h"

#include <algorithm>

namespace photopic {
namespace {

/// `defines` and the pyramid's level count, which every GTAO program's surface header reads (the host sizes
/// the image by the same constant).
ShaderDefines gtaoDefines(ShaderDefines defines) {
    defines.push_back({"GTAO_SURFACE_LEVELS", std::to_string(GtaoPass::kSurfaceLevels)});
    return defines;
}

} // namespace

GtaoPass::GtaoPass(Stage stage)
    : mStage(stage)
    , mDenoiseFull(makeComputeProgram("passes/gtao/gtao_denoise.comp.glsl",
                                      bindingDefines(gtaoDefines({{"GTAO_SCALE", "1"}}))))
    , mDenoiseHalf(makeComputeProgram("passes/gtao/gtao_denoise.comp.glsl",
                                      bindingDefines(gtaoDefines({{"GTAO_SCALE", "2"}}))))
    , mParameters("gtao parameters") {}

std::span<const ResourceUse> GtaoPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::LinearDepth, Access::Read},
                                            {Resource::Normals, Access::Read},
                                            {Resource::Camera, Access::Read},
                                            {Resource::AmbientOcclusion, Access::Write}};
    return kUses;
}

bool GtaoPass::enabled(const FrameContext& ctx) const {
    const GtaoSettings& s = ctx.settings.gtao;
    if (!s.enabled) {
        return false;
    }
    // The post-stage instance feeds the multiply pass, which works on the HDR path's scene colour.
    return mStage == Stage::Lighting ? s.apply == GtaoApply::Lighting
                                     : s.apply == GtaoApply::Multiply && ctx.hdr;
}

glm::ivec2 GtaoPass::slicesAndSteps(EffectQuality quality) noexcept {
    switch (quality) {
    case EffectQuality::Low:
        return {1, 2};
    case EffectQuality::Medium:
        return {2, 2};
    case EffectQuality::High:
        return {3, 3};
    case EffectQuality::Ultra:
        return {9, 3};
    }
    return {3, 3};
}

void GtaoPass::texelToView(GtaoParameters& p) noexcept {
    // ndc = (texel + 0.5) 2 / size - 1 and xy = (ndc w + P[2].xy z - P[3].xy) / (P[0][0], P[1][1]).
    const glm::vec2 diagonal{p.projection[0][0], p.projection[1][1]};
    p.texelScale = 2.0f / (p.fullSize * diagonal);
    p.texelBias = (1.0f / p.fullSize - 1.0f) / diagonal;
    p.depthScale = glm::vec2(p.projection[2][0], p.projection[2][1]) / diagonal;
    p.viewOffset = -glm::vec2(p.projection[3][0], p.projection[3][1]) / diagonal;
}

void GtaoPass::execute(FrameContext& ctx, FrameResources& resources) {
    const GtaoSettings& s = ctx.settings.gtao;
    const Extent e = ctx.extent;
    const int scale = resolutionScale(s.resolution);
    const Extent rawExtent{(e.width + scale - 1) / scale, (e.height + scale - 1) / scale};
    const Texture& surface = packSurface(ctx, resources);
    TexturePool& pool = resources.pool();
    const Texture& raw = pool.acquireNearest(rawExtent, GL_RG32UI, "gtao raw");
    const Texture& out = pool.acquireNearest(e, GL_R16F, "ambient occlusion");
    const glm::ivec2 tier = slicesAndSteps(s.quality);
    const double rawTexels = double(rawExtent.width) * rawExtent.height;
    const double fullTexels = double(e.width) * e.height;
    // Horizon search: a surface texel per step (2 sides) and per side's depth check, plus the centre's, and
    // its output texel; denoise: the centre's surface texel, 9 (25 at half resolution) output texels of the
    // search, mostly cache hits, and the visibility. Three timers: the packing, the search and the denoiser
    // cost differently with the preset and the resolution.
    const double searchBytes = rawTexels * (8.0 * 2.0 * tier.x * (tier.y + 1) + 8.0 + 8.0);
    const double denoiseBytes = fullTexels * (8 + 8 + 2);
    search(surface, raw, s.quality, scale, s.sampleMips, searchBytes, ctx.timers);
    denoise(surface, raw, out, scale, denoiseBytes, ctx.timers);
    resources.bind(Resource::AmbientOcclusion, out);
}

const Texture& GtaoPass::packSurface(FrameContext& ctx, FrameResources& resources) {
    const GtaoSettings& s = ctx.settings.gtao;
    const Extent e = ctx.extent;
    const glm::ivec2 tier = slicesAndSteps(s.quality);
    GtaoParameters parameters{.projection = ctx.inputs.camera->projection,
                              .fullSize = glm::vec2(float(e.width), float(e.height)),
                              .radius = s.radius,
                              .bias = s.bias,
                              .slices = tier.x,
                              .steps = tier.y,
                              .scale = resolutionScale(s.resolution),
                              .frame = std::uint32_t(ctx.time.frameIndex % 1024u),
                              .octahedral = ctx.inputs.normalEncoding == NormalEncoding::Octahedral ? 1 : 0};
    texelToView(parameters);
    mParameters.update(parameters);
    mParameters.bind(kBindingParameters);

    const bool mips = s.sampleMips;
    const Texture& surface =
        resources.pool().acquireNearest(mips ? surfacePyramidExtent(e) : e, GL_RG32UI, "gtao surface");
    // With the coarse levels, their texels (under a third of level 0's) are written besides.
    ScopedGpuTimer timer(ctx.timers, "gtao surface",
                         double(e.width) * e.height * (4 + 8 + 8 + (mips ? 8.0 / 3.0 : 0.0)));
    const PrepareProgram& p =
        mPrepare.get(mips ? 1 : 0, gtaoDefines({{"GTAO_SAMPLE_MIPS", mips ? "1" : "0"}}));
    p.program.use();
    bind(p.depth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
    bind(p.normals, *resources.texture(Resource::Normals));
    bind(p.surface, surface, ImageAccess::Write);
    dispatch(p.program, e, Barrier::ComputeRead);
    return surface;
}

Extent GtaoPass::surfacePyramidExtent(Extent full) noexcept {
    // Level 0 at the origin; levels 1-4 in a column to its right, in bands of the height rounded up to 16
    // rows (gtao_pyramid.h.glsl surfaceLevelOrigin): the last ends above the rounded height's 15/16.
    const int band = (full.height + 15) & ~15;
    return {full.width + ((full.width - 1) >> 1) + 1, std::max(full.height, band - (band >> kSurfaceLevels))};
}

const GtaoPass::SearchProgram& GtaoPass::searchProgram(EffectQuality quality, int scale, bool mips) {
    const glm::ivec2 tier = slicesAndSteps(quality);
    return mSearch.get((std::size_t(quality) * 2 + std::size_t(scale - 1)) * 2 + (mips ? 1 : 0),
                       gtaoDefines({{"GTAO_SLICES", std::to_string(tier.x)},
                                    {"GTAO_STEPS", std::to_string(tier.y)},
                                    {"GTAO_SCALE", std::to_string(scale)},
                                    {"GTAO_SAMPLE_MIPS", mips ? "1" : "0"}}));
}

void GtaoPass::search(const Texture& surface, const Texture& raw, EffectQuality quality, int scale, bool mips,
                      double bytes, GpuTimers* timers) {
    ScopedGpuTimer timer(timers, "gtao", bytes);
    const SearchProgram& program = searchProgram(quality, scale, mips);
    program.program.use();
    bind(program.surface, surface, ImageAccess::Read);
    bind(program.raw, raw, ImageAccess::Write);
    dispatch(program.program, raw.extent(), Barrier::ImageAccess);
}

void GtaoPass::denoise(const Texture& surface, const Texture& raw, const Texture& out, int scale,
                       double bytes, GpuTimers* timers) {
    ScopedGpuTimer timer(timers, "gtao denoise", bytes);
    const DenoiseProgram& d = scale == 2 ? mDenoiseHalf : mDenoiseFull;
    d.program.use();
    bind(d.surface, surface, ImageAccess::Read);
    bind(d.raw, raw, ImageAccess::Read);
    bind(d.out, out, ImageAccess::Write);
    dispatch(d.program, out.extent(), Barrier::None);
}

AoMultiplyPass::AoMultiplyPass()
    : mProgram(makeComputeProgram("passes/gtao/ao_multiply.comp.glsl", bindingDefines()))
    , mParameters("ao multiply parameters") {}

std::span<const ResourceUse> AoMultiplyPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::AmbientOcclusion, Access::Read},
                                            {Resource::SceneColor, Access::Write}};
    return kUses;
}

bool AoMultiplyPass::enabled(const FrameContext& ctx) const {
    return ctx.hdr && ctx.settings.gtao.enabled && ctx.settings.gtao.apply == GtaoApply::Multiply;
}

void AoMultiplyPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const Texture& out =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with ao"})
            .texture();
    ScopedGpuTimer timer(ctx.timers, "ao multiply", double(e.width) * e.height * (8 + 2 + 8));
    mParameters.update({.power = ctx.settings.gtao.power});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    bind(mScene, *resources.texture(Resource::SceneColor));
    bind(mVisibility, *resources.texture(Resource::AmbientOcclusion));
    bind(mOut, out, ImageAccess::Write);
    dispatch(mProgram, e, Barrier::None);
    resources.bind(Resource::SceneColor, out);
}

} // namespace photopic
