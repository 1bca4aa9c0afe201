#pragma once
// Display-domain effects in one pass (after tone mapping; fused because full-resolution traffic is the cost):
// chromatic aberration, lens flare composite, dazzle, vignette and grain on the tone-mapped display image,
// one read and one write.
// Tests: tests/gl/test_display_effects.cpp, tests/gl/test_display_bit_depth.cpp.

#include "passes/DisplayProgram.h"
#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>

namespace photopic {

/// std140 mirror of display_effects.comp.glsl's parameter block.
struct DisplayEffectsParameters {
    float texel[2] = {0.0f, 0.0f}; ///< 1 / size
    float chromaticAberration = 0.0f;
    std::int32_t flare = 0;
    std::int32_t dazzle = 0;
    float dazzleStrength = 0.0f;
    float dazzleRangeEV = 0.0f;
    std::int32_t vignette = 0;
    float vignetteIntensity = 0.0f;
    float vignetteFalloff = 0.0f;
    std::int32_t grain = 0;
    float grainIntensity = 0.0f;
    std::uint32_t frame = 0;
    std::uint32_t padding[3] = {};
};
static_assert(sizeof(DisplayEffectsParameters) == 64);
static_assert(offsetof(DisplayEffectsParameters, chromaticAberration) == 8 &&
              offsetof(DisplayEffectsParameters, dazzle) == 16 &&
              offsetof(DisplayEffectsParameters, vignette) == 28 &&
              offsetof(DisplayEffectsParameters, grainIntensity) == 44 &&
              offsetof(DisplayEffectsParameters, frame) == 48);

class DisplayEffectsPass final : public FramePass {
public:
    DisplayEffectsPass();
    [[nodiscard]] std::string_view name() const override { return "display effects"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// Any of its effects is on (the lens flare counts when its own pass can run).
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    /// Builds the program for output.bitDepth ahead of the first frame; throws GlError with the log.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    DisplayProgram mProgram;
    SamplerSlot mDisplay = mProgram.sampler("uDisplay");
    SamplerSlot mFlare = mProgram.sampler("uFlareTex");
    SamplerSlot mGlare = mProgram.sampler("uGlareTex");
    ImageSlot mOutput = mProgram.image("uOutput");
    ParameterBlock<DisplayEffectsParameters> mParameters;
    Texture mBlack; ///< bound where an optional input is absent, so every sampler has a complete texture
};

} // namespace photopic
