#include "passes/probe/SubjectContextsPass.h"

#include "core/Subjects.h"
#include "passes/exposure/ExposurePass.h"

namespace photopic {

std::span<const ResourceUse> SubjectContextsPass::uses() const {
    // Reads no GL resource; declared after exposure so it runs once this frame's telemetry is queued.
    static constexpr ResourceUse kUses[] = {{Resource::ExposureState, Access::Read}};
    return kUses;
}

void SubjectContextsPass::execute(FrameContext& ctx, FrameResources&) {
    // The base settings: the tracker applies each subject's own outdoors coupling.
    if (ctx.subjects != nullptr && ctx.exposureTelemetry != nullptr) {
        ctx.subjects->updateExposure(ctx.settings.autoExposure, ctx.exposureTelemetry->appliedLog2);
    }
}

} // namespace photopic
