#pragma once
// Passes that turn the host's 3D inputs into the pipeline's conventions: linear view depth for every 3D pass,
// and camera-only motion from depth when the host gives no motion vectors.
// Tests: tests/gl/test_renderer_inputs.cpp, tests/gl/test_frame_graph.cpp.

#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>

namespace photopic {

/// std140 mirror of linear_depth.comp.glsl's parameter block.
struct LinearDepthParameters {
    std::int32_t kind = 0; ///< DepthKind
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    float padding = 0.0f;
};
static_assert(sizeof(LinearDepthParameters) == 16);

/// std140 mirror of camera_motion.comp.glsl's parameter block.
struct CameraMotionParameters {
    glm::mat4 invProjection{1.0f};
    glm::mat4 invView{1.0f};
    glm::mat4 prevViewProjection{1.0f};
    std::int32_t cut = 0;
    std::int32_t padding[3] = {};
};
static_assert(sizeof(CameraMotionParameters) == 208);
static_assert(offsetof(CameraMotionParameters, cut) == 192);

/// Depth (standard, reversed or linear; FrameInputs::depthKind) -> R32F linear view depth.
class LinearDepthPass final : public FramePass {
public:
    LinearDepthPass();
    [[nodiscard]] std::string_view name() const override { return "linear depth"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// On when the host gives depth; it runs only when a pass that runs reads linear depth.
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    SamplerSlot mDepth = mProgram.sampler("uDepth");
    ImageSlot mLinear = mProgram.image("uLinear");
    ParameterBlock<LinearDepthParameters> mParameters;
};

/// Camera-only motion vectors reconstructed from linear depth and the camera, when the host gives none.
class CameraMotionPass final : public FramePass {
public:
    CameraMotionPass();
    [[nodiscard]] std::string_view name() const override { return "camera motion"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// On when the host gives depth but no motion; it runs only when a pass that runs reads motion.
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    SamplerSlot mLinearDepth = mProgram.sampler("uLinearDepth");
    ImageSlot mMotion = mProgram.image("uMotion");
    ParameterBlock<CameraMotionParameters> mParameters;
};

} // namespace photopic
