#include "passes/smaa/SmaaPass.h"

#include "core/SmaaTextures.h"
#include "passes/Bindings.h"

#include <cstddef>

namespace photopic {

namespace {

constexpr ResourceUse kDisplayUses[] = {{Resource::DisplayColor, Access::Read},
                                        {Resource::LinearDepth, Access::ReadOptional},
                                        {Resource::DisplayColor, Access::Write}};
constexpr ResourceUse kHdrUses[] = {{Resource::SceneColor, Access::Read},
                                    {Resource::ExposureState, Access::Read},
                                    {Resource::LinearDepth, Access::ReadOptional},
                                    {Resource::SceneColor, Access::Write}};

ShaderDefines domainVariant(SmaaPass::Domain domain) {
    return domain == SmaaPass::Domain::Hdr ? ShaderDefines{{"SMAA_HDR", "1"}} : ShaderDefines{};
}

ShaderDefines domainDefines(SmaaPass::Domain domain) {
    return bindingDefines(domainVariant(domain));
}

ShaderDefines depthDefines(SmaaPass::Domain domain) {
    ShaderDefines defines = domainVariant(domain);
    defines.emplace_back("SMAA_DEPTH", "1");
    return bindingDefines(defines);
}

constexpr int kTileSize = 8; // the edge and weights steps' work groups

Extent tileGrid(Extent e) {
    return {(e.width + kTileSize - 1) / kTileSize, (e.height + kTileSize - 1) / kTileSize};
}

Texture makeTable(int width, int height, GLenum internalFormat, GLenum format, GLenum type, const void* data,
                  std::string_view name) {
    Texture t({.extent = {width, height},
               .format = internalFormat,
               .minFilter = GL_NEAREST,
               .magFilter = GL_NEAREST,
               .debugName = name});
    // Rows of the search table are 66 bytes: tightly packed, not 4-aligned.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t.id(), 0, 0, 0, width, height, format, type, data);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return t;
}

} // namespace

SmaaPass::SmaaPass(Domain domain)
    : mDomain(domain)
    , mEdges(makeComputeProgram("passes/smaa/smaa_edges.comp.glsl", domainDefines(domain)))
    , mWeights(makeComputeProgram("passes/smaa/smaa_weights.comp.glsl", domainDefines(domain)))
    , mBlend("passes/smaa/smaa_blend.comp.glsl", domainVariant(domain))
    , mParameters("smaa parameters") {
    const smaa::AreaTables& areas = smaa::areaTables();
    mAreaOrtho = makeTable(smaa::kOrthoSize, smaa::kOrthoSize, GL_RG8, GL_RG, GL_UNSIGNED_BYTE,
                           areas.ortho.data(), "smaa orthogonal area");
    mAreaDiag = makeTable(smaa::kDiagSize, smaa::kDiagSize, GL_RG8, GL_RG, GL_UNSIGNED_BYTE,
                          areas.diag.data(), "smaa diagonal area");
    mSearch = makeTable(smaa::kSearchWidth, smaa::kSearchHeight, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                        smaa::searchTable().data(), "smaa search");
}

std::span<const ResourceUse> SmaaPass::uses() const {
    return mDomain == Domain::Display ? std::span<const ResourceUse>(kDisplayUses)
                                      : std::span<const ResourceUse>(kHdrUses);
}

void SmaaPass::configure(const Settings& settings) {
    if (mDomain == Domain::Display) {
        mBlend.prepare(settings.output.bitDepth);
    }
}

SmaaPass::Targets SmaaPass::acquireTargets(Extent e, GLenum colorFormat, FrameResources& resources) {
    TexturePool& pool = resources.pool();
    Targets t;
    // The weights step fetches two edge pixels at once through bilinear filtering.
    t.edges = &pool.acquire({.extent = e, .format = GL_RG8, .debugName = "smaa edges"}).texture();
    t.weights = &pool.acquireNearest(e, GL_RGBA8, "smaa weights");
    t.out = &pool.acquire({.extent = e, .format = colorFormat, .debugName = "smaa output"}).texture();
    return t;
}

void SmaaPass::resetTiles(Extent e) {
    const Extent grid = tileGrid(e);
    const std::size_t tiles = std::size_t(grid.width) * std::size_t(grid.height);
    const std::size_t bytes = sizeof(GpuSmaaTiles) + 4 * tiles * sizeof(std::uint32_t);
    if (mTiles.size() < bytes) {
        mTiles = Buffer({.size = bytes, .flags = 0, .debugName = "smaa tiles"});
    }
    // On the GPU: both dispatches (0, 1, 1) and both lists' flags zero.
    const std::uint32_t dispatchNone[4] = {0, 1, 1, 0};
    for (const std::size_t offset :
         {offsetof(GpuSmaaTiles, weightGroups), offsetof(GpuSmaaTiles, blendGroups)}) {
        mTiles.clearWords(offset, dispatchNone, 4);
    }
    glClearNamedBufferSubData(
        mTiles.id(), GL_R32UI, GLintptr(sizeof(GpuSmaaTiles) + 2 * tiles * sizeof(std::uint32_t)),
        GLsizeiptr(2 * tiles * sizeof(std::uint32_t)), GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingTileList, mTiles.id());
}

void SmaaPass::updateParameters(const FrameContext& ctx, bool hdr, bool blendAll) {
    const smaa::Preset preset = smaa::preset(int(ctx.settings.smaa.quality));
    const Extent grid = tileGrid(ctx.extent);
    // Under taa+smaa the sub-pixel ridges are TAA's to resolve: its jittered frames sample a thin line
    // without bias, and dimming each of them would take a third of the line away from the converged image.
    mParameters.update(
        {.threshold = preset.threshold,
         .contrastFactor = preset.contrastFactor,
         .cornerRounding = preset.cornerRounding > 0.0f ? preset.cornerRounding / 100.0f : 1.0f,
         .searchSteps = preset.searchSteps,
         .diagonalSteps = preset.diagonalSteps,
         .subpixel = hdr ? 0.0f : ctx.settings.smaa.subpixel,
         .tilesX = grid.width,
         .tileCount = grid.width * grid.height,
         .blendAll = blendAll ? 1 : 0});
    mParameters.bind(kBindingParameters);
}

void SmaaPass::detectEdges(const FrameContext& ctx, const FrameResources& resources, const Texture& color,
                           const Targets& t, const std::string& prefix) {
    const Extent e = ctx.extent;
    // A 3D host's linear depth marks the silhouettes; its program is compiled the first time a frame brings
    // one, so 2D hosts never pay for it.
    const Texture* depth = resources.texture(Resource::LinearDepth);
    if (depth && !mEdgesDepth) {
        mEdgesDepth.emplace(makeComputeProgram("passes/smaa/smaa_edges.comp.glsl", depthDefines(mDomain)));
    }
    // Up to ten colour reads per pixel (neighbours hit the cache), the depth's and one RG8 write; the tile
    // list's reset and appends (under a byte a pixel) are not counted.
    ScopedGpuTimer timer(
        ctx.timers, prefix + "edges",
        double(e.width) * e.height *
            (bytesPerTexel(t.out->format()) + (depth ? bytesPerTexel(depth->format()) : 0.0) + 2.0));
    resetTiles(e);
    const EdgesProgram& program = depth ? *mEdgesDepth : mEdges;
    program.program.use();
    bind(program.color, color);
    if (depth) {
        bind(program.depth, *depth, ImageAccess::Read);
    }
    bind(program.edges, *t.edges, ImageAccess::Write);
    dispatch(program.program, e, Barrier::IndirectDispatch);
}

void SmaaPass::blendingWeights(const FrameContext& ctx, const Targets& t, const std::string& prefix) {
    const Extent e = ctx.extent;
    // The listed tiles' pixels search (edge pixels) or read their RG8 texel and write RGBA8 (the rest); the
    // other tiles are cleared. Counted as every pixel: the list's length stays on the GPU.
    ScopedGpuTimer timer(ctx.timers, prefix + "weights", double(e.width) * e.height * 6.0);
    glClearTexImage(t.weights->id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    mWeights.use();
    bind(mWeightsEdges, *t.edges);
    bind(mWeightsAreaOrtho, mAreaOrtho, ImageAccess::Read);
    bind(mWeightsAreaDiag, mAreaDiag, ImageAccess::Read);
    bind(mWeightsSearch, mSearch, ImageAccess::Read);
    bind(mWeightsOut, *t.weights, ImageAccess::Write);
    dispatchIndirect(mWeights, mTiles.id(), GLintptr(offsetof(GpuSmaaTiles, weightGroups)),
                     Barrier::IndirectDispatch);
}

void SmaaPass::blend(const FrameContext& ctx, const Texture& color, const Targets& t, int bitDepth,
                     const std::string& prefix) {
    const Extent e = ctx.extent;
    // Colour, weights and edges in (the neighbours hit the cache), colour out; counted as if every tile
    // blended (the list's length stays on the GPU).
    ScopedGpuTimer timer(ctx.timers, prefix + "blend",
                         double(e.width) * e.height * (2.0 + bytesPerTexel(t.out->format()) + 6.0));
    const Program& program = mBlend.at(bitDepth);
    program.use();
    bind(mBlendColor, color);
    bind(mBlendWeights, *t.weights, ImageAccess::Read);
    bind(mBlendEdges, *t.edges, ImageAccess::Read);
    bind(mBlendOutput, *t.out, ImageAccess::Write);
    if (blendsAll(color, t)) {
        dispatch(program, e, Barrier::None);
        return;
    }
    // Pixels no weight or edge reaches keep their colour: the whole image copied, then the listed tiles
    // blended over it.
    t.out->copyLevel0From(color, e);
    dispatchIndirect(program, mTiles.id(), GLintptr(offsetof(GpuSmaaTiles, blendGroups)), Barrier::None);
}

bool SmaaPass::blendsAll(const Texture& color, const Targets& t) {
    return color.format() != t.out->format();
}

void SmaaPass::execute(FrameContext& ctx, FrameResources& resources) {
    const bool hdr = mDomain == Domain::Hdr;
    const Resource colorResource = hdr ? Resource::SceneColor : Resource::DisplayColor;
    const int bitDepth = hdr ? 8 : ctx.settings.output.bitDepth;
    const GLenum colorFormat = hdr ? GL_RGBA16F : displayFormat(bitDepth);
    const Texture& color = *resources.texture(colorResource);
    const Targets t = acquireTargets(ctx.extent, colorFormat, resources);
    updateParameters(ctx, hdr, blendsAll(color, t));
    if (hdr) {
        bindExposureStateForReading(*resources.buffer(Resource::ExposureState));
    }
    const std::string prefix = hdr ? "smaa (hdr) " : "smaa ";
    detectEdges(ctx, resources, color, t, prefix);
    blendingWeights(ctx, t, prefix);
    blend(ctx, color, t, bitDepth, prefix);
    // The weights step samples the edges on unit 0, the most of the three: none stays bound.
    unbind(mWeightsEdges);
    resources.bind(colorResource, *t.out);
}

} // namespace photopic
