#include "passes/outline/OutlinePass.h"

#include "passes/Bindings.h"

namespace photopic {

OutlinePass::OutlinePass()
    : mProgram(makeComputeProgram("passes/outline/outline.comp.glsl", bindingDefines()))
    , mParameters("outline parameters") {}

std::span<const ResourceUse> OutlinePass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::LinearDepth, Access::Read},
                                            {Resource::Normals, Access::ReadOptional},
                                            {Resource::SceneColor, Access::Write}};
    return kUses;
}

void OutlinePass::execute(FrameContext& ctx, FrameResources& resources) {
    const OutlineSettings& s = ctx.settings.outline;
    const Extent e = ctx.extent;
    const Texture& out =
        resources.pool()
            .acquire({.extent = e, .format = GL_RGBA16F, .debugName = "scene colour with outline"})
            .texture();
    const Texture* normals = resources.texture(Resource::Normals);
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    // Depth, the normals when given and the colour read once from memory (the neighbours hit the cache), the
    // colour out.
    ScopedGpuTimer timer(ctx.timers, "outline",
                         double(e.width) * e.height * (4.0 + (normals ? 8.0 : 0.0) + 16.0));
    mParameters.update({.color = glm::vec4(s.color, s.intensity),
                        .depthThreshold = s.depthThreshold,
                        .normalThreshold = s.normalThreshold,
                        .width = s.width,
                        .normals = normalsSource(ctx, resources)});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    bind(mScene, *resources.texture(Resource::SceneColor), ImageAccess::Read);
    bind(mDepth, depth, ImageAccess::Read);
    bind(mNormals, normals ? *normals : depth);
    bind(mOut, out, ImageAccess::Write);
    dispatch(mProgram, e, Barrier::None);
    resources.bind(Resource::SceneColor, out);
}

} // namespace photopic
