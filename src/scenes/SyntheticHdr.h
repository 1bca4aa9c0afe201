#pragma once
// Frames for benchmarks and smoke tests. The synthetic HDR frame is deterministic: a sky gradient, a sun far
// above 1, a few lamps, a checkerboard floor with hard diagonal edges, so every effect has something to act
// on. Its large flat areas are a best case for a GPU that compresses memory; a natural image mirrored to the
// same size (mirroredTo) is not.

#include "core/Image.h"

namespace photopic {

[[nodiscard]] ImageF makeSyntheticHdr(int width, int height);

/// `image` repeated to fill `width` x `height` (or cropped to it), every other copy flipped, so that the
/// copies meet at their own edges: a natural image at any size, with no seam a filter would see.
[[nodiscard]] ImageF mirroredTo(const ImageF& image, int width, int height);

} // namespace photopic
