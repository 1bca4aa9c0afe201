#pragma once
// The inputs of a sequence command (`photopic image`, `meter`, `farm`): files, or frame-numbered patterns
// expanded from their folder (--frames, --start-number), in the order frames run, each with its frame number.

#include "Commands.h"

#include "common/SequencePattern.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <vector>

namespace photopic::cli {

/// The frame numbers missing between the first and the last of a sequence in ascending order.
struct FrameGaps {
    std::int64_t missing = 0;                 ///< how many
    std::optional<std::int64_t> firstMissing; ///< the first of them
};

/// FrameGaps of `items` (ascending by frame), `frameOf(item)` giving each one's frame number.
template <class Items, class FrameOf>
FrameGaps frameGaps(const Items& items, FrameOf frameOf) {
    FrameGaps gaps;
    for (std::size_t i = 1; i < items.size(); ++i) {
        const std::int64_t previous = frameOf(items[i - 1]);
        const std::int64_t gap = frameOf(items[i]) - previous - 1;
        if (gap > 0 && !gaps.firstMissing) {
            gaps.firstMissing = previous + 1;
        }
        gaps.missing += std::max<std::int64_t>(gap, 0);
    }
    return gaps;
}

/// An input once its patterns are expanded, with the frame number its pattern matched.
struct InputFile {
    std::filesystem::path path;
    std::optional<std::int64_t> frame;
};

/// Natural order of file names (runs of digits compare by value: f9 before f10).
[[nodiscard]] bool naturalLess(const std::filesystem::path& a, const std::filesystem::path& b);

/// The inputs in the order they run: each pattern replaced by its frames (--frames, --start-number), then
/// everything in natural order. A name that exists as a file is that file, whatever characters it holds.
/// Throws InputError naming a pattern with no frames, a missing frame of a range, or a bad range.
[[nodiscard]] std::vector<InputFile> expandInputs(const ImageOptions& options);

/// The number each input's result takes in an output pattern: the frame its input pattern matched, else the
/// last number in its file name; when an input has neither, or two inputs would share one, every input is
/// numbered by its position from 0. It is also the frame's number in time (FrameTime::frameIndex, the
/// telemetry's frame column), so a frame renders the same whichever chunk of its sequence it is run in.
[[nodiscard]] std::vector<std::int64_t> outputFrameNumbers(const std::vector<InputFile>& inputs);

/// Each input's own frame number, where it has one (a pattern's, else the last run of digits in its name):
/// what a camera track (--camera) is keyed by.
[[nodiscard]] std::map<std::filesystem::path, std::int64_t>
inputFrameNumbers(const std::vector<InputFile>& inputs);
/// `path`'s number in inputFrameNumbers' map, if it has one.
[[nodiscard]] inline std::optional<std::int64_t>
frameNumberOf(const std::map<std::filesystem::path, std::int64_t>& numbers,
              const std::filesystem::path& path) {
    const auto it = numbers.find(path);
    return it == numbers.end() ? std::nullopt : std::optional(it->second);
}

/// The lowest frame that exists of the inputs' one frame-numbered pattern (where its sequence starts,
/// whatever
/// --frames picks); nullopt when the inputs are not one pattern.
[[nodiscard]] std::optional<std::int64_t> sequenceStart(const ImageOptions& options);

/// --preroll N: up to `count` frames of the one pattern input that come just before the first of `chunk`
/// (fewer at the sequence's start), in frame order. Throws InputError when the inputs are not one pattern.
[[nodiscard]] std::vector<InputFile> prerollInputs(const ImageOptions& options,
                                                   const std::vector<InputFile>& chunk, int count);

} // namespace photopic::cli
