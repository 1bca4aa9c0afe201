#pragma once
// Volumetric light: screen-space radial scattering from the sun's projected position (Mitchell, "Volumetric
// Light Scattering as a Post-Process", GPU Gems 3 ch. 13), added to the HDR image after SSR
// (docs/architecture.md, "Volumetric light"). `intensity`, `density` and `decay` keep the names and defaults
// of the older settings files; `weight` and `exposure` are the paper's other two terms.

#include "core/settings/Reflect.h"

namespace photopic {

struct VolumetricLightSettings {
    bool enabled = false;
    float intensity = 1.0f;
    float density = 1.0f;
    float decay = 0.97f;
    float weight = 1.0f;
    float exposure = 0.005f;
    int samples = 64;

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
        v.field("samples", samples, Range{4, 256},
                "samples along each ray (half resolution, a dithered start per pixel and frame, accumulated "
                "over frames)");
    }
};

} // namespace photopic
