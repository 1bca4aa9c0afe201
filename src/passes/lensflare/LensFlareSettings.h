#pragma once
// Lens flare's settings (display-referred, added after tone mapping).

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

/// Post lens flare (a lens artefact, so display-referred): ghosts and a halo from a thresholded, downsampled
/// HDR buffer, independent of bloom, added in the display domain.
struct LensFlareSettings {
    bool enabled = false;
    float intensity = 0.05f;
    float threshold = 4.0f;
    int ghosts = 4;
    float ghostSpacing = 0.3f;
    float haloRadius = 0.45f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns the lens flare (ghosts and halo) on");
        v.field("intensity", intensity, Range{0, 10}, "gain of the flare before it is added");
        v.field("threshold", threshold, Range{0, 65000}, "exposed scene-linear: what feeds the flare");
        v.field("ghosts", ghosts, Range{0, 8}, "ghost images along the line through the centre");
        v.field("ghostSpacing", ghostSpacing, Range{0, 1}, "UV: distance between ghosts");
        v.field("haloRadius", haloRadius, Range{0, 1}, "UV: radius of the halo ring");
    }
};

} // namespace photopic
