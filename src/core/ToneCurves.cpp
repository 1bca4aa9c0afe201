// Tone curves, CPU reference. src/passes/tonemap/tonecurves.h.glsl mirrors this file function by function:
// change both together (same constants, same order of operations) or the GL mirror test fails.
//
// Sources:
//  - Reinhard, Stark, Shirley, Ferwerda, "Photographic Tone Reproduction for Digital Images", SIGGRAPH 2002,
//    eq. 3 (simple) and eq. 4 (extended, white point L_white).
//  - Hable, "Uncharted 2: HDR Lighting", GDC 2010, and "Filmic Tonemapping Operators" (filmicworlds.com):
//    A..F, W = 11.2, exposure bias 2.
//  - Lottes, "Advanced Techniques and Optimization of HDR Color Pipelines", GDC 2016:
//    x^a / (x^(a d) b + c), with b and c solved from f(midIn) = midOut and f(hdrMax) = 1.
//  - Uchimura, "HDR Theory and Practice", CEDEC 2017 (Gran Turismo Sport tone mapper), default parameters.
//  - Narkowicz, "ACES Filmic Tone Mapping Curve" (knarkowicz.wordpress.com, 2016-01-06).
//  - Hill, BakingLab ACES.hlsl (github.com/TheRealMJP/BakingLab): ACESInputMat, RRTAndODTFit, ACESOutputMat.
//  - ACES 1.x CTL (in ToneCurvesAces.cpp; github.com/ampas/aces-dev, transforms a1.0.3): RRT.ctl,
//  ACESlib.RRT_Common.ctl,
//    ACESlib.Tonescales.ctl, ACESlib.ODT_Common.ctl, ACESlib.Transform_Common.ctl,
//    ACESlib.Utilities_Color.ctl, ODT.Academy.sRGB_100nits_dim.ctl. The matrices are derived from the CTL
//    chromaticities in double precision (Bradford CAT as calculate_cat_matrix); the tests re-derive them.
//  - AgX: Sobotka (github.com/sobotka/AgX), in the polynomial form and with the looks of Wrensch,
//    "Minimal AgX Implementation" (iolite-engine.com/blog_posts/minimal_agx_implementation).
//  - Khronos PBR Neutral: github.com/KhronosGroup/ToneMapping, PBR_Neutral/README.md (the final version,
//    which blends toward newPeak, not toward 1).

#include "core/ToneCurves.h"

#include "core/ToneCurvesAces.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace photopic {

namespace {

constexpr float kHalfMax = 65504.0f; // largest finite half float: the HDR target's range

// -------------------------------------------------------------------------------- Reinhard
glm::vec3 reinhard(glm::vec3 x) {
    return x / (1.0f + x);
}

glm::vec3 reinhardExtended(glm::vec3 x, float whitePoint) {
    const float w = std::max(whitePoint, 1e-4f);
    // f(W) = 1 and f is increasing, so inputs past W are clamped there (keeps x * x / W^2 finite too).
    x = glm::min(x, glm::vec3(w));
    return x * (1.0f + x / (w * w)) / (1.0f + x);
}

// -------------------------------------------------------------------------------- Hable
constexpr float kHableA = 0.15f; // shoulder strength
constexpr float kHableB = 0.50f; // linear strength
constexpr float kHableC = 0.10f; // linear angle
constexpr float kHableD = 0.20f; // toe strength
constexpr float kHableE = 0.02f; // toe numerator
constexpr float kHableF = 0.30f; // toe denominator
constexpr float kHableW = 11.2f; // linear white point
constexpr float kHableExposureBias = 2.0f;

// Hable's U(x) = (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F, over one denominator. The published
// form subtracts two numbers near 1/15 for small x, which leaves rounding noise of 1e-8 where the result is
// 1e-7 (not monotonic near black, and U(0) != 0); this form is exactly 0 at 0 and has no cancellation in x.
glm::vec3 hableU(glm::vec3 x) {
    return x * ((kHableF - kHableE) * kHableA * x + (kHableF * kHableC - kHableE) * kHableB) /
           (kHableF * (x * (kHableA * x + kHableB) + kHableD * kHableF));
}

glm::vec3 hable(glm::vec3 x) {
    return hableU(kHableExposureBias * x) / hableU(glm::vec3(kHableW));
}

// -------------------------------------------------------------------------------- Lottes
constexpr float kLottesA = 1.6f;      // contrast
constexpr float kLottesD = 0.977f;    // shoulder
constexpr float kLottesAD = 1.5632f;  // a * d
constexpr float kLottesHdrMax = 8.0f; // input that maps to 1
// b and c solved in double from f(0.18) = 0.267 and f(8) = 1 (Lottes' closed form; re-derived by the tests).
constexpr float kLottesB = 1.0730397117f;
constexpr float kLottesC = 0.1674199382f;

glm::vec3 lottes(glm::vec3 x) {
    // f(hdrMax) = 1 and f is increasing (b, c > 0, d < 1), so inputs past hdrMax are clamped there.
    x = glm::min(x, glm::vec3(kLottesHdrMax));
    return glm::pow(x, glm::vec3(kLottesA)) / (glm::pow(x, glm::vec3(kLottesAD)) * kLottesB + kLottesC);
}

// -------------------------------------------------------------------------------- Uchimura
constexpr float kUchimuraP = 1.0f;  // max display brightness
constexpr float kUchimuraA = 1.0f;  // contrast
constexpr float kUchimuraM = 0.22f; // linear section start
constexpr float kUchimuraL = 0.4f;  // linear section length
constexpr float kUchimuraC = 1.33f; // black tightness
constexpr float kUchimuraB = 0.0f;  // pedestal

glm::vec3 uchimura(glm::vec3 x) {
    const float l0 = ((kUchimuraP - kUchimuraM) * kUchimuraL) / kUchimuraA;
    const float s0 = kUchimuraM + l0;
    const float s1 = kUchimuraM + kUchimuraA * l0;
    const float c2 = (kUchimuraA * kUchimuraP) / (kUchimuraP - s1);
    const float cp = -c2 / kUchimuraP;

    const glm::vec3 w0 = 1.0f - glm::smoothstep(glm::vec3(0.0f), glm::vec3(kUchimuraM), x);
    const glm::vec3 w2 = glm::step(glm::vec3(kUchimuraM + l0), x);
    const glm::vec3 w1 = 1.0f - w0 - w2;

    const glm::vec3 t = kUchimuraM * glm::pow(x / kUchimuraM, glm::vec3(kUchimuraC)) + kUchimuraB;
    const glm::vec3 s = kUchimuraP - (kUchimuraP - s1) * glm::exp(cp * (x - s0));
    const glm::vec3 l = kUchimuraM + kUchimuraA * (x - kUchimuraM);

    return t * w0 + l * w1 + s * w2;
}

// -------------------------------------------------------------------------------- Narkowicz
glm::vec3 acesNarkowicz(glm::vec3 x) {
    return (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
}

// -------------------------------------------------------------------------------- Hill fit
// glm::mat3 takes columns; these are BakingLab's row-major matrices transposed.
const glm::mat3 kHillInput{0.59719f, 0.07600f, 0.02840f, //
                           0.35458f, 0.90834f, 0.13383f, //
                           0.04823f, 0.01566f, 0.83777f};
const glm::mat3 kHillOutput{1.60475f,  -0.10208f, -0.00327f, //
                            -0.53108f, 1.10813f,  -0.07276f, //
                            -0.07367f, -0.00605f, 1.07602f};

glm::vec3 acesFitted(glm::vec3 x) {
    glm::vec3 v = kHillInput * x;
    v = (v * (v + 0.0245786f) - 0.000090537f) / (v * (0.983729f * v + 0.4329510f) + 0.238081f);
    return kHillOutput * v;
}

// -------------------------------------------------------------------------------- AgX
// Column-major, as Wrensch's GLSL (the AgX inset for Rec.709 input).
const glm::mat3 kAgxInset{0.842479062253094f,  0.0423282422610123f, 0.0423756549057051f, //
                          0.0784335999999992f, 0.878468636469772f,  0.0784336f,          //
                          0.0792237451477643f, 0.0791661274605434f, 0.879142973793104f};
const glm::mat3 kAgxOutset{1.19687900512017f,    -0.0528968517574562f, -0.0529716355144438f, //
                           -0.0980208811401368f, 1.15190312990417f,    -0.0980434501171241f, //
                           -0.0990297440797205f, -0.0989611768448433f, 1.15107367264116f};
constexpr float kAgxMinEv = -12.47393f; // log2(0.18 * 2^-10)
constexpr float kAgxMaxEv = 4.026069f;  // log2(0.18 * 2^6.5)

// Wrensch's 6th-order fit of the AgX sigmoid (mean squared error 3.67e-6).
glm::vec3 agxContrastApprox(glm::vec3 x) {
    const glm::vec3 x2 = x * x;
    const glm::vec3 x4 = x2 * x2;
    return +15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x -
           0.00232f;
}

glm::vec3 agxLogEncode(glm::vec3 x) {
    // log2 of 0 is -inf in C and undefined in GLSL: floor the argument well below 2^kAgxMinEv.
    x = glm::clamp(glm::log2(glm::max(x, glm::vec3(1e-10f))), glm::vec3(kAgxMinEv), glm::vec3(kAgxMaxEv));
    return (x - kAgxMinEv) / (kAgxMaxEv - kAgxMinEv);
}

// ASC CDL (v1.2) in AgX's encoded space: slope, offset, power, then saturation around the Rec.709 luma of the
// slope/offset/power result. Wrensch's listing takes the luma before slope/offset/power instead; with
// punchy's power 1.35 and saturation 1.4 that makes greys 1.4 v^1.35 - 0.4 v, which falls for v < 0.012 (not
// monotonic near black), so we keep the CDL's order. Golden's saturation is Wrensch's 0.8; Filament's port
// uses 1.3.
glm::vec3 agxLook(glm::vec3 val, AgxLook look) {
    glm::vec3 offset{0.0f};
    glm::vec3 slope{1.0f};
    glm::vec3 power{1.0f};
    float sat = 1.0f;
    if (look == AgxLook::Golden) {
        slope = glm::vec3(1.0f, 0.9f, 0.5f);
        power = glm::vec3(0.8f);
        sat = 0.8f;
    } else if (look == AgxLook::Punchy) {
        slope = glm::vec3(1.0f);
        power = glm::vec3(1.35f);
        sat = 1.4f;
    }
    // The sigmoid dips to -0.00232 at the bottom: pow() of a negative base is undefined in GLSL.
    val = glm::pow(glm::max(val * slope + offset, glm::vec3(0.0f)), power);
    const glm::vec3 lw{0.2126f, 0.7152f, 0.0722f};
    const float luma = glm::dot(val, lw);
    return luma + sat * (val - luma);
}

glm::vec3 agx(glm::vec3 x, AgxLook look) {
    glm::vec3 v = kAgxInset * x;
    v = agxLogEncode(v);
    v = agxContrastApprox(v);
    if (look != AgxLook::Base) {
        v = agxLook(v, look);
    }
    v = kAgxOutset * v;
    // The curve's output is display-encoded for a 2.2 power display; decode to linear. max(0) removes the
    // polynomial's -0.00232 black offset, so 0 maps to 0.
    return glm::pow(glm::max(v, glm::vec3(0.0f)), glm::vec3(2.2f));
}

// -------------------------------------------------------------------------------- PBR Neutral
glm::vec3 neutral(glm::vec3 color) {
    constexpr float kStartCompression = 0.8f - 0.04f;
    constexpr float kDesaturation = 0.15f;

    const float x = std::min(color.r, std::min(color.g, color.b));
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    color -= offset;

    const float peak = std::max(color.r, std::max(color.g, color.b));
    if (peak < kStartCompression) {
        return color;
    }

    const float d = 1.0f - kStartCompression;
    const float newPeak = 1.0f - d * d / (peak + d - kStartCompression);
    color *= newPeak / peak;

    const float g = 1.0f - 1.0f / (kDesaturation * (peak - newPeak) + 1.0f);
    return glm::mix(color, glm::vec3(newPeak), g);
}

// -------------------------------------------------------------------------------- names
constexpr std::array<std::string_view, 11> kToneMapperNames{
    "linear",   "reinhard",       "reinhard-extended", "hable", "lottes",
    "uchimura", "aces-narkowicz", "aces-fitted",       "aces",  "agx",
    "neutral"};
constexpr std::array<std::string_view, 3> kAgxLookNames{"base", "punchy", "golden"};

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char l, char r) {
        const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
        return lower(l) == lower(r);
    });
}

} // namespace

glm::vec3 toneMap(ToneMapper mapper, glm::vec3 exposedLinearRec709, const ToneCurveParams& params) noexcept {
    const glm::vec3 x = glm::clamp(exposedLinearRec709, glm::vec3(0.0f), glm::vec3(kHalfMax));
    glm::vec3 y{0.0f};
    switch (mapper) {
    case ToneMapper::Linear:
        y = x;
        break;
    case ToneMapper::Reinhard:
        y = reinhard(x);
        break;
    case ToneMapper::ReinhardExtended:
        y = reinhardExtended(x, params.whitePoint);
        break;
    case ToneMapper::Hable:
        y = hable(x);
        break;
    case ToneMapper::Lottes:
        y = lottes(x);
        break;
    case ToneMapper::Uchimura:
        y = uchimura(x);
        break;
    case ToneMapper::AcesNarkowicz:
        y = acesNarkowicz(x);
        break;
    case ToneMapper::AcesFitted:
        y = acesFitted(x);
        break;
    case ToneMapper::Aces:
        y = detail::aces(x);
        break;
    case ToneMapper::Agx:
        y = agx(x, params.agxLook);
        break;
    case ToneMapper::Neutral:
        y = neutral(x);
        break;
    }
    // Every curve ends here: the formulas that dip below 0 (Hill's fit at black) or overshoot 1 (Narkowicz,
    // Hable, AgX's outset of saturated colours) are clamped to the display range.
    return glm::clamp(y, glm::vec3(0.0f), glm::vec3(1.0f));
}

std::string_view toneMapperName(ToneMapper mapper) noexcept {
    const auto index = std::size_t(mapper);
    return index < kToneMapperNames.size() ? kToneMapperNames[index] : std::string_view{};
}

std::optional<ToneMapper> parseToneMapper(std::string_view name) noexcept {
    for (std::size_t i = 0; i < kToneMapperNames.size(); ++i) {
        if (equalsIgnoreCase(name, kToneMapperNames[i])) {
            return ToneMapper(i);
        }
    }
    return std::nullopt;
}

std::span<const std::string_view> toneMapperNames() noexcept {
    return kToneMapperNames;
}

std::string_view agxLookName(AgxLook look) noexcept {
    const auto index = std::size_t(look);
    return index < kAgxLookNames.size() ? kAgxLookNames[index] : std::string_view{};
}

std::optional<AgxLook> parseAgxLook(std::string_view name) noexcept {
    for (std::size_t i = 0; i < kAgxLookNames.size(); ++i) {
        if (equalsIgnoreCase(name, kAgxLookNames[i])) {
            return AgxLook(i);
        }
    }
    return std::nullopt;
}

std::span<const std::string_view> agxLookNames() noexcept {
    return kAgxLookNames;
}

namespace detail {

float agxCurveForTest(float sceneLinear) noexcept {
    return agxContrastApprox(agxLogEncode(glm::vec3(std::max(sceneLinear, 0.0f)))).x;
}

LottesCoefficientsForTest lottesCoefficientsForTest() noexcept {
    return {kLottesB, kLottesC};
}

} // namespace detail

} // namespace photopic
