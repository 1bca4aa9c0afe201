#pragma once
// Subject probes (the light a subject stands in, for metering that follows it): one compute dispatch measures
// the light under every subject scheduled this frame on the sanitised HDR image, before exposure, with the
// multi-tap pattern of core's probeImage (kProbeTaps, probeTapTexel). The results stay in a small SSBO that
// the pipeline copies into a readback ring (never waited on). For `subject` metering the same dispatch keeps
// the subject of the view's luma on the GPU (with the probe deadband) and writes it as the metering reading,
// so exposure follows it in the same frame and keeps adapting between probes.
// Tests: tests/gl/test_subjects_gpu.cpp.

#include "core/OutdoorsMask.h"
#include "core/Subjects.h"
#include "gl/ReadbackRing.h"
#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace photopic {

/// std140 mirror of probe.comp.glsl's parameter block.
struct ProbeParameters {
    std::int32_t writeReading = 0; ///< 1: subject metering, write the reading
    std::int32_t padding[3] = {};
};
static_assert(sizeof(ProbeParameters) == 16 && offsetof(ProbeParameters, writeReading) == 0);

class ProbePass final : public FramePass {
public:
    struct Inputs {
        const Texture* scene = nullptr;         ///< sanitised HDR colour (texture rows bottom-up)
        std::span<const ProbeRequest> requests; ///< this frame's probes (at most capacity())
        int taps = 5;                           ///< 1, 5 or 9
        float radius = 0.02f;                   ///< image heights
        bool active = false;                    ///< there is a subject of the view
        std::uint32_t selectedId = 0;           ///< its id (its entry, when probed, is found by id)
        float deadbandEV = 0.05f;               ///< probe.deadbandEV on the kept luma
        float timeS = 0.0f;                     ///< frame time of the probes (lastProbeAt)
        const Buffer* metering = nullptr;       ///< MeteringPass's buffer: gReading is written when non-null
        GpuTimers* timers = nullptr;
    };

    ProbePass();
    [[nodiscard]] std::string_view name() const override { return "subject probes"; }
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// The subject tracker advances every frame (selection, probe schedule, results coming back).
    [[nodiscard]] bool hasSideEffects() const override { return true; }
    /// Sizes the tracker, the pending list, the probe buffer and its readback ring (subjects.maxSubjects).
    void configure(const Settings& settings) override;
    /// Registers the frame's subjects, schedules and dispatches the probes; with `subject` metering writes
    /// the reading and, with outdoors coupling, this frame's auto exposure settings into the context.
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// Subjects for the next frame when FrameInputs brings none (hosts that prepare before the caller
    /// runs the pipeline); copied into storage sized at set-up, so it does not allocate.
    void setPending(std::span<const Subject> subjects, glm::vec2 viewCentreWorld) noexcept;
    [[nodiscard]] SubjectTracker& tracker() noexcept { return mTracker; }
    [[nodiscard]] const SubjectTracker& tracker() const noexcept { return mTracker; }
    [[nodiscard]] std::uint64_t droppedProbes() const { return mRing.dropped(); }

    /// Set-up time: sizes the probe buffer for `entries` probes per frame.
    void setCapacity(std::size_t entries);
    [[nodiscard]] std::size_t capacity() const { return mCapacity; }
    /// Bytes of the probe buffer (GpuProbeHeader + capacity() entries): the readback ring's slot size.
    [[nodiscard]] std::size_t bytes() const;
    /// Uploads the requests, probes them, updates the kept subject luma and, with `metering`, writes the
    /// reading. Requests beyond capacity() are not probed.
    void execute(const Inputs& in) noexcept;
    /// The probe buffer (header + entries with luma) of the last execute().
    [[nodiscard]] const Buffer& results() const { return mProbes; }

    static constexpr int kGroupSize = 64;

private:
    Program mProgram;
    SamplerSlot mScene = mProgram.sampler("uScene");
    ParameterBlock<ProbeParameters> mParameters;
    Buffer mProbes;
    Buffer mState; ///< GpuSubjectState, across frames
    std::vector<std::byte> mStaging;
    std::size_t mCapacity = 0;
    void pollProbes() noexcept;

    SubjectTracker mTracker;
    ReadbackRing mRing;
    std::vector<Subject> mPending; ///< setPending(), capacity subjects.maxSubjects
    std::size_t mPendingCount = 0;
    glm::vec2 mPendingCentre{0.0f};
    AutoExposureSettings mCoupled; ///< this frame's outdoors-coupled auto exposure (subject metering)
};

} // namespace photopic
