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

struct DepthOfFieldSettings {
    bool enabled = false;                    ///< default off
    DofMode mode = DofMode::Physical;        ///< physical (default: the camera's lens), artistic
    DofKernel kernel = DofKernel::Disc;      ///< disc (default), hexagon
    DofQuality quality = DofQuality::Medium; ///< low, medium (default), high: rings of the gather
    /// Pixels (full resolution), [1, 64], default 16: the largest CoC radius; larger blur is clamped.
    float maxCocRadius = 16.0f;
    float focalDistance = 10.0f; ///< artistic: scene units, [0.01, 1e5], default 10: the distance in focus
    /// Artistic: scene units, [0.01, 1e5], default 5: how far in front of and behind the focal distance the
    /// blur reaches bokehRadius
    float focalRange = 5.0f;
    float bokehRadius = 4.0f; ///< artistic: pixels, [0, 64], default 4: the CoC radius at the range's ends

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("mode", mode, dofModeNames());
        v.field("kernel", kernel, dofKernelNames());
        v.field("quality", quality, dofQualityNames());
        v.field("maxCocRadius", maxCocRadius, Range{1, 64});
        v.field("focalDistance", focalDistance, Range{0.01, 1e5});
        v.field("focalRange", focalRange, Range{0.01, 1e5});
        v.field("bokehRadius", bokehRadius, Range{0, 64});
    }
};

} // namespace photopic
