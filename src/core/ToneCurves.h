#pragma once
// Tone curves: the CPU source of truth. src/passes/tonemap/tonecurves.h.glsl mirrors every function here line
// by line (same constants, same order of operations, float), and the GL tests hold the two within 1/255 after
// sRGB encoding. Sources are cited per curve in ToneCurves.cpp.
//
// Contract of toneMap():
//  - input: scene-linear Rec.709, already multiplied by exposure (no hidden pre-scale inside any curve);
//  - output: LINEAR display light in [0, 1], before the sRGB OETF (the pipeline applies srgbEncode after);
//  - every curve is finite, in [0, 1] and maps 0 to 0 for any finite non-negative input. Inputs are first
//    clamped to [0, 65504], the range of the RGBA16F HDR target: negative values (ringing from filters)
//    become 0, and every curve has saturated (or is within 1e-5 of its asymptote) long before 65504, while
//    intermediate products such as x^2 stay finite in float.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string_view>

namespace photopic {

/// Tone curves, in the order of their GLSL TONEMAP_* defines (static_cast<int> is the shader's mode value).
enum class ToneMapper {
    Linear,           ///< clamp to [0, 1]
    Reinhard,         ///< Reinhard et al. 2002, x / (1 + x)
    ReinhardExtended, ///< Reinhard 2002 with white point W: x (1 + x / W^2) / (1 + x)
    Hable,            ///< Hable 2010 (Uncharted 2), W = 11.2, exposure bias 2
    Lottes,           ///< Lottes 2016 (GDC "Advanced Techniques and Optimization of HDR Color Pipelines")
    Uchimura,         ///< Uchimura 2017 (Gran Turismo Sport)
    AcesNarkowicz,    ///< Narkowicz 2015 fit of the ACES RRT + sRGB ODT, per channel
    AcesFitted,       ///< Hill's fit (BakingLab ACES.hlsl): matrices + rational RRT/ODT fit
    Aces,             ///< full ACES 1.x RRT + ODT sRGB 100 nits dim, as the aces-dev CTL
    Agx,              ///< Sobotka's AgX, Wrensch's minimal polynomial form, with looks
    Neutral,          ///< Khronos PBR Neutral
};

/// AgX looks (ASC CDL in AgX's log-encoded display space), in the order of the GLSL AGX_LOOK_* defines.
enum class AgxLook {
    Base,   ///< no look
    Punchy, ///< power 1.35, saturation 1.4
    Golden, ///< slope (1, 0.9, 0.5), power 0.8, saturation 0.8 (see ToneCurves.cpp on the saturation value)
};

/// Parameters the curves take besides the colour.
struct ToneCurveParams {
    float whitePoint = 4.0f; ///< scene-linear, > 0, reinhard-extended W (input that maps to 1); default 4
    AgxLook agxLook = AgxLook::Base; ///< look applied by ToneMapper::Agx; default Base
};

/// Maps exposed scene-linear Rec.709 to linear display light in [0, 1] (see the contract above).
[[nodiscard]] glm::vec3 toneMap(ToneMapper mapper, glm::vec3 exposedLinearRec709,
                                const ToneCurveParams& params = {}) noexcept;

/// Stable lower-case names ("linear", "reinhard", "reinhard-extended", "hable", "lottes", "uchimura",
/// "aces-narkowicz", "aces-fitted", "aces", "agx", "neutral"), used by settings files and the CLI.
[[nodiscard]] std::string_view toneMapperName(ToneMapper mapper) noexcept;
/// Inverse of toneMapperName, ASCII case-insensitive; nullopt for an unknown name.
[[nodiscard]] std::optional<ToneMapper> parseToneMapper(std::string_view name) noexcept;
/// Every name, in enum order.
[[nodiscard]] std::span<const std::string_view> toneMapperNames() noexcept;

/// "base", "punchy", "golden".
[[nodiscard]] std::string_view agxLookName(AgxLook look) noexcept;
[[nodiscard]] std::optional<AgxLook> parseAgxLook(std::string_view name) noexcept;
[[nodiscard]] std::span<const std::string_view> agxLookNames() noexcept;

namespace detail {

/// AgX sigmoid on a scene-linear grey value, without the inset matrix: log2 encode over
/// [-12.47393, 4.026069], normalise, apply the 6th-order polynomial. The value is display-encoded (about
/// gamma 2.2). 0.18 -> 0.49673.
[[nodiscard]] float agxCurveForTest(float sceneLinear) noexcept;

/// The ACES RRT tone scale (segmented_spline_c5_fwd with RRT_PARAMS), in and out in ACES luminance units.
[[nodiscard]] float acesRrtSplineForTest(float x) noexcept;
/// The ACES 48-nit ODT tone scale (segmented_spline_c9_fwd with ODT_48nits), OCES in, cd/m^2 out.
[[nodiscard]] float acesOdtSplineForTest(float x) noexcept;

/// The hard-coded constants that the CPU and the shader share, exposed so tests can re-derive them.
struct AcesMatricesForTest {
    glm::mat3 rec709ToAp0; ///< linear Rec.709 (D65) -> ACES2065-1 (AP0, D60), Bradford adaptation
    glm::mat3 ap0ToAp1;    ///< AP0 -> AP1 (same white)
    glm::mat3 ap1ToXyz;    ///< AP1 -> CIE XYZ (D60 white)
    glm::mat3 xyzToAp1;    ///< inverse of ap1ToXyz
    glm::mat3 ap1ToRec709; ///< AP1 -> XYZ -> Bradford D60 -> D65 -> linear Rec.709
    glm::mat3 rrtSat;      ///< RRT global desaturation, factor 0.96 around AP1 luminance
    glm::mat3 odtSat;      ///< ODT desaturation, factor 0.93 around AP1 luminance
};
[[nodiscard]] AcesMatricesForTest acesMatricesForTest() noexcept;

/// ODT_48nits spline anchors: the RRT tone scale evaluated at 0.18 * 2^-6.5, 0.18 and 0.18 * 2^6.5.
struct AcesOdtAnchorsForTest {
    float minX;
    float midX;
    float maxX;
};
[[nodiscard]] AcesOdtAnchorsForTest acesOdtAnchorsForTest() noexcept;

/// Lottes' b and c, solved offline from f(0.18) = 0.267 and f(8) = 1, hard-coded here and in the shader.
struct LottesCoefficientsForTest {
    float b;
    float c;
};
[[nodiscard]] LottesCoefficientsForTest lottesCoefficientsForTest() noexcept;

} // namespace detail

} // namespace photopic
