#pragma once
// SMAA's settings (Jimenez et al. 2012, "SMAA: Enhanced Subpixel Morphological Antialiasing"),
// selected by aa.mode = smaa or taa+smaa.

#include "core/settings/QualitySettings.h"
#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

/// SMAA 1x (Jimenez et al. 2012) on the display-referred image.
struct SmaaSettings {
    EffectQuality quality = EffectQuality::High;
    float subpixel = 0.33f;

    template <class V>
    void visit(V& v) {
        v.field(
            "quality", quality, effectQualityNames(),
            "sMAA preset. The reference presets: luma threshold 0.15 / 0.1 / 0.1 / 0.05, orthogonal search "
            "steps 4 / 8 / 16 / 32, diagonal steps - / - / 8 / 16, corner rounding - / - / 25% / 25%");
        v.field(
            "subpixel", subpixel, Range{0, 1},
            "a pixel the patterns leave alone that is a ridge one pixel wide (edges on both sides, darker "
            "or brighter than both) moves this far towards its sides' mean in linear light: a line thinner "
            "than a pixel is drawn fainter, as its coverage would have it. 0 is the reference SMAA 1x. Not "
            "under taa+smaa, where TAA's jittered frames resolve thin lines");
    }
};

} // namespace photopic
