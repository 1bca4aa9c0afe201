#pragma once
// HDR bloom on exposed colour (after metering; passes/bloom/). The common keys `enabled`,
// `threshold`, `intensity` are fields here and keep their meaning; only what exceeds 1.0 blooms by
// default.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class BloomMode {
    EnergyConserving, ///< mix(scene, bloom, intensity) over the whole image, no threshold (Jimenez 2014)
    Threshold,        ///< scene + intensity * bloom of what lies above a soft-knee threshold
};

inline std::span<const std::string_view> bloomModeNames() {
    static constexpr std::array<std::string_view, 2> kNames{"energy-conserving", "threshold"};
    return kNames;
}

struct BloomSettings {
    bool enabled = true;
    BloomMode mode = BloomMode::EnergyConserving;
    float intensity = 0.04f;
    float threshold = 1.0f;
    float knee = 0.5f;
    float radius = 0.85f;
    int mipCount = 0;

    /// The real-time look: the defaults above, a glow over the whole image that games and the built-in
    /// scenes are tuned for.
    [[nodiscard]] static BloomSettings realtime() { return {}; }

    /// A gentle look for still photographs: only what lies three stops past display white (8) blooms, a
    /// quarter of it, into a tight halo (two levels below half size, each handing on half). Energy-conserving
    /// bloom mixes a little of the whole frame's blur into every pixel, so the sun in
    /// data/blender_sunrise.exr lifts 38% of the frame by more than 2 code values; with these settings 0.4%
    /// (tests/e2e/veil.sh), while the pixels beside the sun still brighten.
    [[nodiscard]] static BloomSettings stills() {
        BloomSettings s;
        s.mode = BloomMode::Threshold;
        s.threshold = 8.0f;
        s.knee = 0.5f;
        s.intensity = 0.25f;
        s.radius = 0.5f;
        s.mipCount = 2;
        return s;
    }

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled,
                "turns bloom on: a modest energy-conserving glare is part of a photographic look");
        v.field("mode", mode, bloomModeNames(), "how bloom joins the scene");
        v.field("intensity", intensity, Range{0, 10},
                "mix factor (energy-conserving, <= 1) or additive gain");
        v.field("threshold", threshold, Range{0, 65000}, "exposed scene-linear: threshold mode only");
        v.field("knee", knee, Range{0, 1}, "fraction of threshold: soft-knee width, threshold mode");
        v.field("radius", radius, Range{0, 1},
                "share each level hands to the wider ones (spread, roundness)");
        v.field("mipCount", mipCount, Range{0, 10},
                "levels of the chain below half size; 0: the quality tier's count");
        v.require(mode != BloomMode::EnergyConserving || intensity <= 1.0f, "intensity",
                  "must lie in [0, 1] in energy-conserving mode (it is a mix factor)");
    }
};

} // namespace photopic
