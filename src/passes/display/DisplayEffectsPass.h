#pragma once
// Display-domain effects in one pass (after tone mapping; fused because full-resolution traffic is the cost):
// chromatic aberration, lens flare composite, dazzle, vignette and grain on the tone-mapped RGBA8 image, one
// read and one write.

#include "passes/FramePass.h"

namespace photopic {

class DisplayEffectsPass final : public FramePass {
public:
    DisplayEffectsPass();
    [[nodiscard]] std::string_view name() const override { return "display effects"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// Any of its effects is on (the lens flare counts when its own pass can run).
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    VertexArray mVao;
    Texture mBlack; ///< bound where an optional input is absent, so every sampler has a complete texture
};

} // namespace photopic
