#pragma once
// Display-domain effects after the single tone mapping (docs/architecture.md). Common keys: fxaa
// `enabled`; vignette `enabled`, `intensity`, `chromaticAberration`. Every effect here is off by default
// (they are a look, so opt-in, and weak when on).

#include "core/settings/Reflect.h"

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
