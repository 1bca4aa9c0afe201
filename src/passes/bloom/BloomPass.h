#pragma once
// HDR bloom on exposed colour (after metering, so the frame's exposure is known; docs/architecture.md):
// prefilter + 13-tap downsample chain, tent upsample chain. The result is the bloom image at the size of
// level 0 (half or a quarter of the scene); the tone-map pass composites it (energy-conserving mix or
// threshold add).

#include "core/settings/BloomSettings.h"
#include "passes/FramePass.h"

#include <vector>

namespace photopic {

class BloomPass final : public FramePass {
public:
    struct Inputs {
        const Texture* scene = nullptr;        ///< sanitised scene-referred colour (not yet exposed)
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const BloomSettings* settings = nullptr;
        int firstDivisor = 2; ///< level 0 is the scene / this (2 or 4; the quality tier decides)
        int mipCount = 6;     ///< levels wanted (fewer when the image is small)
        GpuTimers* timers = nullptr;
    };
    BloomPass();
    [[nodiscard]] std::string_view name() const override { return "bloom"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// The HDR path's chain (the LDR path's glow is part of the tone-map pass).
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.tier.bloom && ctx.settings.bloom.enabled;
    }
    void resize(Extent extent) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    const Texture& execute(const Inputs& in);
    /// Levels of the chain the last execute ran.
    [[nodiscard]] int levels() const { return mLevels; }

private:
    void ensureChain(int firstDivisor, int levels);

    Program mPrefilter; ///< level 0: exposure, Karis average, threshold
    Program mDownsample;
    Program mUpsample;
    VertexArray mVao;
    Extent mExtent;
    int mDivisor = 0;
    int mLevels = 0;
    std::vector<Texture> mDown, mUp;
    std::vector<Framebuffer> mDownFbo, mUpFbo;
};

} // namespace photopic
