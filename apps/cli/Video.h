#pragma once
// MP4 from a numbered PNG sequence by the ffmpeg program, started directly (posix_spawnp with an argument
// vector, no shell): a path is one argument whatever it holds -- quotes, ';', '$(...)' are only characters.

#include <filesystem>
#include <string>
#include <vector>

namespace photopic::cli {

/// Runs `args` (args[0] found on PATH, no shell, standard input from /dev/null) and waits. Returns the exit
/// status (128 + the signal for a signalled child), or a negative errno when it could not be started.
int runProgram(const std::vector<std::string>& args);

struct VideoResult {
    bool written = false;
    std::string
        note; ///< what happened, for the run's summary ("demo.mp4", "skipped (no ffmpeg command)", ...)
};

/// Encodes `folder`/frame_0000.png, frame_0001.png, ... at `fps` into `output` (H.264, yuv420p, sides rounded
/// down to even). Written to a temporary beside `output` (io/ImageIO.h AtomicFileWriter), flushed to disk and
/// renamed into place only when ffmpeg succeeds;
/// otherwise nothing is left. No ffmpeg on PATH is not an error: the result says so.
VideoResult encodeFrameSequence(const std::filesystem::path& folder, double fps,
                                const std::filesystem::path& output);

} // namespace photopic::cli
