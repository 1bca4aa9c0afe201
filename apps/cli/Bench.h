#pragma once
// What the files of `photopic bench` (BenchCommand.h) share: its options, the median and the JSON writer.
// PipelineBench.h times the pipeline's passes, CanvasBench.cpp the canvas scene's tiled against full-screen
// shading.

#include "Commands.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace photopic::cli {

struct BenchOptions {
    std::string size = "1920x1080"; ///< WxH of the synthetic frame, or of --input mirrored to fill it
    bool sizeGiven = false;         ///< --size was given: with --input, the image is mirrored to that size
    int frames = 60;                ///< timed frames, after the warm-up
    int warmup = 5;                 ///< untimed frames first (shader compilation, first-use allocations)
    std::filesystem::path input;    ///< an HDR image instead of the synthetic frame
    /// The input texture's format, "rgba32f" or "rgba16f" (a renderer's usual scene colour): what the first
    /// passes read, and the format of the bandwidth reference copy.
    std::string inputFormat = "rgba32f";
    std::int64_t maxPixels = kDefaultMaxPixels; ///< a larger --input is refused before it is decoded
    std::filesystem::path json;                 ///< also write the table here (atomically)
    SettingsSources settings;
    bool forceLdr = false;
    /// Debug: glFinish() around every pass and report its wall time beside the timer query (stalls every
    /// pass; for drivers whose timestamps miss deferred work, such as Mesa llvmpipe).
    bool sync = false;
    /// Untimed GPU work before each timed frame, longer than the CPU takes to submit one, so the timestamps
    /// hold the GPU's own work and not its waits for the CPU (QueueAhead.h).
    bool queueAhead = false;
    std::string scene; ///< "" (the pipeline on a synthetic or --input frame) or "canvas" (its shading paths)
    /// Pixels a frame of uniform horizontal motion in the 3D frame's motion vectors (0: a still frame, on
    /// which motion blur gathers on no tile).
    float motion = 0.0f;
    /// The 3D frame's lower part is a floor that meets the wall (screen-space reflections' long rays).
    bool floor = false;
    /// A camera track for an EXR --input's 3D layers (as `photopic image --camera`).
    std::filesystem::path camera;
};

/// `--scene canvas`: the canvas scene's tiled shading (specular + sparkle only on tiles with material,
/// indirect dispatch) against its full-screen shading, after checking that both give the same image.
int runCanvasBench(const BenchOptions& options);

/// The table as JSON, through the io library's atomic writer. Throws IoError naming the file.
void writeJsonAtomically(const std::filesystem::path& path, const nlohmann::json& doc);

/// The median of `values` (the mean of the middle two for an even count), 0 for none: what the bench and the
/// image command's stage report print.
[[nodiscard]] double median(std::vector<double> values);

} // namespace photopic::cli
