#include "passes/tonemap/TonemapPass.h"

#include "core/ColorGrading.h"
#include "passes/Bindings.h"

#include <glm/gtc/type_ptr.hpp>

namespace photopic {

namespace {
constexpr const char* kVertex = "passes/common/fullscreen.vert.glsl";
constexpr const char* kFragment = "passes/tonemap/tonemap.frag.glsl";
} // namespace

TonemapPass::TonemapPass()
    : mDisplayProgram{makeGraphicsProgram(kVertex, kFragment, bindingDefines()),
                      makeGraphicsProgram(kVertex, kFragment, bindingDefines({{"BLOOM", "1"}}))}
    , mSceneProgram{makeGraphicsProgram(kVertex, kFragment, bindingDefines({{"OUTPUT_SCENE", "1"}})),
                    makeGraphicsProgram(kVertex, kFragment,
                                        bindingDefines({{"OUTPUT_SCENE", "1"}, {"BLOOM", "1"}}))}
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
    if (in.bloom) {
        const Extent b = in.bloom->extent();
        setUniform(program, "uBloomTexel", 1.0f / float(b.width), 1.0f / float(b.height));
        setUniform(program, "uBloomAdditive", in.bloomSettings->mode == BloomMode::Threshold ? 1 : 0);
        setUniform(program, "uBloomIntensity", in.bloomSettings->intensity);
        glBindTextureUnit(1, in.bloom->id());
    }
    const bool grade = in.grading && in.grading->enabled;
    setUniform(program, "uGrade", grade ? 1 : 0);
    if (grade) {
        const ColorGradingSettings& g = *in.grading;
        const glm::mat3 wb = whiteBalanceMatrix(g.temperature, g.tint);
        glProgramUniformMatrix3fv(program.id(), glGetUniformLocation(program.id(), "uWhiteBalance"), 1,
                                  GL_FALSE, glm::value_ptr(wb));
        setUniform(program, "uContrast", g.contrast);
        setUniform(program, "uSaturation", g.saturation);
        setUniform(program, "uLift", g.lift.x, g.lift.y, g.lift.z);
        setUniform(program, "uInvGamma", 1.0f / g.gamma.x, 1.0f / g.gamma.y, 1.0f / g.gamma.z);
        setUniform(program, "uGain", g.gain.x, g.gain.y, g.gain.z);
    }
    program.use();
    glBindTextureUnit(0, in.scene->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

const Texture& TonemapPass::execute(const Inputs& in) {
    const Extent e = mDisplay.extent();
    DebugGroup group("tonemap");
    double bytes = double(e.width) * e.height * (bytesPerTexel(in.scene->format()) + 4);
    if (in.bloom) {
        bytes +=
            double(in.bloom->extent().width) * in.bloom->extent().height * bytesPerTexel(in.bloom->format());
    }
    ScopedGpuTimer timer(in.timers, "composite + grade + tonemap", bytes);
    mDisplayFbo.bind();
    draw(mDisplayProgram[in.bloom ? 1 : 0], in);
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
    draw(mSceneProgram[in.bloom ? 1 : 0], in);
    return mScene;
}

} // namespace photopic
