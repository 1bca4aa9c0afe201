#pragma once
// Completes each subject's context after exposure: its target from its probed luma and the applied exposure
// from the newest telemetry that came back (never waited on), so the context API a host polls reads
// target and applied from the same controller the image uses.

#include "passes/FramePass.h"
#include "passes/exposure/ExposurePass.h"
#include "passes/probe/ProbePass.h"

namespace photopic {

class SubjectContextsPass final : public FramePass {
public:
    SubjectContextsPass(ProbePass& probes, const ExposurePass& exposure)
        : mProbes(probes)
        , mExposure(exposure) {}
    [[nodiscard]] std::string_view name() const override { return "subject contexts"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool hasSideEffects() const override { return true; }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    ProbePass& mProbes;
    const ExposurePass& mExposure;
};

} // namespace photopic
