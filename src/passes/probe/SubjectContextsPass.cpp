#include "passes/probe/SubjectContextsPass.h"

namespace photopic {

std::span<const ResourceUse> SubjectContextsPass::uses() const {
    // Reads no GL resource; declared after exposure so it runs once this frame's telemetry is queued.
    static constexpr ResourceUse kUses[] = {{Resource::ExposureState, Access::Read}};
    return kUses;
}

void SubjectContextsPass::execute(FrameContext& ctx, FrameResources&) {
    // The base settings: the tracker applies each subject's own outdoors coupling.
    mProbes.tracker().updateExposure(ctx.settings.autoExposure, mExposure.lastTelemetry().appliedLog2);
}

} // namespace photopic
