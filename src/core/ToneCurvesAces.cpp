// The ACES 1.x reference rendering for the tone curves (ToneCurves.cpp): RRT and the sRGB 100-nit dim ODT,
// CPU reference. src/passes/tonemap/tonecurves.h.glsl mirrors it function by function: change both together
// (same constants, same order of operations) or the GL mirror test fails.
//
// Source: ACES 1.x CTL (github.com/ampas/aces-dev, transforms a1.0.3): RRT.ctl, ACESlib.RRT_Common.ctl,
// ACESlib.Tonescales.ctl, ACESlib.ODT_Common.ctl, ACESlib.Transform_Common.ctl, ACESlib.Utilities_Color.ctl,
// ODT.Academy.sRGB_100nits_dim.ctl. The matrices are derived from the CTL chromaticities in double precision
// (Bradford CAT as calculate_cat_matrix); the tests re-derive them.
#include "core/ToneCurvesAces.h"

#include "core/ToneCurves.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

constexpr float kHalfMax = 65504.0f; // largest finite half float: the HDR target's range

// -------------------------------------------------------------------------------- ACES 1.x
// Column-major (glm/GLSL constructor order), out = M * in. Derived in double from the CTL chromaticities.
const glm::mat3 kAcesRec709ToAp0{0.4396329819f, 0.0897764430f, 0.0175411704f, //
                                 0.3829886982f, 0.8134394287f, 0.1115465533f, //
                                 0.1773783199f, 0.0967841283f, 0.8709122763f};
const glm::mat3 kAcesAp0ToAp1{1.4514393161f,  -0.0765537734f, 0.0083161484f,  //
                              -0.2365107469f, 1.1762296998f,  -0.0060324498f, //
                              -0.2149285693f, -0.0996759264f, 0.9977163014f};
const glm::mat3 kAcesAp1ToXyz{0.6624541811f, 0.2722287168f, -0.0055746495f, //
                              0.1340042065f, 0.6740817658f, 0.0040607335f,  //
                              0.1561876870f, 0.0536895174f, 1.0103391003f};
const glm::mat3 kAcesXyzToAp1{1.6410233797f,  -0.6636628587f, 0.0117218943f,  //
                              -0.3248032942f, 1.6153315917f,  -0.0082844420f, //
                              -0.2364246952f, 0.0167563477f,  0.9883948585f};
const glm::mat3 kAcesAp1ToRec709{1.7050509927f,  -0.1302564175f, -0.0240033568f, //
                                 -0.6217921207f, 1.1408047366f,  -0.1289689761f, //
                                 -0.0832588720f, -0.0105483191f, 1.1529723329f};
const glm::mat3 kAcesRrtSat{0.9708891487f, 0.0108891487f, 0.0108891487f, //
                            0.0269632706f, 0.9869632706f, 0.0269632706f, //
                            0.0021475807f, 0.0021475807f, 0.9621475807f};
const glm::mat3 kAcesOdtSat{0.9490560102f, 0.0190560102f, 0.0190560102f, //
                            0.0471857236f, 0.9771857236f, 0.0471857236f, //
                            0.0037582662f, 0.0037582662f, 0.9337582662f};

constexpr float kAcesHalfMin = 5.96046448e-08f; // CTL HALF_MIN, the smallest positive half
constexpr float kAcesLog10Of2 = 0.30102999566f; // log10 is log2 * log10(2), as GLSL has no log10
constexpr float kAcesLog2Of10 = 3.32192809489f;

float acesLog10(float x) {
    return std::log2(x) * kAcesLog10Of2;
}

float acesPow10(float y) {
    return std::exp2(y * kAcesLog2Of10);
}

// "Glow" module, red modifier, desaturation (ACESlib.RRT_Common.ctl, RRT.ctl).
constexpr float kAcesGlowGain = 0.05f;
constexpr float kAcesGlowMid = 0.08f;
constexpr float kAcesRedScale = 0.82f;
constexpr float kAcesRedPivot = 0.03f;
constexpr float kAcesRedHue = 0.0f;
constexpr float kAcesRedWidth = 135.0f;

// Quadratic B-spline segment: monomials (t^2, t, 1) . (cf * M), M the CTL's monomial-to-basis matrix.
float acesSplineSegment(float c0, float c1, float c2, float t) {
    const float a = 0.5f * c0 - c1 + 0.5f * c2;
    const float b = -c0 + c1;
    const float c = 0.5f * c0 + 0.5f * c1;
    return t * t * a + t * b + c;
}

// segmented_spline_c5_fwd with RRT_PARAMS: min (0.18 * 2^-15, 1e-4), mid (0.18, 4.8), max (0.18 * 2^18, 1e4),
// both end slopes 0. log10 of the anchors precomputed in double.
constexpr float kC5LogMinX = -5.2601774299f;
constexpr float kC5LogMidX = -0.7447274949f;
constexpr float kC5LogMaxX = 4.6738124271f;
constexpr float kC5LogMinY = -4.0f;
constexpr float kC5LogMaxY = 4.0f;

float acesSplineC5(float x) {
    constexpr std::array<float, 6> coefsLow{-4.0000000000f, -4.0000000000f, -3.1573765773f,
                                            -0.4852499958f, 1.8477324706f,  1.8477324706f};
    constexpr std::array<float, 6> coefsHigh{-0.7185482425f, 2.0810307172f, 3.6681241237f,
                                             4.0000000000f,  4.0000000000f, 4.0000000000f};
    constexpr int kKnotsLow = 4;
    constexpr int kKnotsHigh = 4;

    const float logx = acesLog10(std::max(x, kAcesHalfMin));
    float logy = 0.0f;
    if (logx <= kC5LogMinX) {
        logy = kC5LogMinY; // slopeLow = 0
    } else if (logx < kC5LogMidX) {
        const float knot = float(kKnotsLow - 1) * (logx - kC5LogMinX) / (kC5LogMidX - kC5LogMinX);
        const int j = std::min(int(knot), kKnotsLow - 1);
        const float t = knot - float(j);
        const auto k = std::size_t(j);
        logy = acesSplineSegment(coefsLow[k], coefsLow[k + 1], coefsLow[k + 2], t);
    } else if (logx < kC5LogMaxX) {
        const float knot = float(kKnotsHigh - 1) * (logx - kC5LogMidX) / (kC5LogMaxX - kC5LogMidX);
        const int j = std::min(int(knot), kKnotsHigh - 1);
        const float t = knot - float(j);
        const auto k = std::size_t(j);
        logy = acesSplineSegment(coefsHigh[k], coefsHigh[k + 1], coefsHigh[k + 2], t);
    } else {
        logy = kC5LogMaxY; // slopeHigh = 0
    }
    return acesPow10(logy);
}

// segmented_spline_c9_fwd with ODT_48nits: anchors are the C5 spline at 0.18 * 2^-6.5, 0.18, 0.18 * 2^6.5
// (0.002879893, 4.8, 1005.719) mapping to 0.02, 4.8, 48 cd/m^2; slopeLow 0, slopeHigh 0.04.
constexpr float kC9LogMinX = -2.5406236189f;
constexpr float kC9LogMidX = 0.6812412373f;
constexpr float kC9LogMaxX = 3.0024768101f;
constexpr float kC9LogMinY = -1.6989700043f;
constexpr float kC9LogMaxY = 1.6812412374f;
constexpr float kC9SlopeHigh = 0.04f;

float acesSplineC9(float x) {
    constexpr std::array<float, 10> coefsLow{-1.6989700043f, -1.6989700043f, -1.4779000000f, -1.2291000000f,
                                             -0.8648000000f, -0.4480000000f, 0.0051800000f,  0.4511080334f,
                                             0.9113744414f,  0.9113744414f};
    constexpr std::array<float, 10> coefsHigh{0.5154386965f, 0.8470437783f, 1.1358000000f, 1.3802000000f,
                                              1.5197000000f, 1.5985000000f, 1.6467000000f, 1.6746091357f,
                                              1.6878733390f, 1.6878733390f};
    constexpr int kKnotsLow = 8;
    constexpr int kKnotsHigh = 8;

    const float logx = acesLog10(std::max(x, kAcesHalfMin));
    float logy = 0.0f;
    if (logx <= kC9LogMinX) {
        logy = kC9LogMinY; // slopeLow = 0
    } else if (logx < kC9LogMidX) {
        const float knot = float(kKnotsLow - 1) * (logx - kC9LogMinX) / (kC9LogMidX - kC9LogMinX);
        const int j = std::min(int(knot), kKnotsLow - 1);
        const float t = knot - float(j);
        const auto k = std::size_t(j);
        logy = acesSplineSegment(coefsLow[k], coefsLow[k + 1], coefsLow[k + 2], t);
    } else if (logx < kC9LogMaxX) {
        const float knot = float(kKnotsHigh - 1) * (logx - kC9LogMidX) / (kC9LogMaxX - kC9LogMidX);
        const int j = std::min(int(knot), kKnotsHigh - 1);
        const float t = knot - float(j);
        const auto k = std::size_t(j);
        logy = acesSplineSegment(coefsHigh[k], coefsHigh[k + 1], coefsHigh[k + 2], t);
    } else {
        logy = logx * kC9SlopeHigh + (kC9LogMaxY - kC9SlopeHigh * kC9LogMaxX);
    }
    return acesPow10(logy);
}

float acesRgbToSaturation(glm::vec3 rgb) {
    constexpr float kTiny = 1e-10f;
    const float mx = std::max(rgb.r, std::max(rgb.g, rgb.b));
    const float mn = std::min(rgb.r, std::min(rgb.g, rgb.b));
    return (std::max(mx, kTiny) - std::max(mn, kTiny)) / std::max(mx, 1e-2f);
}

float acesRgbToYc(glm::vec3 rgb) {
    constexpr float kYcRadiusWeight = 1.75f;
    // The radicand is half the sum of squared channel differences, >= 0; max() absorbs float round-off that
    // would otherwise make sqrt() return NaN for near-greys.
    const float chroma = std::sqrt(
        std::max(rgb.b * (rgb.b - rgb.g) + rgb.g * (rgb.g - rgb.r) + rgb.r * (rgb.r - rgb.b), 0.0f));
    return (rgb.b + rgb.g + rgb.r + kYcRadiusWeight * chroma) / 3.0f;
}

float acesSigmoidShaper(float x) {
    const float t = std::max(1.0f - std::abs(x / 2.0f), 0.0f);
    const float y = 1.0f + glm::sign(x) * (1.0f - t * t);
    return y / 2.0f;
}

float acesGlowFwd(float ycIn, float glowGainIn, float glowMid) {
    if (ycIn <= 2.0f / 3.0f * glowMid) {
        return glowGainIn;
    }
    if (ycIn >= 2.0f * glowMid) {
        return 0.0f;
    }
    return glowGainIn * (glowMid / ycIn - 1.0f / 2.0f);
}

// Hue in degrees [0, 360). Only called for non-neutral colours (the CTL returns NaN for neutrals).
float acesRgbToHue(glm::vec3 rgb) {
    constexpr float kSqrt3 = 1.7320508076f;
    constexpr float kRadToDeg = 57.2957795131f;
    float hue = kRadToDeg * std::atan2(kSqrt3 * (rgb.g - rgb.b), 2.0f * rgb.r - rgb.g - rgb.b);
    if (hue < 0.0f) {
        hue = hue + 360.0f;
    }
    return hue;
}

float acesCenterHue(float hue, float centerH) {
    float hueCentered = hue - centerH;
    if (hueCentered < -180.0f) {
        hueCentered = hueCentered + 360.0f;
    } else if (hueCentered > 180.0f) {
        hueCentered = hueCentered - 360.0f;
    }
    return hueCentered;
}

// Uniform cubic B-spline bump of full base width w (degrees), 1 at x = 0.
float acesCubicBasisShaper(float x, float w) {
    float y = 0.0f;
    if (x > -w / 2.0f && x < w / 2.0f) {
        const float knot = (x + w / 2.0f) * 4.0f / w;
        const int j = int(knot);
        const float t = knot - float(j);
        const float m0 = t * t * t;
        const float m1 = t * t;
        const float m2 = t;
        if (j == 3) {
            y = m0 * (-1.0f / 6.0f) + m1 * (3.0f / 6.0f) + m2 * (-3.0f / 6.0f) + 1.0f / 6.0f;
        } else if (j == 2) {
            y = m0 * (3.0f / 6.0f) + m1 * (-6.0f / 6.0f) + m2 * (0.0f / 6.0f) + 4.0f / 6.0f;
        } else if (j == 1) {
            y = m0 * (-3.0f / 6.0f) + m1 * (3.0f / 6.0f) + m2 * (3.0f / 6.0f) + 1.0f / 6.0f;
        } else if (j == 0) {
            y = m0 * (1.0f / 6.0f);
        }
    }
    return y * 3.0f / 2.0f;
}

// ODT_Common darkSurround_to_dimSurround: gamma 0.9811 on Y, chromaticity kept.
glm::vec3 acesDarkToDimSurround(glm::vec3 linearCV) {
    constexpr float kDimSurroundGamma = 0.9811f;
    glm::vec3 xyz = kAcesAp1ToXyz * linearCV;
    float divisor = xyz.x + xyz.y + xyz.z;
    if (divisor == 0.0f) {
        divisor = 1e-10f;
    }
    glm::vec3 xyY{xyz.x / divisor, xyz.y / divisor, xyz.y};
    xyY.z = std::max(xyY.z, 0.0f);
    xyY.z = std::pow(xyY.z, kDimSurroundGamma);
    xyz = glm::vec3(xyY.x * xyY.z / std::max(xyY.y, 1e-10f), xyY.z,
                    (1.0f - xyY.x - xyY.y) * xyY.z / std::max(xyY.y, 1e-10f));
    return kAcesXyzToAp1 * xyz;
}

} // namespace

namespace detail {

glm::vec3 aces(glm::vec3 rgb) {
    // Linear Rec.709 (D65) -> ACES2065-1 (AP0, D60).
    glm::vec3 ap0 = kAcesRec709ToAp0 * rgb;

    // --- RRT (RRT.ctl) ---
    // Glow module.
    const float saturation = acesRgbToSaturation(ap0);
    const float ycIn = acesRgbToYc(ap0);
    const float s = acesSigmoidShaper((saturation - 0.4f) / 0.2f);
    const float addedGlow = 1.0f + acesGlowFwd(ycIn, kAcesGlowGain * s, kAcesGlowMid);
    ap0 = addedGlow * ap0;

    // Red modifier. The CTL's hue is NaN for neutrals, which makes the shaper weight 0; say so explicitly, as
    // NaN comparisons are not dependable in GLSL.
    float hueWeight = 0.0f;
    if (!(ap0.r == ap0.g && ap0.g == ap0.b)) {
        const float hue = acesRgbToHue(ap0);
        const float centeredHue = acesCenterHue(hue, kAcesRedHue);
        hueWeight = acesCubicBasisShaper(centeredHue, kAcesRedWidth);
    }
    ap0.r = ap0.r + hueWeight * saturation * (kAcesRedPivot - ap0.r) * (1.0f - kAcesRedScale);

    // ACES -> AP1 rendering space, global desaturation, per-channel tone scale.
    ap0 = glm::max(ap0, glm::vec3(0.0f));
    glm::vec3 rgbPre = glm::clamp(kAcesAp0ToAp1 * ap0, glm::vec3(0.0f), glm::vec3(kHalfMax));
    rgbPre = kAcesRrtSat * rgbPre;
    const glm::vec3 rgbPost{acesSplineC5(rgbPre.r), acesSplineC5(rgbPre.g), acesSplineC5(rgbPre.b)};

    // --- ODT sRGB 100 nits dim (ODT.Academy.sRGB_100nits_dim.ctl) ---
    // The RRT ends with AP1 -> AP0 (OCES) and the ODT starts with AP0 -> AP1; the pair is the identity and is
    // skipped.
    const glm::vec3 odtPost{acesSplineC9(rgbPost.r), acesSplineC9(rgbPost.g), acesSplineC9(rgbPost.b)};

    // Y_2_linCV with CINEMA_WHITE 48 and CINEMA_BLACK = pow10(log10(0.02)), defined like the CTL so that the
    // spline's floor maps to exactly 0.
    const float cinemaWhite = 48.0f;
    const float cinemaBlack = acesPow10(kC9LogMinY);
    glm::vec3 linearCV = (odtPost - cinemaBlack) / (cinemaWhite - cinemaBlack);
    // The spline never goes below CINEMA_BLACK, so this only removes round-off; it keeps the xyY round trip
    // below away from a vanishing X + Y + Z with a non-zero Y.
    linearCV = glm::max(linearCV, glm::vec3(0.0f));

    linearCV = acesDarkToDimSurround(linearCV);
    linearCV = kAcesOdtSat * linearCV;
    // AP1 -> XYZ -> Bradford D60 -> D65 -> Rec.709, one matrix.
    linearCV = kAcesAp1ToRec709 * linearCV;
    // The CTL clamps to [0, 1] and then applies the sRGB OETF; we return the clamped linear value.
    return glm::clamp(linearCV, glm::vec3(0.0f), glm::vec3(1.0f));
}

float acesRrtSplineForTest(float x) noexcept {
    return acesSplineC5(x);
}

float acesOdtSplineForTest(float x) noexcept {
    return acesSplineC9(x);
}

AcesMatricesForTest acesMatricesForTest() noexcept {
    return {kAcesRec709ToAp0, kAcesAp0ToAp1, kAcesAp1ToXyz, kAcesXyzToAp1,
            kAcesAp1ToRec709, kAcesRrtSat,   kAcesOdtSat};
}

AcesOdtAnchorsForTest acesOdtAnchorsForTest() noexcept {
    return {acesPow10(kC9LogMinX), acesPow10(kC9LogMidX), acesPow10(kC9LogMaxX)};
}

} // namespace detail

} // namespace photopic
