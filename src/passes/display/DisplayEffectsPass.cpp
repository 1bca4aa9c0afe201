#include "passes/display/DisplayEffectsPass.h"

#include "passes/Bindings.h"

namespace photopic {

DisplayEffectsPass::DisplayEffectsPass()
    : mProgram(makeGraphicsProgram("passes/common/fullscreen.vert.glsl",
                                   "passes/display/display_effects.frag.glsl", bindingDefines()))
    , mVao(VertexArray::create("display effects fullscreen"))
    , mBlack({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "black texel"}) {
    const float black[4] = {0, 0, 0, 1};
    mBlack.uploadRgba32f(black);
}

void DisplayEffectsPass::resize(Extent extent) {
    if (mOutput.valid() && mOutput.extent() == extent) {
        return;
    }
    mOutput = Texture({.extent = extent, .format = GL_RGBA8, .debugName = "display effects output"});
    mFbo = Framebuffer(mOutput, 0, "display effects output");
}

const Texture& DisplayEffectsPass::execute(const Inputs& in) {
    const Extent e = mOutput.extent();
    double bytes = double(e.width) * e.height * 8.0;
    for (const Texture* t : {in.flare, in.glare}) {
        if (t) {
            bytes += double(t->extent().width) * t->extent().height * bytesPerTexel(t->format());
        }
    }
    DebugGroup group("display effects");
    ScopedGpuTimer timer(in.timers, "flare + dazzle + vignette + grain", bytes);
    const VignetteSettings& v = *in.vignette;
    setUniform(mProgram, "uTexel", 1.0f / float(e.width), 1.0f / float(e.height));
    setUniform(mProgram, "uChromaticAberration",
               v.enabled && in.chromaticAberration ? v.chromaticAberration : 0.0f);
    setUniform(mProgram, "uVignette", v.enabled ? 1 : 0);
    setUniform(mProgram, "uVignetteIntensity", v.intensity);
    setUniform(mProgram, "uVignetteFalloff", v.falloff);
    setUniform(mProgram, "uFlare", in.flare ? 1 : 0);
    setUniform(mProgram, "uDazzle", in.dazzle->enabled ? 1 : 0);
    setUniform(mProgram, "uDazzleStrength", in.dazzle->strength);
    setUniform(mProgram, "uDazzleRangeEV", in.dazzle->rangeEV);
    setUniform(mProgram, "uGrain", in.grain->enabled ? 1 : 0);
    setUniform(mProgram, "uGrainIntensity", in.grain->intensity);
    glProgramUniform1ui(mProgram.id(), glGetUniformLocation(mProgram.id(), "uFrame"), GLuint(in.frameIndex));
    mProgram.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindTextureUnit(0, in.display->id());
    glBindTextureUnit(1, in.flare ? in.flare->id() : mBlack.id());
    glBindTextureUnit(2, in.glare ? in.glare->id() : mBlack.id());
    mFbo.bind();
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return mOutput;
}

} // namespace photopic
