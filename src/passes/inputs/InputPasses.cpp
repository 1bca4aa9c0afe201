#include "passes/inputs/InputPasses.h"

#include "core/Log.h"
#include "passes/Bindings.h"

namespace photopic {

LinearDepthPass::LinearDepthPass()
    : mProgram(makeComputeProgram("passes/inputs/linear_depth.comp.glsl", bindingDefines()))
    , mParameters("linear depth parameters") {}

std::span<const ResourceUse> LinearDepthPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::Depth, Access::Read},
                                            {Resource::Camera, Access::Read},
                                            {Resource::LinearDepth, Access::Write}};
    return kUses;
}

bool LinearDepthPass::enabled(const FrameContext& ctx) const {
    return ctx.inputs.depth != nullptr;
}

void LinearDepthPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Camera& camera = *ctx.inputs.camera;
    const Texture& out = resources.pool().acquireNearest(ctx.extent, GL_R32F, "linear depth");
    const Texture& depth = *resources.texture(Resource::Depth);
    ScopedGpuTimer timer(ctx.timers, "linear depth",
                         double(ctx.extent.width) * ctx.extent.height * (bytesPerTexel(depth.format()) + 4));
    mParameters.update({.kind = std::int32_t(ctx.inputs.depthKind),
                        .nearPlane = camera.nearPlane,
                        .farPlane = camera.farPlane});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    bind(mDepth, depth);
    bind(mLinear, out, ImageAccess::Write);
    dispatch(mProgram, ctx.extent, Barrier::None);
    resources.bind(Resource::LinearDepth, out);
}

CameraMotionPass::CameraMotionPass()
    : mProgram(makeComputeProgram("passes/inputs/camera_motion.comp.glsl", bindingDefines()))
    , mParameters("camera motion parameters") {}

std::span<const ResourceUse> CameraMotionPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::LinearDepth, Access::Read},
                                            {Resource::Camera, Access::Read},
                                            {Resource::Motion, Access::Write}};
    return kUses;
}

bool CameraMotionPass::enabled(const FrameContext& ctx) const {
    return ctx.inputs.motion == nullptr && ctx.inputs.depth != nullptr;
}

void CameraMotionPass::execute(FrameContext& ctx, FrameResources& resources) {
    try {
        warnOnce(
            "motion.reconstructed",
            "no motion vectors from the host: motion is reconstructed from depth and the camera, so objects "
            "that move on their own will ghost in temporal passes");
    } catch (...) { // logging must not take the frame down
    }
    const Camera& camera = *ctx.inputs.camera;
    const Texture& out = resources.pool().acquireNearest(ctx.extent, GL_RG16F, "camera motion");
    ScopedGpuTimer timer(ctx.timers, "camera motion", double(ctx.extent.width) * ctx.extent.height * 8);
    mParameters.update({.invProjection = glm::inverse(camera.projection),
                        .invView = glm::inverse(camera.view),
                        .prevViewProjection = camera.prevViewProjection,
                        .cut = camera.cut ? 1 : 0});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    bind(mLinearDepth, *resources.texture(Resource::LinearDepth));
    bind(mMotion, out, ImageAccess::Write);
    dispatch(mProgram, ctx.extent, Barrier::None);
    resources.bind(Resource::Motion, out);
}

} // namespace photopic
