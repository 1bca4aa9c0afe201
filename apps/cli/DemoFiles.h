#pragma once
// What the two demos (the tabletop walk and the orbit) write beside their frames, set up and finished the
// same way: frame_NNNN.png, exposure_plot.png, contact_sheet.png and demo.mp4 in one folder, each checked
// before the first frame is rendered and taken back by RunOutputs when the run fails.

#include "Outputs.h"

#include <cstddef>
#include <filesystem>
#include <string>

namespace photopic::cli {

/// `folder`/frame_NNNN.png.
[[nodiscard]] std::filesystem::path demoFramePath(const std::filesystem::path& folder, std::size_t index);

struct DemoFiles {
    std::filesystem::path folder;
    std::filesystem::path plot;  ///< exposure_plot.png
    std::filesystem::path sheet; ///< contact_sheet.png
    std::filesystem::path video; ///< demo.mp4
};

/// Checks a demo's size, frame rate and length (InputError naming the flags), makes `folder` and checks that
/// every file can be written there before the first frame; the frames are registered as a sequence.
[[nodiscard]] DemoFiles prepareDemoFiles(RunOutputs& outputs, const std::filesystem::path& folder, int width,
                                         int height, float fps, float seconds);

/// With `enabled`, encodes the written frames at `fps` into files.video (registered when written); returns
/// what happened, for the summary.
[[nodiscard]] std::string encodeDemoVideo(RunOutputs& outputs, const DemoFiles& files, double fps,
                                          bool enabled);

} // namespace photopic::cli
