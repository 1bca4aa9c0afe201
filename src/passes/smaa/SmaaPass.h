#pragma once
// SMAA 1x (Jimenez et al. 2012) on the display-referred RGBA8 image, after tone mapping, in FXAA's place:
// luma edges with local contrast adaptation, blending weights from orthogonal and diagonal pattern searches
// with corner rounding, and neighbourhood blending. Three compute dispatches; the edges and weights are
// pooled transients, the area and search tables (core/SmaaTextures.h) are uploaded once.

#include "passes/FramePass.h"

namespace photopic {

class SmaaPass final : public FramePass {
public:
    SmaaPass();
    [[nodiscard]] std::string_view name() const override { return "smaa"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        const AntiAliasing aa = ctx.settings.antiAliasing();
        return aa == AntiAliasing::Smaa || aa == AntiAliasing::TaaSmaa;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// The tables as the GPU holds them (tests compare them with the CPU generator).
    [[nodiscard]] const Texture& orthogonalAreaTexture() const { return mAreaOrtho; }
    [[nodiscard]] const Texture& diagonalAreaTexture() const { return mAreaDiag; }
    [[nodiscard]] const Texture& searchTexture() const { return mSearch; }

private:
    Program mEdges;
    Program mWeights;
    Program mBlend;
    Texture mAreaOrtho;
    Texture mAreaDiag;
    Texture mSearch;
};

} // namespace photopic
