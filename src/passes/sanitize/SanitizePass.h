#pragma once
// The first read of the host's colour: any float format -> RGBA16F with NaN, +-Inf and negatives -> 0 and
// values clamped below the half-float maximum, so nothing non-finite reaches metering, exposure or bloom.
// Tests: tests/gl/test_frame_graph.cpp, tests/gl/test_output_reference.cpp.

#include "passes/FramePass.h"

namespace photopic {

class SanitizePass final : public FramePass {
public:
    SanitizePass();
    [[nodiscard]] std::string_view name() const override { return "sanitize"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// The HDR path only, and only when a pass of the frame reads the scene colour without sanitising it:
    /// the LDR path sanitises inside its single pass, and metering, bloom and tone mapping sanitise what
    /// they read.
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.sanitizeScene;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    SamplerSlot mInput = mProgram.sampler("uInput");
    ImageSlot mOutput = mProgram.image("uOutput");
};

} // namespace photopic
