#include "passes/probe/ProbePass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <cstring>

namespace photopic {

ProbePass::ProbePass()
    : mProgram(makeComputeProgram("passes/probe/probe.comp.glsl", bindingDefines())) {
    const GpuSubjectState initial;
    mState = Buffer({.size = sizeof(GpuSubjectState),
                     .flags = GL_DYNAMIC_STORAGE_BIT,
                     .data = &initial,
                     .debugName = "subject state"});
    setCapacity(1);
}

std::size_t ProbePass::bytes() const {
    return sizeof(GpuProbeHeader) + mCapacity * sizeof(GpuProbeEntry);
}

void ProbePass::setCapacity(std::size_t entries) {
    entries = std::max<std::size_t>(entries, 1);
    if (entries == mCapacity && mProbes.valid()) {
        return;
    }
    mCapacity = entries;
    mStaging.assign(bytes(), std::byte{0});
    mProbes = Buffer(
        {.size = bytes(), .flags = GL_DYNAMIC_STORAGE_BIT, .data = mStaging.data(), .debugName = "probes"});
}

void ProbePass::execute(const Inputs& in) noexcept {
    const std::size_t count = std::min(in.requests.size(), mCapacity);
    DebugGroup group("subject probes");
    ScopedGpuTimer timer(in.timers, "subject probes", double(count) * 9.0 * 8.0 + double(bytes()));

    GpuProbeHeader header;
    header.count = std::uint32_t(count);
    header.taps = in.taps;
    header.radius = in.radius;
    header.selected = -1;
    header.active = in.active ? 1 : 0;
    header.selectedId = in.selectedId;
    header.deadbandEV = in.deadbandEV;
    header.timeS = in.timeS;
    for (std::size_t i = 0; i < count; ++i) {
        const ProbeRequest& r = in.requests[i];
        const GpuProbeEntry entry{.u = r.screenUv.x, .v = r.screenUv.y, .id = r.id, .luma = 0.0f};
        std::memcpy(mStaging.data() + sizeof(GpuProbeHeader) + i * sizeof(GpuProbeEntry), &entry,
                    sizeof(entry));
        if (in.active && r.id == in.selectedId) {
            header.selected = int(i);
        }
    }
    std::memcpy(mStaging.data(), &header, sizeof(header));
    mProbes.update(mStaging.data(), sizeof(GpuProbeHeader) + count * sizeof(GpuProbeEntry));

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingProbe, mProbes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingSubjectState, mState.id());
    if (in.metering) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingMetering, in.metering->id());
    }
    glBindTextureUnit(0, in.scene->id());
    setUniform(mProgram, "uWriteReading", in.metering ? 1 : 0);
    mProgram.use();
    // At least one invocation: it writes the reading on frames without a probe of the subject.
    const GLuint groups = GLuint(std::max<std::size_t>((count + kGroupSize - 1) / kGroupSize, 1));
    glDispatchCompute(groups, 1, 1);
    // The adaptation pass reads gReading as an SSBO; the readback copies the probe buffer.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

} // namespace photopic
