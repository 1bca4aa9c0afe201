#pragma once
// FXAA's settings (display-referred, after tone mapping).

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

/// FXAA 3.11 quality preset (Lottes 2011) on display-referred luma.
struct FxaaSettings {
    bool enabled = false;
    float subpix = 0.75f;
    float edgeThreshold = 0.166f;
    float edgeThresholdMin = 0.0833f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "camera images arrive anti-aliased, FXAA would soften them");
        v.field("subpix", subpix, Range{0, 1}, "sub-pixel aliasing removal");
        v.field("edgeThreshold", edgeThreshold, Range{0.063, 0.333}, "local contrast needed, relative");
        v.field("edgeThresholdMin", edgeThresholdMin, Range{0, 0.25}, "darkest contrast processed, absolute");
    }
};

} // namespace photopic
