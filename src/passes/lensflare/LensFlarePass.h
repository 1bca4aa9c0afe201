#pragma once
// Post lens flare (a lens artefact, so added in the display domain): thresholded, downsampled exposed HDR ->
// ghosts + halo, an HDR buffer the display-effects pass adds in the display domain. Independent of bloom and
// its settings.

#include "core/settings/DisplaySettings.h"
#include "passes/FramePass.h"

namespace photopic {

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
    VertexArray mVao;
    Extent mExtent;
    int mDivisor = 0;
    Texture mSource, mFlare;
    Framebuffer mSourceFbo, mFlareFbo;
};

} // namespace photopic
