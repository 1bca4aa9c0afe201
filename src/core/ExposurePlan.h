#pragma once
// Auto exposure of a whole sequence planned on the CPU, for sequences rendered in chunks (on a farm): each
// frame is metered on its own (`photopic meter`, in parallel), then the exposure controller runs over every
// frame's reading in frame order (this file: microseconds a frame), then any chunk renders with the planned
// exposures (`photopic image --exposure-track`), so a chunk's frames are the single run's frames.
//
// The plan is the CPU twin of the GPU adaptation (core/ExposureController.h): the same target, adaptation,
// deadband, dt clamp and snap, so a run with the GPU's own adaptation and a run with the plan differ by the
// float rounding of the two (1e-3 EV at most, see the controller's tests). It snaps on the first frame and on
// each cut. A reading is what the GPU's adaptation consumes: the metered luminance of the configured mode, or
// for histogram metering the bins, whose percentile window the plan computes itself (histogramAverage, as the
// shader does), so the window may change between metering and planning.

#include "core/ExposureController.h"
#include "core/Metering.h"
#include "core/settings/AutoExposureSettings.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace photopic {

/// One frame's metering: what the adaptation consumes.
struct MeterRecord {
    std::int64_t frame = 0;
    /// The configured mode's metered luminance (for histogram metering, exp2 of the window's mean at the
    /// percentiles metering ran with); 0 when the frame had nothing meterable.
    float reading = 0.0f;
    /// exposure.mode physical: log2 of the camera's exposure multiplier (cameraExposureLog2); the frame was
    /// metered camera-exposed and the target is a correction around it. 0 otherwise.
    float cameraLog2 = 0.0f;
    float minLuminance = 0.0f; ///< smallest meterable pixel luminance (0: none)
    float maxLuminance = 0.0f;
    /// Histogram metering: the frame's 256 bins over [histogramLog2Min, histogramLog2Max].
    std::optional<Histogram> histogram;
};

/// One frame of the plan.
struct PlannedExposure {
    std::int64_t frame = 0;
    bool cut = false;   ///< exposure snapped to its target here (the first frame, a cut)
    float reading = 0;  ///< the luminance the target followed (0: none this frame; exposure held)
    ExposureState state; ///< appliedLog2 is the auto exposure to render with; exposure includes the manual EV
};

/// What decides a reading's meaning: the metering mode and its parameters (the histogram's range, the spot's
/// disc, the mask's file). Two metering runs whose descriptions differ cannot be planned together.
[[nodiscard]] std::string meteringDescription(const AutoExposureSettings& settings);

/// The luminance the adaptation follows for `record` under `settings`: the histogram window's geometric
/// mean for histogram metering (0 for an empty histogram), else the record's reading.
[[nodiscard]] float planReading(const AutoExposureSettings& settings, const MeterRecord& record) noexcept;

/// Runs the controller over `records` (in frame order, one `dt` apart) with the settings' adaptation, manual
/// EV `manualEV` (tonemapping.exposure), snapping at the first record and at every frame in `cuts`.
/// Requires settings.enabled; a histogram-metered plan needs every record's bins.
[[nodiscard]] std::vector<PlannedExposure> planExposure(const AutoExposureSettings& settings,
                                                        std::span<const MeterRecord> records, float dt,
                                                        float manualEV, std::span<const std::int64_t> cuts);

} // namespace photopic
