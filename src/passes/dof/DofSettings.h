#pragma once
// Depth of field: the blur of a lens focused at one distance (docs/architecture.md, "Depth of field"). Each
// pixel's circle of confusion (CoC) comes from its depth, either from the camera's thin lens (focal length,
// f-number, focus distance) or from an artistic focal distance and range; near and far fields are gathered
// at half resolution and composited over the sharp image.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class DofMode {
    /// The thin-lens CoC of the camera's lens: radius = f^2 |z - F| / (2 N z (F - f)) on the sensor, in
    /// pixels by the sensor's height. Needs a camera (its lens).
    Physical,
    /// radius = bokehRadius * clamp((z - focalDistance) / focalRange, -1, 1) pixels: sharp at the focal
    /// distance, fully blurred a focal range in front of it or behind it.
    Artistic,
};

inline std::span<const std::string_view> dofModeNames() {
    static constexpr std::array<std::string_view, 2> kNames{"physical", "artistic"};
    return kNames;
}

/// The shape of the aperture the gather's samples cover.
enum class DofKernel {
    Disc,    ///< a round aperture
    Hexagon, ///< six blades: samples on the disc squeezed onto a regular hexagon (a flat edge at the top)
};

inline std::span<const std::string_view> dofKernelNames() {
    static constexpr std::array<std::string_view, 2> kNames{"disc", "hexagon"};
    return kNames;
}

/// Rings of the gather's sample pattern (1 + 4 r (r + 1) samples for r rings).
enum class DofQuality {
    Low,    ///< 2 rings, 25 samples
    Medium, ///< 3 rings, 49 samples
    High,   ///< 4 rings, 81 samples
};

inline std::span<const std::string_view> dofQualityNames() {
    static constexpr std::array<std::string_view, 3> kNames{"low", "medium", "high"};
    return kNames;
}

struct DofSettings {
    bool enabled = false;
    DofMode mode = DofMode::Physical;
    DofKernel kernel = DofKernel::Disc;
    DofQuality quality = DofQuality::Medium;
    float maxCocRadius = 16.0f;
    float focalDistance = 10.0f;
    float focalRange = 5.0f;
    float bokehRadius = 4.0f;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns depth of field on");
        v.field("mode", mode, dofModeNames(),
                "physical: the camera's lens (f-number, focus); artistic: focalDistance, focalRange and "
                "bokehRadius");
        v.field("kernel", kernel, dofKernelNames(), "the bokeh's shape");
        v.field("quality", quality, dofQualityNames(), "rings of the gather");
        v.field("maxCocRadius", maxCocRadius, Range{1, 64},
                "pixels (full resolution): the largest CoC radius; larger blur is clamped");
        v.field("focalDistance", focalDistance, Range{0.01, 1e5},
                "artistic: scene units: the distance in focus");
        v.field("focalRange", focalRange, Range{0.01, 1e5},
                "artistic: scene units: how far in front of and behind the focal distance the blur reaches "
                "bokehRadius");
        v.field("bokehRadius", bokehRadius, Range{0, 64},
                "artistic: pixels: the CoC radius at the range's ends");
    }
};

} // namespace photopic
