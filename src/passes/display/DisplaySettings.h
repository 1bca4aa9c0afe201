#pragma once
// Display-domain effects after the single tone mapping (docs/architecture.md). Vignette, grain and
// dazzle are the display pass's; FXAA and lens flare have their own passes and settings headers. Every effect here is off by default
// (they are a look, so opt-in, and weak when on).

#include "core/settings/Reflect.h"

namespace photopic {

/// Lens vignetting (light fall-off, in linear display light) and lateral chromatic aberration.
struct VignetteSettings {
    bool enabled = false;
    float intensity = 0.5f;
    float falloff = 2.0f;
    float chromaticAberration = 0.003f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns the vignette and chromatic aberration on");
        v.field("intensity", intensity, Range{0, 1}, "light lost in the corners");
        v.field("falloff", falloff, Range{0.5, 8}, "exponent of the normalised corner distance");
        v.field("chromaticAberration", chromaticAberration, Range{0, 0.05}, "UV: R/B scale at the corners");
    }
};

/// Film grain: monochrome hash noise, deterministic per frame index, strongest in the mid-tones.
struct GrainSettings {
    bool enabled = false;
    float intensity = 0.04f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns film grain on");
        v.field("intensity", intensity, Range{0, 0.5}, "display code values: peak grain amplitude");
    }
};

/// Dazzle: whitening, glare and desaturation while the exposure is above its target (stepping into sunlight
/// before the eye has adapted). Driven by max(0, appliedLog2 - targetLog2) from the exposure state.
struct DazzleSettings {
    bool enabled = false;
    float strength = 1.0f;
    float rangeEV = 2.0f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns dazzle (veiling glare when over-exposed) on");
        v.field("strength", strength, Range{0, 1}, "effect at full dazzle");
        v.field("rangeEV", rangeEV, Range{0.1, 10}, "EV: over-exposure that gives full dazzle");
    }
};

} // namespace photopic
