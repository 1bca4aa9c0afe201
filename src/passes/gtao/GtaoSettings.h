#pragma once
// Screen-space ambient occlusion: ground-truth ambient occlusion (GTAO, Jimenez et al. 2016, "Practical
// Real-Time Strategies for Accurate Indirect Occlusion") from linear depth, view normals and the camera.

#include "core/settings/QualitySettings.h"
#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class GtaoResolution {
    Full, ///< one horizon search per pixel
    Half, ///< one per 2 x 2 pixels, upsampled by the depth-aware denoiser
};

inline std::span<const std::string_view> gtaoResolutionNames() {
    static constexpr std::array<std::string_view, 2> kNames{"full", "half"};
    return kNames;
}

enum class GtaoApply {
    /// The lighting stage hands the visibility to the host, which multiplies its indirect (ambient, IBL)
    /// light only.
    Lighting,
    /// For hosts without a lighting stage (and the CLI): a post pass multiplies the scene colour by the
    /// visibility before TAA and metering. Known error: it darkens direct light (the sun, emission) too, so
    /// occluded creases in sunlight come out darker than they are.
    Multiply,
};

inline std::span<const std::string_view> gtaoApplyNames() {
    static constexpr std::array<std::string_view, 2> kNames{"lighting", "multiply"};
    return kNames;
}

struct GtaoSettings {
    bool enabled = false;
    float radius = 1.0f;
    float bias = 0.0f;
    float power = 1.0f;
    EffectQuality quality = EffectQuality::High;
    GtaoResolution resolution = GtaoResolution::Full;
    GtaoApply apply = GtaoApply::Lighting;
    bool sampleMips = false;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns ground-truth-style ambient occlusion (horizon search) on");
        v.field("radius", radius, Range{0.001, 100}, "world units: occluders farther than this do not count");
        v.field("bias", bias, Range{0, 1},
                "world units: the surface point is lifted this far along its normal before the horizons are "
                "searched, so surfaces less than `bias` above the tangent plane do not occlude (depth buffer "
                "acne on coarse geometry). 0 matches the ray tracer's reference");
        v.field(
            "power", power, Range{0.1, 8},
            "visibility^power, an artistic shaping applied after the raw visibility (the lighting stage's "
            "texture stays raw and hands the exponent to the host; the multiply pass applies it)");
        v.field("quality", quality, effectQualityNames(),
                "slices x steps per side of each slice: low 1 x 2, medium 2 x 2, high 3 x 3, ultra 9 x 3");
        v.field("resolution", resolution, gtaoResolutionNames(),
                "full: one horizon search per pixel; half: one per 2 x 2 pixels, upsampled by the "
                "depth-aware denoiser");
        v.field("sampleMips", sampleMips,
                "the horizon search's far steps read a decimated copy of the depth and normals (levels of "
                "2 x 2 to 16 x 16 pixels, each texel one real pixel of its block), at the level the step's "
                "distance calls for: fewer cache lines a pixel on a GPU, at a small cost in accuracy");
        v.field("apply", apply, gtaoApplyNames(),
                "lighting: the lighting stage hands the visibility to the host, which multiplies its "
                "indirect light only; multiply: a post pass multiplies the scene colour by it before TAA and "
                "metering (darkens direct light too)");
    }
};

} // namespace photopic
