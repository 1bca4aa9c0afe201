#pragma once
// Screen-space contact shadows: a short ray march through the depth buffer from each surface point towards
// the sun, for the sun's direct light only (docs/architecture.md, "Contact shadows"). They add the small,
// sharp shadows where objects meet that a shadow map's resolution and bias lose; they are not a shadow map.

#include "core/settings/QualitySettings.h"
#include "core/settings/Reflect.h"

#include <cstddef>

namespace photopic {

/// The most object ids `contactShadows.mask` may list (the pass's parameter block holds this many).
inline constexpr std::size_t kMaxContactShadowMaskIds = 16;

struct ContactShadowsSettings {
    bool enabled = false;
    float distance = 0.18f;
    float thickness = 0.003f;
    float strength = 1.1f;
    EffectQuality quality = EffectQuality::High;
    int steps = 0;
    IdList mask;

    /// Samples along the ray: `steps`, or the preset's count when it is 0.
    [[nodiscard]] int stepCount() const noexcept { return countOrPreset(steps, quality, {8, 14, 22, 40}); }

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns screen-space contact shadows (a ray march towards the sun) on");
        v.field("distance", distance, Range{0.001, 100},
                "world units: how far the ray marches towards the sun. Occluders farther than this along the "
                "sun's direction cast no contact shadow (that is the shadow map's range)");
        v.field("thickness", thickness, Range{0, 10},
                "world units: how thick a surface in the depth buffer is assumed to be. A sample occludes "
                "only where the ray, over the step that reaches it, lies behind the depth surface by less "
                "than this (a ray that crosses a surface between two samples always counts), so the ray "
                "passing far behind a thin foreground object casts nothing");
        v.field("strength", strength, Range{0, 4},
                "the occlusion (1 at a hit near the surface, faded to 0 towards the ray's end and at the "
                "screen's edges) is multiplied by this and clamped to [0, 1]; visibility = 1 - that. Above 1 "
                "a hit stays fully black further into the fade; below 1 no pixel goes fully black");
        v.field("quality", quality, effectQualityNames(),
                "samples along the ray: low 8, medium 14, high 22, ultra 40 (one dithered start per pixel "
                "and frame)");
        v.field("steps", steps, Range{0, 128}, "samples along the ray; 0: the quality preset's count");
        v.field("mask", mask, Range{1, 4294967295.0},
                "object ids (the host's objectId input), at most 16; empty: every object. When not empty, "
                "only the listed objects receive and cast contact shadows: other pixels keep visibility 1, "
                "and their depth occludes nothing. A frame without an objectId input then skips the pass "
                "(reported) rather than shadow every object");
        v.require(mask.size() <= kMaxContactShadowMaskIds, "mask", "lists at most 16 object ids");
    }
};

} // namespace photopic
