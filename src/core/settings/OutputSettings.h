#pragma once

#include "core/settings/Reflect.h"

namespace photopic {

/// The output transform after tone mapping: sRGB OETF, then quantisation of the display image to its bit
/// depth, with dithering against 8-bit banding.
struct OutputSettings {
    bool dither = true;
    int bitDepth = 8;

    template <class V>
    void visit(V& v) {
        v.field("dither", dither,
                "triangular-PDF dither of +-1 LSB before 8-bit quantisation; no effect at 16 bits");
        v.field("bitDepth", bitDepth, Range{8, 16},
                "bits per channel of the display image (RGBA8 or RGBA16 unorm): 8 or 16");
        v.require(bitDepth == 8 || bitDepth == 16, "bitDepth", "must be 8 or 16");
    }
};

} // namespace photopic
