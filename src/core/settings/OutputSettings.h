#pragma once

#include "core/settings/Reflect.h"

namespace photopic {

/// The output transform after tone mapping: sRGB OETF, then dithering against 8-bit banding.
struct OutputSettings {
    bool dither = true; ///< triangular-PDF dither of +-1 LSB before 8-bit quantisation, default on

    template <class V>
    void visit(V& v) {
        v.field("dither", dither);
    }
};

} // namespace photopic
