#include "passes/fxaa/FxaaPass.h"

#include "passes/Bindings.h"

namespace photopic {

FxaaPass::FxaaPass()
    : mProgram(makeGraphicsProgram("passes/common/fullscreen.vert.glsl", "passes/fxaa/fxaa.frag.glsl",
                                   bindingDefines()))
    , mVao(VertexArray::create("fxaa fullscreen")) {}

void FxaaPass::resize(Extent extent) {
    if (mOutput.valid() && mOutput.extent() == extent) {
        return;
    }
    mOutput = Texture({.extent = extent, .format = GL_RGBA8, .debugName = "fxaa output"});
    mFbo = Framebuffer(mOutput, 0, "fxaa output");
}

const Texture& FxaaPass::execute(const Inputs& in) {
    const Extent e = mOutput.extent();
    DebugGroup group("fxaa");
    // One RGBA8 read (the 3x3 and the searches hit the cache) and one RGBA8 write.
    ScopedGpuTimer timer(in.timers, "fxaa", double(e.width) * e.height * 8.0);
    setUniform(mProgram, "uTexel", 1.0f / float(e.width), 1.0f / float(e.height));
    setUniform(mProgram, "uSubpix", in.settings->subpix);
    setUniform(mProgram, "uEdgeThreshold", in.settings->edgeThreshold);
    setUniform(mProgram, "uEdgeThresholdMin", in.settings->edgeThresholdMin);
    mProgram.use();
    glBindTextureUnit(0, in.display->id());
    mFbo.bind();
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return mOutput;
}

} // namespace photopic
