#include "passes/sanitize/SanitizePass.h"

#include "passes/Bindings.h"

namespace photopic {

SanitizePass::SanitizePass()
    : mProgram(makeComputeProgram("passes/sanitize/sanitize.comp.glsl", bindingDefines())) {}

void SanitizePass::resize(Extent extent) {
    if (mOutput.valid() && mOutput.extent() == extent) {
        return;
    }
    mOutput = Texture({.extent = extent, .format = GL_RGBA16F, .debugName = "sanitized colour"});
}

const Texture& SanitizePass::execute(const Inputs& in) {
    const Extent e = mOutput.extent();
    const double bytes = double(e.width) * e.height * (bytesPerTexel(in.color->format()) + 8);
    DebugGroup group("sanitize");
    ScopedGpuTimer timer(in.timers, "sanitize", bytes);
    mProgram.use();
    glBindTextureUnit(0, in.color->id());
    glBindImageTexture(0, mOutput.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glDispatchCompute(GLuint((e.width + 7) / 8), GLuint((e.height + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    return mOutput;
}

} // namespace photopic
