#pragma once
// Volumetric light: screen-space radial scattering from the sun's projected position (Mitchell, "Volumetric
// Light Scattering as a Post-Process", GPU Gems 3 ch. 13), added to the HDR image after SSR
// (docs/architecture.md, "Volumetric light"). `intensity`, `density` and `decay` keep the names and defaults
// of the older settings files; `weight` and `exposure` are the paper's other two terms. With a sun shadow map
// from the host, single scattering ray-marched along the view rays instead (`mode`).

#include "core/settings/QualitySettings.h"
#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

/// Which volumetric light runs (docs/architecture.md, "Volumetric light").
enum class VolumetricLightMode {
    Screen,    ///< screen-space radial scattering from the sun's projected position
    ShadowMap, ///< in-scattering ray-marched along view rays against the host's sun shadow map
    Auto,      ///< shadowMap when the frame has a sun shadow map, else screen
};

inline std::span<const std::string_view> volumetricLightModeNames() {
    static constexpr std::array<std::string_view, 3> kNames{"screen", "shadowmap", "auto"};
    return kNames;
}

/// The shadow-map march's resolution, a fraction of the image's on each axis.
enum class VolumetricLightResolution { Half, Quarter };

inline std::span<const std::string_view> volumetricLightResolutionNames() {
    static constexpr std::array<std::string_view, 2> kNames{"half", "quarter"};
    return kNames;
}

struct VolumetricLightSettings {
    bool enabled = false;
    float intensity = 1.0f;
    float density = 1.0f;
    float decay = 0.97f;
    float weight = 1.0f;
    float exposure = 0.005f;
    EffectQuality quality = EffectQuality::High;
    int samples = 0;
    VolumetricLightMode mode = VolumetricLightMode::Auto;
    VolumetricLightResolution resolution = VolumetricLightResolution::Half;
    float scattering = 0.02f;
    float anisotropy = 0.6f;
    float maxDistance = 100.0f;

    /// Samples along each ray: `samples`, or the preset's count when it is 0.
    [[nodiscard]] int sampleCount() const noexcept {
        return countOrPreset(samples, quality, {16, 32, 64, 128});
    }

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns volumetric light (screen-space light shafts) on");
        v.field("intensity", intensity, Range{0, 16},
                "scales the light added (0: computed, not added). A multiplier like `weight` and `exposure`; "
                "kept because older settings files set it");
        v.field("density", density, Range{0, 2},
                "how far towards the sun each pixel's samples reach, as a fraction of its distance to the "
                "sun on screen (1: up to the sun; below 1 the rays of pixels far from the sun fall short of "
                "it, so they get shorter)");
        v.field("decay", decay, Range{0, 1},
                "the falloff along the ray, per 1/64 of the way towards the sun (the paper's per-sample "
                "decay at 64 samples; defined per fraction of the way so that `samples` changes the noise, "
                "not the look). Below 1 the light near the pixel counts more than the light at the sun");
        v.field("weight", weight, Range{0, 16},
                "the weight of each sample (the paper's `weight`), normalised by the sample count");
        v.field("exposure", exposure, Range{0, 1},
                "the final scale (the paper's `exposure`). The sun's disc dominates the sums: with the "
                "defaults the testbed's sun (radiance about 8000) adds about 0.2 at a quarter of the image "
                "height from it and 0.1 at half; a scene with another sun radiance scales it to taste");
        v.field("quality", quality, effectQualityNames(),
                "samples along each ray (screen: towards the sun; shadowmap: steps along the view ray): low "
                "16, medium 32, high 64, ultra 128, a dithered start per pixel and frame, accumulated over "
                "frames");
        v.field("samples", samples, Range{0, 256},
                "samples along each ray (at least 4); 0: the quality preset's count");
        v.require(samples == 0 || samples >= 4, "samples", "must be 0 (the preset's) or at least 4");
        v.field("mode", mode, volumetricLightModeNames(),
                "screen: radial rays from the sun on screen; shadowmap: single scattering marched along the "
                "view rays against the host's sun shadow map, where `density` multiplies `scattering`, "
                "`decay` is the medium's albedo (the scattered share of the light it removes) and "
                "`intensity` scales the result (`weight` and `exposure` are screen mode's); auto: shadowmap "
                "when the frame has a sun shadow map, else screen");
        v.field("resolution", resolution, volumetricLightResolutionNames(),
                "the shadow-map march's resolution");
        v.field("scattering", scattering, Range{0, 10},
                "per scene unit: the medium's extinction coefficient at density 1 (shadowmap)");
        v.field("anisotropy", anisotropy, Range{-0.95, 0.95},
                "Henyey-Greenstein g: > 0 scatters forwards, so looking towards the sun shows more "
                "(shadowmap)");
        v.field("maxDistance", maxDistance, Range{0.01, 1e6},
                "scene units: the longest march; the sky's rays end here (shadowmap)");
    }
};

} // namespace photopic
