#pragma once
// Display-domain effects after the single tone mapping (docs/architecture.md). Common keys: fxaa
// `enabled`; vignette `enabled`, `intensity`, `chromaticAberration`. Every effect here is off by default
// (they are a look, so opt-in, and weak when on).

#include "core/settings/Reflect.h"

namespace photopic {

/// FXAA 3.11 quality preset (Lottes 2011) on display-referred luma.
struct FxaaSettings {
    bool enabled = false;         ///< default off: camera images arrive anti-aliased, FXAA would soften them
    float subpix = 0.75f;         ///< [0, 1], default 0.75: sub-pixel aliasing removal
    float edgeThreshold = 0.166f; ///< [0.063, 0.333], default 0.166: local contrast needed, relative
    float edgeThresholdMin = 0.0833f; ///< [0, 0.25], default 0.0833: darkest contrast processed, absolute

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("subpix", subpix, Range{0, 1});
        v.field("edgeThreshold", edgeThreshold, Range{0.063, 0.333});
        v.field("edgeThresholdMin", edgeThresholdMin, Range{0, 0.25});
    }
};

/// Lens vignetting (light fall-off, in linear display light) and lateral chromatic aberration.
struct VignetteSettings {
    bool enabled = false;               ///< default off
    float intensity = 0.5f;             ///< [0, 1], default 0.5: light lost in the corners
    float falloff = 2.0f;               ///< [0.5, 8], default 2: exponent of the normalised corner distance
    float chromaticAberration = 0.003f; ///< UV, [0, 0.05], default 0.003: R/B scale at the corners

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("intensity", intensity, Range{0, 1});
        v.field("falloff", falloff, Range{0.5, 8});
        v.field("chromaticAberration", chromaticAberration, Range{0, 0.05});
    }
};

/// Film grain: monochrome hash noise, deterministic per frame index, strongest in the mid-tones.
struct GrainSettings {
    bool enabled = false;    ///< default off
    float intensity = 0.04f; ///< display code values, [0, 0.5], default 0.04: peak grain amplitude

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("intensity", intensity, Range{0, 0.5});
    }
};

/// Post lens flare (a lens artefact, so display-referred): ghosts and a halo from a thresholded, downsampled
/// HDR buffer, independent of bloom, added in the display domain.
struct LensFlareSettings {
    bool enabled = false;      ///< default off
    float intensity = 0.05f;   ///< [0, 10], default 0.05: gain of the flare before it is added
    float threshold = 4.0f;    ///< exposed scene-linear, [0, 65000], default 4: what feeds the flare
    int ghosts = 4;            ///< [0, 8], default 4: ghost images along the line through the centre
    float ghostSpacing = 0.3f; ///< UV, [0, 1], default 0.3: distance between ghosts
    float haloRadius = 0.45f;  ///< UV, [0, 1], default 0.45: radius of the halo ring

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("intensity", intensity, Range{0, 10});
        v.field("threshold", threshold, Range{0, 65000});
        v.field("ghosts", ghosts, Range{0, 8});
        v.field("ghostSpacing", ghostSpacing, Range{0, 1});
        v.field("haloRadius", haloRadius, Range{0, 1});
    }
};

/// Dazzle: whitening, glare and desaturation while the exposure is above its target (stepping into sunlight
/// before the eye has adapted). Driven by max(0, appliedLog2 - targetLog2) from the exposure state.
struct DazzleSettings {
    bool enabled = false;  ///< default off
    float strength = 1.0f; ///< [0, 1], default 1: effect at full dazzle
    float rangeEV = 2.0f;  ///< EV, [0.1, 10], default 2: over-exposure that gives full dazzle

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("strength", strength, Range{0, 1});
        v.field("rangeEV", rangeEV, Range{0.1, 10});
    }
};

} // namespace photopic
