#pragma once
// A deterministic synthetic HDR frame for benchmarks and smoke tests: a sky gradient, a sun far above 1, a
// few lamps, a checkerboard floor with hard diagonal edges. Every effect has something to act on.

#include "core/Image.h"

namespace photopic {

[[nodiscard]] ImageF makeSyntheticHdr(int width, int height);

} // namespace photopic
