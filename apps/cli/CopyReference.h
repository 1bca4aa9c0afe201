#pragma once
// The bench's bandwidth references: a copy of the frame's texture, of a texture of one value, and a 2x2
// reduction, each timed as the passes are and its output checked.

#include "Bench.h"
#include "QueueAhead.h"

#include "gl/Objects.h"

#include <nlohmann/json.hpp>

#include <string>

namespace photopic::cli {

/// The bandwidth reference measured in the same run: a compute copy of the frame's own texture into another
/// of its format and size, timed as the passes are (GPU timestamps around each copy after a warm-up,
/// collected every frame), its output checked against its input. The passes read the frame's texels, so the
/// copy moves them too: on a GPU that compresses memory, a texture of one value (what the reference copied
/// before) can move fewer bytes than its size, and a copy of it would be a best case no frame gets. That copy
/// is still measured beside it (`constantCopy`), for comparison with the records taken with it.
struct CopyReference {
    std::string format; ///< GLSL image format of the copy
    std::string source; ///< "frame": the frame's texture; "constant": a texture cleared to one value
    double medianMs = 0;
    double bytes = 0; ///< read + written per copy
    [[nodiscard]] double gbPerSecond() const { return medianMs > 0 ? bytes / (medianMs * 1e6) : 0.0; }
    [[nodiscard]] nlohmann::json json() const {
        return {{"format", format},
                {"source", source},
                {"medianMs", medianMs},
                {"bytesMoved", bytes},
                {"gbPerSecond", gbPerSecond()}};
    }
};

/// GLSL image format qualifier of the formats a frame comes in.
std::string imageFormatName(GLenum format);

/// The reference copy of `source` (the frame's texture, or the one-value texture: `what`) into a texture of
/// its format and size. Throws when the copy did not reproduce its source.
CopyReference measureCopy(const Texture& source, const char* what, const BenchOptions& options,
                          QueueAhead* ahead);

/// The reduction reference: the 2x2 box mean of `source` into an RGBA16F texture of half its size, timed as
/// the copy is. A pass that reads the whole frame and writes a quarter of it (the bloom prefilter) moves its
/// bytes at no more than this pace: its share of the copy's is that kind of pass's ceiling on the device.
/// Throws when the means are not the source's.
CopyReference measureReduction(const Texture& source, const BenchOptions& options, QueueAhead* ahead);

/// A texture of `extent` and `format` cleared to one colour: the source of the copy earlier records used.
Texture constantTexture(Extent extent, GLenum format);

} // namespace photopic::cli
