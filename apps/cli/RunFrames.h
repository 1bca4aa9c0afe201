#pragma once
// The frames a `photopic image` run processes (RunFrames): --preroll's, then the ones it writes.

#include "Commands.h"
#include "InputSequence.h"

#include "common/ExposureTrack.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

namespace photopic::cli {

/// The frames a run processes: --preroll's (processed, not written), then the ones it writes, each with its
/// frame number, which is its time (FrameTime::frameIndex, the telemetry's frame column): a frame renders the
/// same whichever chunk of its sequence it is run in.
struct RunFrames {
    std::vector<std::filesystem::path> inputs;
    std::vector<std::int64_t> numbers;
    std::size_t prerolled = 0;    ///< the first `prerolled` inputs are not written
    std::uint64_t firstIndex = 0; ///< the first input's place in its sequence (Halton jitter)
    /// Each input's own frame number, preroll included (inputFrameNumbers): what a camera track is keyed by.
    std::map<std::filesystem::path, std::int64_t> frameNumbers;
};

/// The run's frames: the --preroll frames before `written` (options.preroll of them), then `written`.
[[nodiscard]] RunFrames runFrames(const ImageOptions& options, const std::vector<InputFile>& written);

/// A preroll never reaches back past a cut of the track: the histories start again at the cut, so the frames
/// before it would change nothing that is written.
void trimPrerollAtCut(RunFrames& run, const ExposureTrack& track);

} // namespace photopic::cli
