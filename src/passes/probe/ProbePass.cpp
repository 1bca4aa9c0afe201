#include "passes/probe/ProbePass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <cstring>

namespace photopic {

ProbePass::ProbePass()
    : mProgram(makeComputeProgram("passes/probe/probe.comp.glsl", bindingDefines()))
    , mParameters("probe parameters") {
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

namespace {
/// Probe readback slots: probes run at probe.hz, a few frames apart; a GPU a few frames behind never fills
/// it.
constexpr int kProbeSlots = 8;
} // namespace

std::span<const ResourceUse> ProbePass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::Metering, Access::Read},
                                            {Resource::Metering, Access::Write}};
    return kUses;
}

void ProbePass::configure(const Settings& settings) {
    mTracker.setSettings(settings.subjects);
    mPending.resize(std::size_t(std::max(settings.subjects.maxSubjects, 1)));
    mPendingCount = std::min(mPendingCount, mPending.size());
    if (capacity() != mTracker.capacity() || mRing.slotCount() == 0) {
        setCapacity(mTracker.capacity());
        mRing = ReadbackRing(bytes(), kProbeSlots, "subject probes");
    }
}

void ProbePass::setPending(std::span<const Subject> subjects, glm::vec2 viewCentreWorld) noexcept {
    mPendingCount = std::min(subjects.size(), mPending.size());
    std::copy_n(subjects.begin(), mPendingCount, mPending.begin());
    mPendingCentre = viewCentreWorld;
}

void ProbePass::pollProbes() noexcept {
    mRing.pollEach([&](const ReadbackRing::Result& r) {
        GpuProbeHeader header;
        std::memcpy(&header, r.bytes.data(), sizeof(header));
        const std::size_t count = std::min<std::size_t>(header.count, mCapacity);
        for (std::size_t i = 0; i < count; ++i) {
            GpuProbeEntry e;
            std::memcpy(&e, r.bytes.data() + sizeof(header) + i * sizeof(GpuProbeEntry), sizeof(e));
            mTracker.recordProbe(e.id, e.luma, header.timeS);
        }
    });
}

void ProbePass::execute(FrameContext& ctx, FrameResources& resources) {
    const FrameInputs& inputs = ctx.inputs;
    const bool pending = inputs.subjects.empty();
    mTracker.beginFrame(ctx.time.dt, pending ? mPendingCentre : inputs.viewCentreWorld);
    for (const Subject& s :
         pending ? std::span<const Subject>(mPending.data(), mPendingCount) : inputs.subjects) {
        mTracker.addSubject(s);
    }
    mPendingCount = 0;
    const std::span<const ProbeRequest> requests = mTracker.scheduleProbes();
    pollProbes(); // results of earlier frames into this frame's contexts (never waits)

    const AutoExposureSettings& ae = ctx.settings.autoExposure;
    const bool subjectMetering = ae.enabled && ae.metering == MeteringMode::Subject;
    const SubjectContext* subject = mTracker.subjectContext();
    const SubjectSettings::Probe& p = ctx.settings.subjects.probe;
    if (!requests.empty() || subjectMetering) {
        execute({.scene = resources.texture(Resource::SceneColor),
                 .requests = requests,
                 .taps = p.taps,
                 .radius = p.radius,
                 .active = subject != nullptr,
                 .selectedId = subject ? subject->id : 0u,
                 .deadbandEV = p.deadbandEV,
                 .timeS = mTracker.time(),
                 .metering = subjectMetering ? resources.buffer(Resource::Metering) : nullptr,
                 .timers = ctx.timers});
        if (!requests.empty()) {
            mRing.enqueue(mProbes, 0, ctx.time.frameIndex);
        }
    }
    // Outdoors coupling of the subject of the view (a tighter maxEV and faster adaptation outdoors); the
    // copy reuses mCoupled's storage, so the frame does not allocate.
    if (subjectMetering && subject && ctx.settings.subjects.outdoorsCoupling.enabled) {
        mCoupled = outdoorsCoupledSettings(ae, ctx.settings.subjects.outdoorsCoupling, subject->outdoors);
        ctx.autoExposure = &mCoupled;
    }
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
    bind(mScene, *in.scene);
    mParameters.update({.writeReading = in.metering ? 1 : 0});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    // At least one invocation: it writes the reading on frames without a probe of the subject.
    const GLuint groups = GLuint(std::max<std::size_t>((count + kGroupSize - 1) / kGroupSize, 1));
    // The adaptation pass reads gReading as an SSBO; the readback copies the probe buffer.
    dispatch(mProgram, Groups{groups, 1, 1}, Barrier::StorageReadback);
}

} // namespace photopic
