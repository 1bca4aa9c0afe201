#include "passes/smaa/SmaaPass.h"

#include "core/SmaaTextures.h"
#include "passes/Bindings.h"

namespace photopic {

namespace {

constexpr ResourceUse kUses[] = {{Resource::DisplayColor, Access::Read},
                                 {Resource::DisplayColor, Access::Write}};

GLuint groups(int size) {
    return GLuint((size + 7) / 8);
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

SmaaPass::SmaaPass()
    : mEdges(makeComputeProgram("passes/smaa/smaa_edges.comp.glsl", bindingDefines()))
    , mWeights(makeComputeProgram("passes/smaa/smaa_weights.comp.glsl", bindingDefines()))
    , mBlend(makeComputeProgram("passes/smaa/smaa_blend.comp.glsl", bindingDefines())) {
    const smaa::AreaTables& areas = smaa::areaTables();
    mAreaOrtho = makeTable(smaa::kOrthoSize, smaa::kOrthoSize, GL_RG8, GL_RG, GL_UNSIGNED_BYTE,
                           areas.ortho.data(), "smaa orthogonal area");
    mAreaDiag = makeTable(smaa::kDiagSize, smaa::kDiagSize, GL_RG8, GL_RG, GL_UNSIGNED_BYTE,
                          areas.diag.data(), "smaa diagonal area");
    mSearch = makeTable(smaa::kSearchWidth, smaa::kSearchHeight, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                        smaa::searchTable().data(), "smaa search");
}

std::span<const ResourceUse> SmaaPass::uses() const {
    return kUses;
}

void SmaaPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Extent e = ctx.extent;
    const double pixels = double(e.width) * e.height;
    const smaa::Preset preset = smaa::preset(int(ctx.settings.smaa.quality));
    const Texture& display = *resources.texture(Resource::DisplayColor);
    // The weights step fetches two edge pixels at once through bilinear filtering.
    const Texture& edges =
        resources.pool().acquire({.extent = e, .format = GL_RG8, .debugName = "smaa edges"}).texture();
    const Texture& weights = resources.pool()
                                 .acquire({.extent = e,
                                           .format = GL_RGBA8,
                                           .minFilter = GL_NEAREST,
                                           .magFilter = GL_NEAREST,
                                           .debugName = "smaa weights"})
                                 .texture();
    const Texture& out =
        resources.pool().acquire({.extent = e, .format = GL_RGBA8, .debugName = "smaa output"}).texture();
    {
        // Five RGBA8 reads (cached) and one RG8 write per pixel.
        ScopedGpuTimer timer(ctx.timers, "smaa edges", pixels * 6.0);
        setUniform(mEdges, "uThreshold", preset.threshold);
        setUniform(mEdges, "uContrastFactor", preset.contrastFactor);
        mEdges.use();
        glBindTextureUnit(0, display.id());
        glBindImageTexture(0, edges.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG8);
        glDispatchCompute(groups(e.width), groups(e.height), 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // Edge pixels search; the rest read their RG8 texel and write RGBA8.
        ScopedGpuTimer timer(ctx.timers, "smaa weights", pixels * 6.0);
        setUniform(mWeights, "uSearchSteps", preset.searchSteps);
        setUniform(mWeights, "uDiagSteps", preset.diagonalSteps);
        setUniform(mWeights, "uCornerRounding",
                   preset.cornerRounding > 0.0f ? preset.cornerRounding / 100.0f : 1.0f);
        mWeights.use();
        glBindTextureUnit(0, edges.id());
        glBindTextureUnit(1, mAreaOrtho.id());
        glBindTextureUnit(2, mAreaDiag.id());
        glBindTextureUnit(3, mSearch.id());
        glBindImageTexture(0, weights.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glDispatchCompute(groups(e.width), groups(e.height), 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // RGBA8 colour and weights in (the neighbours hit the cache), RGBA8 out.
        ScopedGpuTimer timer(ctx.timers, "smaa blend", pixels * 12.0);
        mBlend.use();
        glBindTextureUnit(0, display.id());
        glBindTextureUnit(1, weights.id());
        glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glDispatchCompute(groups(e.width), groups(e.height), 1);
    }
    for (GLuint unit = 0; unit < 4; ++unit) {
        glBindTextureUnit(unit, 0);
    }
    resources.bind(Resource::DisplayColor, out);
}

} // namespace photopic
