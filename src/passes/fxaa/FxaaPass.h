#pragma once
// FXAA 3.11 (quality path) on the display-referred RGBA8 image, after tone mapping: anti-aliasing judges
// edges by perceived contrast, which display-referred values carry.

#include "passes/FramePass.h"

namespace photopic {

class FxaaPass final : public FramePass {
public:
    FxaaPass();
    [[nodiscard]] std::string_view name() const override { return "fxaa"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.tier.fxaa && ctx.settings.antiAliasing() == AntiAliasing::Fxaa;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    VertexArray mVao;
};

} // namespace photopic
