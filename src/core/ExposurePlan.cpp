#include "core/ExposurePlan.h"

#include "core/PhysicalExposure.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace photopic {

std::string meteringDescription(const AutoExposureSettings& s) {
    const std::string_view mode = meteringModeNames()[std::size_t(s.metering)];
    switch (s.metering) {
    case MeteringMode::Histogram:
        return fmt::format("{} histogramLog2Min={:.9g} histogramLog2Max={:.9g}", mode, s.histogramLog2Min,
                           s.histogramLog2Max);
    case MeteringMode::Spot:
        return fmt::format("{} u={:.9g} v={:.9g} radius={:.9g} taps={}", mode, s.spot.u, s.spot.v,
                           s.spot.radius, s.spot.taps);
    case MeteringMode::Mask:
        return fmt::format("{} path={}", mode, s.mask.path);
    default:
        return std::string(mode);
    }
}

float planReading(const AutoExposureSettings& settings, const MeterRecord& record) noexcept {
    if (settings.metering != MeteringMode::Histogram || !record.histogram) {
        return record.reading;
    }
    const HistogramStats stats =
        histogramAverage(*record.histogram, settings.lowPercent, settings.highPercent);
    return stats.counted > 0 ? std::exp2(stats.averageLog2) : 0.0f;
}

std::vector<PlannedExposure> planExposure(const AutoExposureSettings& settings,
                                          std::span<const MeterRecord> records, float dt, float manualEV,
                                          std::span<const std::int64_t> cuts) {
    std::vector<PlannedExposure> plan;
    plan.reserve(records.size());
    ExposureController controller(settings);
    for (const MeterRecord& r : records) {
        const bool cut = plan.empty() || std::find(cuts.begin(), cuts.end(), r.frame) != cuts.end();
        if (cut) {
            controller.reset();
        }
        // exposure.mode physical, as the pipeline hands it to the GPU (0 in the other modes: no change).
        const PhysicalExposureInputs frame = physicalExposure(settings, manualEV, r.cameraLog2);
        controller.setSettings(frame.autoExposure);
        const float reading = planReading(settings, r);
        plan.push_back({.frame = r.frame,
                        .cut = cut,
                        .reading = reading,
                        .state = controller.update(reading, dt, frame.manualEV)});
    }
    return plan;
}

} // namespace photopic
