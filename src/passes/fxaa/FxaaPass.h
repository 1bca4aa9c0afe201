#pragma once
// FXAA 3.11 (quality path) on the display-referred image (RGBA8 or RGBA16), after tone mapping: anti-aliasing
// judges edges by perceived contrast, which display-referred values carry.
// Tests: tests/gl/test_display_effects.cpp, tests/gl/test_smaa.cpp (FXAA beside SMAA).

#include "passes/DisplayProgram.h"
#include "passes/FramePass.h"

#include <cstddef>

namespace photopic {

/// std140 mirror of fxaa.comp.glsl's parameter block.
struct FxaaParameters {
    float texel[2] = {0.0f, 0.0f}; ///< 1 / size
    float subpix = 0.75f;
    float edgeThreshold = 0.166f;
    float edgeThresholdMin = 0.0833f;
    float padding[3] = {};
};
static_assert(sizeof(FxaaParameters) == 32);
static_assert(offsetof(FxaaParameters, subpix) == 8 && offsetof(FxaaParameters, edgeThreshold) == 12 &&
              offsetof(FxaaParameters, edgeThresholdMin) == 16);

class FxaaPass final : public FramePass {
public:
    FxaaPass();
    [[nodiscard]] std::string_view name() const override { return "fxaa"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.tier.fxaa && ctx.settings.antiAliasing() == AntiAliasing::Fxaa;
    }
    /// Builds the program for output.bitDepth ahead of the first frame; throws GlError with the log.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    DisplayProgram mProgram;
    SamplerSlot mInput = mProgram.sampler("uInput");
    ImageSlot mOutput = mProgram.image("uOutput");
    ParameterBlock<FxaaParameters> mParameters;
};

} // namespace photopic
