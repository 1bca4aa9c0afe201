#pragma once
// Debug views (settings `debug.view`). Scene-value views (exposure false colour, luma, EV, metering weights,
// bloom) and the 3D input views (depth, normals, motion) replace the image before tone mapping and are shown
// as they are. The histogram is an overlay over the tone-mapped image, drawn from the GPU histogram buffer,
// by HistogramOverlayPass.

#include "core/Settings.h"
#include "passes/FramePass.h"

namespace photopic {

class DebugViewPass final : public FramePass {
public:
    DebugViewPass();
    [[nodiscard]] std::string_view name() const override { return "debug view"; }
    /// Depends on the view: the 3D views require their input, the others the scene and its metering.
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return isSceneView(ctx.settings.debug.view);
    }
    void configure(const Settings& settings) override { mView = settings.debug.view; }
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// True for the views that replace the scene before tone mapping.
    [[nodiscard]] static bool isSceneView(DebugView view) {
        return view != DebugView::None && view != DebugView::Histogram;
    }

private:
    void drawSceneView(const FrameContext& ctx, const FrameResources& resources);
    void drawInputView(const FrameContext& ctx, const FrameResources& resources);

    Program mSceneProgram;
    Program mInputProgram;
    VertexArray mVao;
    DebugView mView = DebugView::None;
};

class HistogramOverlayPass final : public FramePass {
public:
    HistogramOverlayPass();
    [[nodiscard]] std::string_view name() const override { return "histogram overlay"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.debug.view == DebugView::Histogram;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    VertexArray mVao;
};

} // namespace photopic
