#include "passes/tonemap/TonemapPass.h"

#include "passes/Bindings.h"

namespace photopic {

namespace {
constexpr const char* kVertex = "passes/common/fullscreen.vert.glsl";
constexpr const char* kFragment = "passes/tonemap/tonemap.frag.glsl";
} // namespace

TonemapPass::TonemapPass()
    : mDisplayProgram(makeGraphicsProgram(kVertex, kFragment, bindingDefines()))
    , mSceneProgram(makeGraphicsProgram(kVertex, kFragment, bindingDefines({{"OUTPUT_SCENE", "1"}})))
    , mVao(VertexArray::create("fullscreen")) {}

void TonemapPass::resize(Extent extent) {
    if (mDisplay.valid() && mDisplay.extent() == extent) {
        return;
    }
    mDisplay = Texture({.extent = extent, .format = GL_RGBA8, .debugName = "display"});
    mDisplayFbo = Framebuffer(mDisplay, 0, "display");
    mScene = {};
    mSceneFbo = {};
}

void TonemapPass::draw(const Program& program, const Inputs& in) {
    setUniform(program, "uMode", int(in.tonemapping->mode));
    setUniform(program, "uWhitePoint", in.tonemapping->whitePoint);
    setUniform(program, "uAgxLook", int(in.tonemapping->agxLook));
    setUniform(program, "uDither", in.output->dither ? 1 : 0);
    glProgramUniform1ui(program.id(), glGetUniformLocation(program.id(), "uFrame"), GLuint(in.frameIndex));
    program.use();
    glBindTextureUnit(0, in.scene->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

const Texture& TonemapPass::execute(const Inputs& in) {
    const Extent e = mDisplay.extent();
    DebugGroup group("tonemap");
    ScopedGpuTimer timer(in.timers, "tonemap",
                         double(e.width) * e.height * (bytesPerTexel(in.scene->format()) + 4));
    mDisplayFbo.bind();
    draw(mDisplayProgram, in);
    return mDisplay;
}

const Texture& TonemapPass::renderScene(const Inputs& in) {
    if (!mScene.valid()) {
        mScene = Texture(
            {.extent = mDisplay.extent(), .format = GL_RGBA32F, .debugName = "scene-referred output"});
        mSceneFbo = Framebuffer(mScene, 0, "scene-referred output");
    }
    DebugGroup group("scene-referred output");
    mSceneFbo.bind();
    draw(mSceneProgram, in);
    return mScene;
}

} // namespace photopic
