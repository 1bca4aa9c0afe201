#pragma once
// `photopic demo` (the main demo): the tabletop walk through the GPU
// pipeline with `subject` metering -- the pipeline probes the tokens and exposure follows the light under the
// player -- then telemetry -> plot, key frames, an MP4 when ffmpeg is there, and a summary per transition.

#include "common/Raster.h"
#include "common/TransitionAnalysis.h"
#include "core/Image.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace photopic::cli {

/// Measured luma (log2), target and applied (EV) over time, and `extra` beside them (its name, colour and
/// one y per sample; x is filled in), drawn under `title` by common/Raster.h plotLines.
[[nodiscard]] Image8 plotExposureTelemetry(const std::vector<TelemetrySample>& samples, PlotSeries extra,
                                           int width, int height, const std::string& title);

/// Frame indices worth showing for each transition: just before the crossing, the start of the gap (the
/// blow-out or the dark lag) and the first settled frame; sorted, without repeats.
[[nodiscard]] std::vector<std::size_t> keyFrameIndices(const std::vector<Transition>& transitions,
                                                       std::size_t frameCount);

struct TabletopWalkOptions {
    std::filesystem::path output = "out/demo";
    int width = 320; ///< 320x180 at 30 fps for 22 s: well under two minutes on llvmpipe (2 cores)
    int height = 180;
    float fps = 30.0f;
    float seconds = 22.0f; ///< the walk crosses out at ~4 s and back in at ~12 s
    int frameEvery = 1;    ///< write every Nth frame as PNG (the MP4 then runs at fps / N)
    bool video = true;     ///< encode demo.mp4 when the ffmpeg command is present
    std::string preset;    ///< --preset NAME: that look over the scene's settings; empty: the scene's own
};

/// Renders the walk through the pipeline (subject metering on the GPU): frame_NNNN.png, telemetry.csv,
/// exposure_plot.png, contact_sheet.png, demo.mp4 (ffmpeg present) and a printed transition summary.
int runTabletopWalk(const TabletopWalkOptions& options);

} // namespace photopic::cli
