#pragma once

#include "core/ToneCurves.h"
#include "core/settings/Reflect.h"

namespace photopic {

/// The single tone mapping of the frame (docs/architecture.md). Common keys: mode, exposure.
struct ToneMappingSettings {
    ToneMapper mode =
        ToneMapper::AcesFitted; ///< curve applied once, after every HDR effect; default aces-fitted
    float exposure =
        0.0f; ///< EV, [-20, 20], default 0: manual exposure, multiplies with auto exposure (2^EV)
    float whitePoint = 4.0f;         ///< scene-linear, [1, 1e4], default 4: white point of reinhard-extended
    AgxLook agxLook = AgxLook::Base; ///< look applied inside the agx curve: base, punchy, golden

    template <class V>
    void visit(V& v) {
        v.field("mode", mode, toneMapperNames());
        v.field("exposure", exposure, Range{-20, 20});
        v.field("whitePoint", whitePoint, Range{1, 1e4});
        v.field("agxLook", agxLook, agxLookNames());
    }
};

} // namespace photopic
