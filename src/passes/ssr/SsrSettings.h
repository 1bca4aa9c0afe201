#pragma once
// Screen-space reflections (docs/architecture.md, "Screen-space reflections"): a hierarchical-Z ray march
// through a min-max depth pyramid of the frame, the reflected radiance taken from the previous frame's image,
// composited onto the specular term in HDR before bloom and exposure.

#include "core/settings/QualitySettings.h"
#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class SsrResolution {
    Preset, ///< the quality preset's: half at low and medium, full at high and ultra
    Full,   ///< one ray per pixel
    /// One ray per 2 x 2 pixels; each other pixel of the block refines its own hit from the blocks' hits
    /// over a short stretch (softer edges; each pixel still sets up its ray, so not a quarter of the cost)
    Half,
};

inline std::span<const std::string_view> ssrResolutionNames() {
    static constexpr std::array<std::string_view, 3> kNames{"preset", "full", "half"};
    return kNames;
}

struct SsrSettings {
    bool enabled = false;
    float intensity = 1.0f;
    EffectQuality quality = EffectQuality::High;
    int maxSteps = 0;
    float thickness = 0.25f;
    float maxDistance = 50.0f;
    float roughnessCutoff = 0.6f;
    float edgeFade = 0.05f;
    SsrResolution resolution = SsrResolution::Preset;

    /// The march's budget of cells a ray: `maxSteps`, or the preset's when it is 0.
    [[nodiscard]] int stepCount() const noexcept {
        return countOrPreset(maxSteps, quality, {48, 96, 200, 400});
    }
    /// The trace runs at half resolution: `resolution`, or the preset's (low and medium) when it is preset.
    [[nodiscard]] bool halfResolution() const noexcept {
        return resolution == SsrResolution::Half ||
               (resolution == SsrResolution::Preset &&
                (quality == EffectQuality::Low || quality == EffectQuality::Medium));
    }

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns screen-space reflections on");
        v.field("intensity", intensity, Range{0, 4},
                "multiplies the reflection added to the image (after the material's specular weight and the "
                "confidence). 1 is physically based; 0 traces but adds nothing");
        v.field("quality", quality, effectQualityNames(),
                "the trace's resolution and the most cells the hierarchical march visits per ray: low half "
                "resolution and 48 cells, medium half and 96, high full and 200, ultra full and 400. A ray "
                "that has not hit after its cells counts as a miss (confidence 0)");
        v.field("maxSteps", maxSteps, Range{0, 1000},
                "the most cells the march visits per ray; 0: the quality preset's count");
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
                "the trace's resolution (the resolve and composite run at full resolution): full, half (one "
                "ray per 2 x 2 pixels; the block's other pixels refine their hits from the blocks' hits), or "
                "preset: the quality preset's");
    }
};

} // namespace photopic
