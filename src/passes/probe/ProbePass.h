#pragma once
// Subject probes (seed 000, "Brightness Measurement"; DESIGN.md "Subjects"): one compute dispatch measures
// the light under every subject scheduled this frame on the sanitised HDR image, before exposure, with the
// multi-tap pattern of core's probeImage (kProbeTaps, probeTapTexel). The results stay in a small SSBO that
// the pipeline copies into a readback ring (never waited on). For `subject` metering the same dispatch keeps
// the subject of the view's luma on the GPU (with the probe deadband) and writes it as the metering reading,
// so exposure follows it in the same frame and keeps adapting between probes.

#include "core/Subjects.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace photopic {

class ProbePass {
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
    Buffer mProbes;
    Buffer mState; ///< GpuSubjectState, across frames
    std::vector<std::byte> mStaging;
    std::size_t mCapacity = 0;
};

} // namespace photopic
