#include "passes/fxaa/FxaaPass.h"

#include "passes/Bindings.h"

namespace photopic {

namespace {
constexpr ResourceUse kUses[] = {{Resource::DisplayColor, Access::Read},
                                 {Resource::DisplayColor, Access::Write}};
} // namespace

FxaaPass::FxaaPass()
    : mProgram(makeComputeProgram("passes/fxaa/fxaa.comp.glsl", bindingDefines()))
    , mParameters("fxaa parameters") {}

std::span<const ResourceUse> FxaaPass::uses() const {
    return kUses;
}

void FxaaPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Texture& display = *resources.texture(Resource::DisplayColor);
    PooledTexture& out =
        resources.pool().acquire({.extent = ctx.extent, .format = GL_RGBA8, .debugName = "fxaa output"});
    const Extent e = ctx.extent;
    const FxaaSettings& s = ctx.settings.fxaa;
    // One RGBA8 read (the 3x3 and the searches hit the cache) and one RGBA8 write.
    ScopedGpuTimer timer(ctx.timers, "fxaa", double(e.width) * e.height * 8.0);
    mParameters.update({.texel = {1.0f / float(e.width), 1.0f / float(e.height)},
                        .subpix = s.subpix,
                        .edgeThreshold = s.edgeThreshold,
                        .edgeThresholdMin = s.edgeThresholdMin});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    glBindTextureUnit(0, display.id());
    glBindImageTexture(0, out.texture().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glDispatchCompute(GLuint((e.width + 7) / 8), GLuint((e.height + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    resources.bind(Resource::DisplayColor, out.texture());
}

} // namespace photopic
