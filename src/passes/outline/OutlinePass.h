#pragma once
// Outlines (docs/architecture.md, "Outline"): edges where depth jumps or the surface's normal turns, drawn in
// the HDR image before TAA, so TAA smooths them like any other edge. One dispatch. The depth test works in
// 1/z, which is affine across any plane, so tilted planes give no edge at any angle, and the jump is relative
// (no scene units); only the nearer side of a jump is drawn, `width` pixels deep.
// Tests: tests/gl/test_outline.cpp.

#include "passes/FramePass.h"

#include <glm/vec4.hpp>

namespace photopic {

/// std140 mirror of outline.comp.glsl's parameter block.
struct OutlineParameters {
    glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f}; ///< rgb: the outline's colour; a: intensity
    float depthThreshold = 0.01f;
    float normalThreshold = 0.3f;
    std::int32_t width = 1;   ///< pixels
    std::int32_t normals = 0; ///< 0: none (depth edges only), 1: view xyz, 2: octahedral
};
static_assert(sizeof(OutlineParameters) == 32);
static_assert(offsetof(OutlineParameters, depthThreshold) == 16);
static_assert(offsetof(OutlineParameters, normals) == 28);

class OutlinePass final : public FramePass {
public:
    OutlinePass();
    [[nodiscard]] std::string_view name() const override { return "outline"; }
    /// sceneColor, linearDepth, normals? -> sceneColor
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.settings.outline.enabled;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    ImageSlot mScene = mProgram.image("uScene");
    ImageSlot mDepth = mProgram.image("uDepth");
    SamplerSlot mNormals = mProgram.sampler("uNormals");
    ImageSlot mOut = mProgram.image("uOut");
    ParameterBlock<OutlineParameters> mParameters;
};

} // namespace photopic
