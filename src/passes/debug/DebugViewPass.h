#pragma once
// Debug views (settings `debug.view`). Scene-value views (exposure false colour, luma, EV, metering weights,
// bloom), the 3D input views (depth, normals, motion) and the lighting stage's contact shadows replace the
// image before tone mapping and are shown as they are. The histogram is an overlay over the tone-mapped
// image, drawn from the GPU histogram buffer, by HistogramOverlayPass.
// Tests: tests/gl/test_debug_views.cpp.

#include "core/Settings.h"
#include "passes/DisplayProgram.h"
#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>

namespace photopic {

/// std140 mirror of debug_view.comp.glsl's parameter block (the scene views).
struct DebugSceneViewParameters {
    std::int32_t view = 0; ///< DebugView
    std::int32_t hasBloom = 0;
    std::int32_t hasMask = 0;
    std::int32_t meteringMode = 0;
    float log2Min = 0.0f;
    float log2Max = 0.0f;
    float spotUv[2] = {0.5f, 0.5f};
    float spotRadius = 0.0f;
    float padding[3] = {};
};
static_assert(sizeof(DebugSceneViewParameters) == 48);
static_assert(offsetof(DebugSceneViewParameters, log2Min) == 16 &&
              offsetof(DebugSceneViewParameters, spotUv) == 24 &&
              offsetof(DebugSceneViewParameters, spotRadius) == 32);

/// std140 mirror of debug_inputs.comp.glsl's parameter block (the input views).
struct DebugInputViewParameters {
    std::int32_t view = 0; ///< DebugView
    std::int32_t octahedral = 0;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    float maxCoc = 16.0f; ///< pixels: the coc view shows radius / maxCoc
    float padding[3] = {};
};
static_assert(sizeof(DebugInputViewParameters) == 32);
static_assert(offsetof(DebugInputViewParameters, octahedral) == 4 &&
              offsetof(DebugInputViewParameters, nearPlane) == 8 &&
              offsetof(DebugInputViewParameters, farPlane) == 12);

/// std140 mirror of debug_histogram.comp.glsl's parameter block.
struct HistogramOverlayParameters {
    float panel[4] = {}; ///< x0, y0, width, height in pixels (GL window coordinates, origin bottom-left)
    float log2Min = 0.0f;
    float log2Max = 0.0f;
    float keyValue = 0.0f;
    float padding = 0.0f;
};
static_assert(sizeof(HistogramOverlayParameters) == 32);
static_assert(offsetof(HistogramOverlayParameters, log2Min) == 16 &&
              offsetof(HistogramOverlayParameters, keyValue) == 24);

class DebugViewPass final : public FramePass {
public:
    DebugViewPass();
    [[nodiscard]] std::string_view name() const override { return "debug view"; }
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    /// Depends on the view: the 3D views require their input, the others the scene and its metering.
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return isSceneView(ctx.settings.debug.view);
    }
    /// Takes the view and builds the programs for output.bitDepth; throws GlError with the log.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// The last run's values as they are (RGBA32F) for a view of data (contact shadows), else nullptr:
    /// valid until the next frame.
    [[nodiscard]] const Texture* rawValues() const { return mRaw; }

    /// True for the views that replace the scene before tone mapping.
    [[nodiscard]] static bool isSceneView(DebugView view) {
        return view != DebugView::None && view != DebugView::Histogram;
    }

private:
    /// Bind the scene views' program, inputs and `out`; returns the program (the dispatch follows).
    const Program& bindSceneView(const FrameContext& ctx, const FrameResources& resources, int bitDepth,
                                 const Texture& out);
    /// Bind the input views' program (with `raw`, the variant that also writes the values unclamped to
    /// `raw`), inputs and `out`; returns the program.
    const Program& bindInputView(const FrameContext& ctx, const FrameResources& resources, int bitDepth,
                                 const Texture& out, const Texture* raw);

    DisplayProgram mSceneProgram;
    DisplayProgram mInputProgram;
    DisplayProgram mInputRawProgram; ///< also writes the unclamped values (data views' EXR)
    SamplerSlot mScene = mSceneProgram.sampler("uScene");
    SamplerSlot mMask = mSceneProgram.sampler("uMask");
    SamplerSlot mBloom = mSceneProgram.sampler("uBloom");
    ImageSlot mSceneOutput = mSceneProgram.image("uOutput");
    /// The input views' slots, from one file: the same units in both of its builds.
    SamplerSlot mInput = mInputRawProgram.sampler("uInput");
    ImageSlot mInputOutput = mInputRawProgram.image("uOutput");
    ImageSlot mRawOutput = mInputRawProgram.image("uRaw");
    ParameterBlock<DebugSceneViewParameters> mSceneParameters;
    ParameterBlock<DebugInputViewParameters> mInputParameters;
    DebugView mView = DebugView::None;
    const Texture* mRaw = nullptr;
};

class HistogramOverlayPass final : public FramePass {
public:
    HistogramOverlayPass();
    [[nodiscard]] std::string_view name() const override { return "histogram overlay"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.debug.view == DebugView::Histogram;
    }
    /// Builds the program for output.bitDepth ahead of the first frame; throws GlError with the log.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    DisplayProgram mProgram;
    SamplerSlot mDisplay = mProgram.sampler("uDisplay");
    ImageSlot mOutput = mProgram.image("uOutput");
    ParameterBlock<HistogramOverlayParameters> mParameters;
};

} // namespace photopic
