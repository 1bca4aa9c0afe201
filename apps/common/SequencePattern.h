#pragma once
// Frame-numbered file names as the tools users know write them: ffmpeg's printf-style `%04d` (zero padded to
// four digits) and `%d` (unpadded), and the `#` and `@` of compositing tools (each stands for one digit,
// so `####` is four digits zero padded and a single `#` or `@` is unpadded, as oiiotool's `@` is). Pure
// functions over names and folder listings, so the rules are tested without touching a disk.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// A file name with one frame number in it: prefix, the number written `width` digits wide at least (zero
/// padded; width 1 is unpadded), suffix.
struct FramePattern {
    std::string prefix;
    std::string suffix;
    int width = 1; ///< digits, [1, 18]; 1: unpadded

    /// The name of `frame` (>= 0), as printf("%0*d") writes it.
    [[nodiscard]] std::string name(std::int64_t frame) const;
    /// The frame `fileName` is, when it is exactly a name this pattern writes (so "f12.exr" is not a frame
    /// of "f%04d.exr", but "f12345.exr" is: printf writes 12345 in five digits).
    [[nodiscard]] std::optional<std::int64_t> match(std::string_view fileName) const;
};

/// The frame-number token of a file name (no folder): nullopt when it holds none. `%%` is a literal `%`.
/// Throws std::invalid_argument for a name with two tokens or a `%` that is neither `%d`, `%0Nd` nor `%%`.
[[nodiscard]] std::optional<FramePattern> parseFramePattern(std::string_view fileName);

/// An inclusive frame range: "1001-1100", or one frame "7". Throws std::invalid_argument naming the text.
struct FrameRange {
    std::int64_t first = 0;
    std::int64_t last = 0;
};
[[nodiscard]] FrameRange parseFrameRange(std::string_view text);

/// One frame of an expanded sequence.
struct SequenceFrame {
    std::filesystem::path path;
    std::int64_t frame = 0;
};

/// Which frames of a pattern a run takes.
struct FrameSelection {
    std::optional<FrameRange> range;       ///< every frame of it, each must exist
    std::optional<std::int64_t> startFrom; ///< the frames that exist from this one on
};

/// The frames of `pattern` (a path whose file name holds the token) among `folderNames` (the names in its
/// folder), in frame order. With a range, every frame of it must be among the names: the first missing one
/// throws std::invalid_argument naming its file. Without one, the frames that exist from `startFrom`
/// (default: the lowest that exists). No frame at all throws std::invalid_argument naming the pattern.
[[nodiscard]] std::vector<SequenceFrame> expandSequence(const std::filesystem::path& pattern,
                                                        const std::vector<std::string>& folderNames,
                                                        const FrameSelection& selection = {});

} // namespace photopic
