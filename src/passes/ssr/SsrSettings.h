#pragma once
// Screen-space reflections (docs/architecture.md, "Screen-space reflections"): a hierarchical-Z ray march
// through a min-depth pyramid of the frame, the reflected radiance taken from the previous frame's image,
// composited onto the specular term in HDR before bloom and exposure.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class SsrResolution {
    Full, ///< one ray per pixel
    Half, ///< one ray per 2 x 2 pixels, shared by the four (a quarter of the trace's cost, softer edges)
};

inline std::span<const std::string_view> ssrResolutionNames() {
    static constexpr std::array<std::string_view, 2> kNames{"full", "half"};
    return kNames;
}

struct SsrSettings {
    bool enabled = false;
    float intensity = 1.0f;
    int maxSteps = 200;
    float thickness = 0.25f;
    float maxDistance = 50.0f;
    float roughnessCutoff = 0.6f;
    float edgeFade = 0.05f;
    SsrResolution resolution = SsrResolution::Full;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns screen-space reflections on");
        v.field("intensity", intensity, Range{0, 4},
                "multiplies the reflection added to the image (after the material's specular weight and the "
                "confidence). 1 is physically based; 0 traces but adds nothing");
        v.field("maxSteps", maxSteps, Range{1, 1000},
                "the most cells the hierarchical march visits per ray. A ray that has not hit after this "
                "many counts as a miss (confidence 0)");
        v.field("thickness", thickness, Range{0.001, 100},
                "world units: how thick a surface in the depth buffer is assumed to be. A ray that passes "
                "behind a surface by more than this goes on behind it (no hit)");
        v.field("maxDistance", maxDistance, Range{0.01, 10000}, "world units: the longest reflected ray");
        v.field("roughnessCutoff", roughnessCutoff, Range{0, 1},
                "surfaces rougher than this get no screen-space reflection (confidence 0); the confidence "
                "fades out over the last 0.1 below it");
        v.field("edgeFade", edgeFade, Range{0, 0.5},
                "fraction of the image's smaller side: hits this close to the image's border fade out, where "
                "the reflected object is partly off screen");
        v.field("resolution", resolution, ssrResolutionNames(),
                "full or half: the trace's resolution (the resolve and composite run at full resolution)");
    }
};

} // namespace photopic
