#pragma once
// Post lens flare (a lens artefact, so added in the display domain): thresholded, downsampled exposed HDR ->
// ghosts + halo, an HDR buffer the display-effects pass adds in the display domain. Independent of bloom and
// its settings.
// Tests: tests/gl/test_display_effects.cpp.

#include "passes/lensflare/LensFlareSettings.h"
#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>

namespace photopic {

// Two blocks, one per program: each program's block holds only what it reads, and each draw has its own
// buffer, so neither is rewritten between the two draws.

/// std140 mirror of lensflare_prefilter.comp.glsl's parameter block.
struct LensFlarePrefilterParameters {
    float targetTexel[2] = {0.0f, 0.0f}; ///< 1 / flare buffer size
    float sourceStep[2] = {0.0f, 0.0f};  ///< UV offset of the 4 taps: a quarter of a target texel
    float threshold = 0.0f;
    float padding[3] = {};
};
static_assert(sizeof(LensFlarePrefilterParameters) == 32);
static_assert(offsetof(LensFlarePrefilterParameters, sourceStep) == 8 &&
              offsetof(LensFlarePrefilterParameters, threshold) == 16);

/// std140 mirror of lensflare_features.comp.glsl's parameter block.
struct LensFlareFeaturesParameters {
    float targetTexel[2] = {0.0f, 0.0f}; ///< 1 / flare buffer size
    std::int32_t ghosts = 0;
    float ghostSpacing = 0.0f;
    float haloRadius = 0.0f;
    float intensity = 0.0f;
    float aspect = 1.0f; ///< width / height
    float padding = 0.0f;
};
static_assert(sizeof(LensFlareFeaturesParameters) == 32);
static_assert(offsetof(LensFlareFeaturesParameters, ghosts) == 8 &&
              offsetof(LensFlareFeaturesParameters, haloRadius) == 16 &&
              offsetof(LensFlareFeaturesParameters, aspect) == 24);

class LensFlarePass final : public FramePass {
public:
    struct Inputs {
        const Texture* scene = nullptr;        ///< sanitised scene-referred colour
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const LensFlareSettings* settings = nullptr;
        int divisor = 4; ///< the flare buffers are the scene / this (the quality tier decides)
        GpuTimers* timers = nullptr;
    };
    LensFlarePass();
    [[nodiscard]] std::string_view name() const override { return "lens flare"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.tier.lensFlare && ctx.settings.lensFlare.enabled;
    }
    void resize(Extent extent) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    const Texture& execute(const Inputs& in);

private:
    void ensureTargets(int divisor);

    Program mPrefilter;
    Program mFeatures;
    SamplerSlot mPrefilterScene = mPrefilter.sampler("uScene");
    ImageSlot mPrefilterTarget = mPrefilter.image("uTarget");
    SamplerSlot mFeaturesSource = mFeatures.sampler("uSource");
    ImageSlot mFeaturesTarget = mFeatures.image("uTarget");
    ParameterBlock<LensFlarePrefilterParameters> mPrefilterParameters;
    ParameterBlock<LensFlareFeaturesParameters> mFeaturesParameters;
    Extent mExtent;
    int mDivisor = 0;
    Texture mSource, mFlare;
};

} // namespace photopic
