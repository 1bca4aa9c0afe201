#pragma once
// Volumetric light: screen-space radial scattering from the sun's projected position (Mitchell, "Volumetric
// Light Scattering as a Post-Process", GPU Gems 3 ch. 13), added to the HDR image after SSR
// (docs/architecture.md, "Volumetric light"). `intensity`, `density` and `decay` keep the names and defaults
// of the older settings files; `weight` and `exposure` are the paper's other two terms. With a sun shadow map
// from the host, single scattering ray-marched along the view rays instead (`mode`).

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
    bool enabled = false; ///< default off
    /// [0, 16], default 1: scales the light added (0: computed, not added). A multiplier like `weight` and
    /// `exposure`; kept because older settings files set it.
    float intensity = 1.0f;
    /// [0, 2], default 1: how far towards the sun each pixel's samples reach, as a fraction of its distance
    /// to the sun on screen (1: up to the sun; below 1 the rays of pixels far from the sun fall short of it,
    /// so they get shorter).
    float density = 1.0f;
    /// [0, 1], default 0.97: the falloff along the ray, per 1/64 of the way towards the sun (the paper's
    /// per-sample decay at 64 samples; defined per fraction of the way so that `samples` changes the noise,
    /// not the look). Below 1 the light near the pixel counts more than the light at the sun.
    float decay = 0.97f;
    /// [0, 16], default 1: the weight of each sample (the paper's `weight`), normalised by the sample count.
    float weight = 1.0f;
    /// [0, 1], default 0.005: the final scale (the paper's `exposure`). The sun's disc dominates the sums:
    /// with the defaults the testbed's sun (radiance about 8000) adds about 0.2 at a quarter of the image
    /// height from it and 0.1 at half; a scene with another sun radiance scales it to taste.
    float exposure = 0.005f;
    /// [4, 256], default 64: samples along each ray (screen: towards the sun; shadowmap: steps along the
    /// view ray), a dithered start per pixel and frame, accumulated over frames.
    int samples = 64;
    /// screen, shadowmap, auto (default: shadowmap when the frame has a sun shadow map, else screen). In
    /// shadowmap mode `density` multiplies `scattering`, `decay` is the medium's single-scattering albedo
    /// (the scattered share of the light it removes) and `intensity` scales the result; `weight` and
    /// `exposure` are the screen mode's only.
    VolumetricLightMode mode = VolumetricLightMode::Auto;
    /// half (default), quarter: the shadow-map march's resolution.
    VolumetricLightResolution resolution = VolumetricLightResolution::Half;
    /// Per scene unit, [0, 10], default 0.02: the medium's extinction coefficient at density 1 (shadowmap).
    float scattering = 0.02f;
    /// Henyey-Greenstein anisotropy g, [-0.95, 0.95], default 0.6: > 0 scatters forwards, so looking
    /// towards the sun shows more (shadowmap).
    float anisotropy = 0.6f;
    /// Scene units, [0.01, 1e6], default 100: the longest march; the sky's rays end here (shadowmap).
    float maxDistance = 100.0f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("intensity", intensity, Range{0, 16});
        v.field("density", density, Range{0, 2});
        v.field("decay", decay, Range{0, 1});
        v.field("weight", weight, Range{0, 16});
        v.field("exposure", exposure, Range{0, 1});
        v.field("samples", samples, Range{4, 256});
        v.field("mode", mode, volumetricLightModeNames());
        v.field("resolution", resolution, volumetricLightResolutionNames());
        v.field("scattering", scattering, Range{0, 10});
        v.field("anisotropy", anisotropy, Range{-0.95, 0.95});
        v.field("maxDistance", maxDistance, Range{0.01, 1e6});
    }
};

} // namespace photopic
