#include "passes/fxaa/FxaaPass.h"

#include "passes/Bindings.h"

namespace photopic {

namespace {
constexpr ResourceUse kUses[] = {{Resource::DisplayColor, Access::Read},
                                 {Resource::DisplayColor, Access::Write}};
} // namespace

FxaaPass::FxaaPass()
    : mProgram(makeGraphicsProgram("passes/common/fullscreen.vert.glsl", "passes/fxaa/fxaa.frag.glsl",
                                   bindingDefines()))
    , mParameters("fxaa parameters")
    , mVao(VertexArray::create("fxaa fullscreen")) {}

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
    out.framebuffer().bind();
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    resources.bind(Resource::DisplayColor, out.texture());
}

} // namespace photopic
