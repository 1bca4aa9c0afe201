#pragma once
// The tabletop walk demo's pieces (seed 000): telemetry -> plot, key frames, transition summary; and a
// phase-1 runner that drives exposure from a CPU probe under the token. After issue 3's GPU metering is
// merged, the runner's CPU probe and ExposureController give way to the pipeline's subject metering and
// `photopic demo` switches to the walk (DESIGN.md: the tabletop is the main demo).

#include "core/Image.h"
#include "core/TransitionAnalysis.h"

#include <cstddef>
#include <filesystem>
#include <vector>

namespace photopic::cli {

/// measured luma (log2), target, applied (EV) and outdoors (0..1) over time, drawn by io/Raster.h plotLines.
[[nodiscard]] Image8 plotExposureTelemetry(const std::vector<TelemetrySample>& samples, int width,
                                           int height);

/// Frame indices worth showing for each transition: just before the crossing, the start of the gap (the
/// blow-out or the dark lag) and the first settled frame; sorted, without repeats.
[[nodiscard]] std::vector<std::size_t> keyFrameIndices(const std::vector<Transition>& transitions,
                                                       std::size_t frameCount);

struct TabletopWalkOptions {
    std::filesystem::path output = "out/demo-walk";
    int width = 480;
    int height = 270;
    float fps = 30.0f;
    float seconds = 24.0f;
};

/// Renders the walk with exposure driven on the CPU (probe under the token -> ExposureController -> manual
/// exposure): frames, telemetry.csv, exposure_plot.png, contact_sheet.png, and a printed transition summary.
int runTabletopWalk(const TabletopWalkOptions& options);

} // namespace photopic::cli
