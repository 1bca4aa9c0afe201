#pragma once
// HDR bloom on exposed colour (after metering; passes/bloom/, and passes/glare/ for mode `glare`). The
// common keys `enabled`, `threshold`, `intensity` are fields here and keep their meaning; only what exceeds
// 1.0 blooms by default.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class BloomMode {
    EnergyConserving, ///< mix(scene, bloom, intensity) over the whole image, no threshold (Jimenez 2014)
    Threshold,        ///< scene + intensity * bloom of what lies above a soft-knee threshold
    /// mix(scene, scene convolved with a physical point-spread function, intensity), by FFT (passes/glare/)
    Glare,
};

inline std::span<const std::string_view> bloomModeNames() {
    static constexpr std::array<std::string_view, 3> kNames{"energy-conserving", "threshold", "glare"};
    return kNames;
}

/// The point-spread function of glare mode (core/Glare.h).
enum class GlareKernel {
    Eye,    ///< the human eye's photopic PSF (Spencer et al. 1995): a sharp core in a power-law halo
    Camera, ///< a lens: diffraction spikes of the aperture blades and a veiling-glare power law
};

inline std::span<const std::string_view> glareKernelNames() {
    static constexpr std::array<std::string_view, 2> kNames{"eye", "camera"};
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
    GlareKernel glareKernel = GlareKernel::Eye;
    float glareRadiusDeg = 6.0f;
    float fieldOfViewDeg = 60.0f;
    int glareBlades = 6;
    float glareBladeRotationDeg = 0.0f;

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
                "mix factor (energy-conserving and glare, <= 1) or additive gain (threshold)");
        v.field("threshold", threshold, Range{0, 65000}, "exposed scene-linear: threshold mode only");
        v.field("knee", knee, Range{0, 1}, "fraction of threshold: soft-knee width, threshold mode");
        v.field("radius", radius, Range{0, 1},
                "share each level hands to the wider ones (spread, roundness)");
        v.field("mipCount", mipCount, Range{0, 10},
                "levels of the chain below half size; 0: the quality tier's count");
        v.field("glareKernel", glareKernel, glareKernelNames(),
                "glare mode: the point-spread function the frame is convolved with");
        v.field("glareRadiusDeg", glareRadiusDeg, Range{0.5, 45},
                "glare mode: degrees of field of view the kernel reaches from a light");
        v.field("fieldOfViewDeg", fieldOfViewDeg, Range{1, 179},
                "glare mode: vertical field of view of a frame whose host gives no camera (degrees)");
        v.field("glareBlades", glareBlades, Range{3, 16},
                "glare mode, camera kernel: aperture blades (spikes: as many if even, twice if odd)");
        v.field("glareBladeRotationDeg", glareBladeRotationDeg, Range{0, 360},
                "glare mode, camera kernel: angle of the first spike from the image's +x axis");
        v.require(mode == BloomMode::Threshold || intensity <= 1.0f, "intensity",
                  "must lie in [0, 1] in energy-conserving and glare modes (it is a mix factor)");
    }
};

} // namespace photopic
