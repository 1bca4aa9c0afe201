#pragma once
// Camera and object motion blur: a reconstruction filter over the frame's motion vectors (McGuire et al.
// 2012, "A Reconstruction Filter for Plausible Motion Blur"; Guertin, McGuire and Nowrouzezahrai 2014): tile
// maximum velocity, its neighbourhood maximum, and a per-pixel gather along that velocity that classifies
// samples by depth, so a moving foreground blurs over a still background and a still foreground keeps its
// edge over a moving one.

#include "core/settings/QualitySettings.h"
#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

/// Where the shutter's open time comes from.
enum class ShutterSource {
    Angle,  ///< motionBlur.shutterAngle, a fraction of the frame interval
    Camera, ///< the host camera's lens: exposureTimeS over the frame's dt, else its shutterAngleDeg
};

inline std::span<const std::string_view> shutterSourceNames() {
    static constexpr std::array<std::string_view, 2> kNames{"angle", "camera"};
    return kNames;
}

/// Where motion blur runs relative to TAA.
enum class MotionBlurPlacement {
    BeforeTaa, ///< on the frame's HDR colour before TAA gathers it (TAA then smooths the blur's noise)
    AfterTaa,  ///< on TAA's resolved image
};

inline std::span<const std::string_view> motionBlurPlacementNames() {
    static constexpr std::array<std::string_view, 2> kNames{"before-taa", "after-taa"};
    return kNames;
}

struct MotionBlurSettings {
    bool enabled = false;
    float intensity = 1.0f;
    EffectQuality quality = EffectQuality::High;
    int sampleCount = 0;
    float shutterAngle = 180.0f;
    ShutterSource shutterSource = ShutterSource::Angle;
    float maxBlur = 20.0f;
    int tileSize = 20;
    MotionBlurPlacement placement = MotionBlurPlacement::BeforeTaa;

    /// Samples of the gather: `sampleCount`, or the preset's count when it is 0.
    [[nodiscard]] int gatherCount() const noexcept {
        return countOrPreset(sampleCount, quality, {7, 11, 15, 25});
    }

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns motion blur on");
        v.field("intensity", intensity, Range{0, 2},
                "scales the blur's length (1: the length the shutter gives; 0: no blur)");
        v.field("quality", quality, effectQualityNames(),
                "samples of the gather along the dominant velocity: low 7, medium 11, high 15, ultra 25");
        v.field("sampleCount", sampleCount, Range{0, 64},
                "samples of the gather (at least 3); 0: the quality preset's count");
        v.require(sampleCount == 0 || sampleCount >= 3, "sampleCount",
                  "must be 0 (the preset's) or at least 3");
        v.field("shutterAngle", shutterAngle, Range{0, 360},
                "degrees: the shutter's open time as a fraction of the frame interval (360: the whole "
                "interval; the blur of a point moving m pixels per frame is m x angle / 360 long)");
        v.field("shutterSource", shutterSource, shutterSourceNames(),
                "angle: shutterAngle; camera: the camera's shutter");
        v.field("maxBlur", maxBlur, Range{1, 256},
                "pixels: the longest blur radius (half the streak); longer motion is clamped to it. At most "
                "tileSize, since the gather looks at most one tile beyond its own");
        v.field("tileSize", tileSize, Range{4, 64}, "pixels: the velocity tiles' size");
        v.field("placement", placement, motionBlurPlacementNames(),
                "whether the blur runs before or after TAA");
        v.require(maxBlur <= float(tileSize), "maxBlur", "must be at most tileSize");
    }
};

} // namespace photopic
