#pragma once
// Passes that turn the host's 3D inputs into the pipeline's conventions: linear view depth for every 3D pass,
// and camera-only motion from depth when the host gives no motion vectors.

#include "passes/FramePass.h"

namespace photopic {

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
};

} // namespace photopic
