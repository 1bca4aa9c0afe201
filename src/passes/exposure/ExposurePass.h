#pragma once
// Exposure target and adaptation (DESIGN.md frame order step 4): one compute invocation reads the frame's
// metering and updates the GPU exposure state (GpuExposureState) that every later pass reads. Same frame, no
// CPU round trip. With auto exposure off it still runs: it writes exposure = 2^manualEV and the histogram
// statistics a debug view may need.

#include "core/settings/AutoExposureSettings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

namespace photopic {

class ExposurePass {
public:
    struct Inputs {
        const Buffer* histogram = nullptr; ///< MeteringPass output (bins)
        const Buffer* metering = nullptr;  ///< MeteringPass output (header + partials)
        Buffer* exposureState = nullptr;   ///< GpuExposureState, read and written
        const AutoExposureSettings* settings = nullptr;
        bool metered = false;        ///< metering ran for exposure this frame
        bool histogramBuilt = false; ///< the bins hold this frame's histogram
        bool reset = false;          ///< snap to the next valid reading
        float dt = 0.0f;             ///< s, from the caller
        float manualEV = 0.0f;       ///< tonemapping.exposure
        GpuTimers* timers = nullptr;
    };
    ExposurePass();
    void execute(const Inputs& in) noexcept;

private:
    Program mProgram;
};

} // namespace photopic
