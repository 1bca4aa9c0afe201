#include "passes/sanitize/SanitizePass.h"

#include "passes/Bindings.h"

namespace photopic {

namespace {
constexpr ResourceUse kUses[] = {{Resource::Color, Access::Read}, {Resource::SceneColor, Access::Write}};
} // namespace

SanitizePass::SanitizePass()
    : mProgram(makeComputeProgram("passes/sanitize/sanitize.comp.glsl", bindingDefines())) {}

std::span<const ResourceUse> SanitizePass::uses() const {
    return kUses;
}

void SanitizePass::execute(FrameContext& ctx, FrameResources& resources) {
    const Texture& color = *resources.texture(Resource::Color);
    const Texture& out =
        resources.pool()
            .acquire({.extent = ctx.extent, .format = GL_RGBA16F, .debugName = "sanitized colour"})
            .texture();
    const Extent e = ctx.extent;
    const double bytes = double(e.width) * e.height * (bytesPerTexel(color.format()) + 8);
    ScopedGpuTimer timer(ctx.timers, "sanitize", bytes);
    mProgram.use();
    bind(mInput, color);
    bind(mOutput, out, ImageAccess::Write);
    dispatch(mProgram, e, Barrier::None);
    resources.bind(Resource::SceneColor, out);
}

} // namespace photopic
