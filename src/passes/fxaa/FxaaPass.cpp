#include "passes/fxaa/FxaaPass.h"

#include "passes/Bindings.h"

namespace photopic {

namespace {
constexpr ResourceUse kUses[] = {{Resource::DisplayColor, Access::Read},
                                 {Resource::DisplayColor, Access::Write}};
} // namespace

FxaaPass::FxaaPass()
    : mProgram("passes/fxaa/fxaa.comp.glsl", {})
    , mParameters("fxaa parameters") {}

std::span<const ResourceUse> FxaaPass::uses() const {
    return kUses;
}

void FxaaPass::configure(const Settings& settings) {
    mProgram.prepare(settings.output.bitDepth);
}

void FxaaPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Texture& display = *resources.texture(Resource::DisplayColor);
    const int bitDepth = ctx.settings.output.bitDepth;
    const GLenum format = displayFormat(bitDepth);
    PooledTexture& out =
        resources.pool().acquire({.extent = ctx.extent, .format = format, .debugName = "fxaa output"});
    const Extent e = ctx.extent;
    const FxaaSettings& s = ctx.settings.fxaa;
    // One display read (the 3x3 and the searches hit the cache) and one display write.
    ScopedGpuTimer timer(ctx.timers, "fxaa", double(e.width) * e.height * 2.0 * bytesPerTexel(format));
    mParameters.update({.texel = {1.0f / float(e.width), 1.0f / float(e.height)},
                        .subpix = s.subpix,
                        .edgeThreshold = s.edgeThreshold,
                        .edgeThresholdMin = s.edgeThresholdMin});
    mParameters.bind(kBindingParameters);
    const Program& program = mProgram.at(bitDepth);
    program.use();
    bind(mInput, display);
    bind(mOutput, out.texture(), ImageAccess::Write);
    dispatch(program, e, Barrier::ImageWrite);
    resources.bind(Resource::DisplayColor, out.texture());
}

} // namespace photopic
