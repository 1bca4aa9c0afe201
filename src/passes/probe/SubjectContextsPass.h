#pragma once
// Completes each subject's context after exposure: its target from its probed luma and the applied exposure
// from the newest telemetry that came back (never waited on), so the context API a host polls reads
// target and applied from the same controller the image uses.
// Tests: tests/gl/test_subjects_gpu.cpp.

#include "passes/FramePass.h"

namespace photopic {

class SubjectContextsPass final : public FramePass {
public:
    [[nodiscard]] std::string_view name() const override { return "subject contexts"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool hasSideEffects() const override { return true; }
    /// Reads the frame's subjects and exposure telemetry from the context (FrameContext::subjects,
    /// FrameContext::exposureTelemetry).
    void execute(FrameContext& ctx, FrameResources& resources) override;
};

} // namespace photopic
