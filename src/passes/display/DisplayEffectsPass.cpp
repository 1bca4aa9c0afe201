#include "passes/display/DisplayEffectsPass.h"

#include "passes/Bindings.h"

namespace photopic {

DisplayEffectsPass::DisplayEffectsPass()
    : mProgram("passes/display/display_effects.comp.glsl", {})
    , mParameters("display effects parameters")
    , mBlack({.extent = {1, 1}, .format = GL_RGBA16F, .debugName = "black texel"}) {
    const float black[4] = {0, 0, 0, 1};
    mBlack.uploadRgba32f(black);
}

std::span<const ResourceUse> DisplayEffectsPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::DisplayColor, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::LensFlare, Access::ReadOptional},
                                            {Resource::Bloom, Access::ReadOptional},
                                            {Resource::DisplayColor, Access::Write}};
    return kUses;
}

bool DisplayEffectsPass::enabled(const FrameContext& ctx) const {
    const Settings& s = ctx.settings;
    const bool flare = ctx.hdr && ctx.tier.lensFlare && s.lensFlare.enabled;
    return flare || (ctx.tier.grain && s.grain.enabled) || s.vignette.enabled || s.dazzle.enabled;
}

void DisplayEffectsPass::configure(const Settings& settings) {
    mProgram.prepare(settings.output.bitDepth);
}

void DisplayEffectsPass::execute(FrameContext& ctx, FrameResources& resources) {
    const Texture& display = *resources.texture(Resource::DisplayColor);
    const Texture* flare = resources.texture(Resource::LensFlare);
    const Texture* glare = resources.texture(Resource::Bloom);
    const int bitDepth = ctx.settings.output.bitDepth;
    const GLenum format = displayFormat(bitDepth);
    PooledTexture& out = resources.pool().acquire(
        {.extent = ctx.extent, .format = format, .debugName = "display effects output"});
    const Settings& s = ctx.settings;
    const Extent e = ctx.extent;
    double bytes = double(e.width) * e.height * 2.0 * bytesPerTexel(format);
    for (const Texture* t : {flare, glare}) {
        if (t) {
            bytes += double(t->extent().width) * t->extent().height * bytesPerTexel(t->format());
        }
    }
    ScopedGpuTimer timer(ctx.timers, "flare + dazzle + vignette + grain", bytes);
    const VignetteSettings& v = s.vignette;
    const bool grain = ctx.tier.grain && s.grain.enabled;
    mParameters.update(
        {.texel = {1.0f / float(e.width), 1.0f / float(e.height)},
         .chromaticAberration = v.enabled && ctx.tier.chromaticAberration ? v.chromaticAberration : 0.0f,
         .flare = flare ? 1 : 0,
         .dazzle = s.dazzle.enabled ? 1 : 0,
         .dazzleStrength = s.dazzle.strength,
         .dazzleRangeEV = s.dazzle.rangeEV,
         .vignette = v.enabled ? 1 : 0,
         .vignetteIntensity = v.intensity,
         .vignetteFalloff = v.falloff,
         .grain = grain ? 1 : 0,
         .grainIntensity = s.grain.intensity,
         .frame = std::uint32_t(ctx.time.frameIndex)});
    mParameters.bind(kBindingParameters);
    const Program& program = mProgram.at(bitDepth);
    program.use();
    bindExposureStateForReading(*resources.buffer(Resource::ExposureState));
    bind(mDisplay, display);
    bind(mFlare, flare ? *flare : mBlack);
    bind(mGlare, glare ? *glare : mBlack);
    bind(mOutput, out.texture(), ImageAccess::Write);
    dispatch(program, e, Barrier::ImageWrite);
    resources.bind(Resource::DisplayColor, out.texture());
}

} // namespace photopic
