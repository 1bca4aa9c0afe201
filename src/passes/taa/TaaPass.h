#pragma once
// Temporal anti-aliasing: this frame's jittered samples resolved with the reprojected history, in the HDR
// domain before metering (the image the exposure reads is the anti-aliased one). The resolve replaces
// sceneColor and keeps itself, with each pixel's depth, as next frame's history.

#include "passes/FramePass.h"
#include "passes/HistoryTexture.h"

namespace photopic {

class TaaPass final : public FramePass {
public:
    TaaPass();
    [[nodiscard]] std::string_view name() const override { return "taa"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void resize(Extent extent) override;
    void invalidateHistory() override {
        mHistory.invalidate();
        mHistoryAux.invalidate();
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// TAA runs on the HDR path when aa.mode (or taa.enabled) selects it.
    [[nodiscard]] static bool selected(const Settings& settings) noexcept;

private:
    Program mProgram;
    HistoryTexture mHistory;    ///< the resolved colour
    HistoryTexture mHistoryAux; ///< per pixel: linear depth and stability (how long it has held still)
    Texture mNoDebug;           ///< bound to the debug image unit when no debug view asks for it
};

} // namespace photopic
