#pragma once

#include "core/ToneCurves.h"
#include "core/settings/Reflect.h"

namespace photopic {

/// The single tone mapping of the frame (docs/architecture.md). Common keys: mode, exposure.
struct ToneMappingSettings {
    ToneMapper mode = ToneMapper::AcesFitted;
    float exposure = 0.0f;
    float whitePoint = 4.0f;
    AgxLook agxLook = AgxLook::Base;

    template <class V>
    void visit(V& v) {
        v.field("mode", mode, toneMapperNames(), "curve applied once, after every HDR effect");
        v.field("exposure", exposure, Range{-20, 20},
                "EV: manual exposure, multiplies with auto exposure (2^EV)");
        v.field("whitePoint", whitePoint, Range{1, 1e4}, "scene-linear: white point of reinhard-extended");
        v.field("agxLook", agxLook, agxLookNames(), "look applied inside the agx curve");
    }
};

} // namespace photopic
