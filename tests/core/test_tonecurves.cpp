// Tone curves: published reference values, the ACES constants re-derived from the CTL chromaticities, the
// ACES output against an OpenColorIO oracle, and the contract every curve keeps (0 -> 0, finite, in [0, 1],
// monotonic on greys).
//
// Tolerances: a published value given to n decimals is checked to half a unit in its last place plus float
// slack (e.g. 0.2669 -> 6e-5), unless stated otherwise next to the check.

#include "core/Color.h"
#include "core/ToneCurves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace photopic {
namespace {

glm::vec3 grey(float x) {
    return glm::vec3(x);
}

float mapGrey(ToneMapper mapper, float x, const ToneCurveParams& params = {}) {
    return toneMap(mapper, grey(x), params).g;
}

std::vector<ToneMapper> allMappers() {
    std::vector<ToneMapper> mappers;
    for (const std::string_view name : toneMapperNames()) {
        mappers.push_back(*parseToneMapper(name));
    }
    return mappers;
}

// Every mapper with default params, plus AgX under each look: the configurations the contract must hold for.
struct Configuration {
    ToneMapper mapper;
    ToneCurveParams params;
    std::string label;
};

std::vector<Configuration> allConfigurations() {
    std::vector<Configuration> configurations;
    for (const ToneMapper mapper : allMappers()) {
        configurations.push_back({mapper, {}, std::string(toneMapperName(mapper))});
    }
    for (const std::string_view look : agxLookNames()) {
        configurations.push_back(
            {ToneMapper::Agx, {.agxLook = *parseAgxLook(look)}, "agx/" + std::string(look)});
    }
    for (const float whitePoint : {0.5f, 1.0f, 11.2f, 1000.0f}) {
        configurations.push_back({ToneMapper::ReinhardExtended,
                                  {.whitePoint = whitePoint},
                                  "reinhard-extended/W=" + std::to_string(whitePoint)});
    }
    return configurations;
}

// --------------------------------------------------------------------------------------- published values

TEST(ToneCurves, LinearClamps) {
    EXPECT_EQ(mapGrey(ToneMapper::Linear, 0.18f), 0.18f);
    EXPECT_EQ(mapGrey(ToneMapper::Linear, 4.0f), 1.0f);
}

TEST(ToneCurves, ReinhardPublishedValues) {
    EXPECT_NEAR(mapGrey(ToneMapper::Reinhard, 0.18f), 0.15254f, 6e-6f);
    EXPECT_NEAR(mapGrey(ToneMapper::Reinhard, 1.0f), 0.5f, 1e-7f);
    // Extended: the white point maps to exactly 1, for the default W = 4 and others.
    EXPECT_NEAR(mapGrey(ToneMapper::ReinhardExtended, 4.0f), 1.0f, 1e-6f);
    for (const float w : {1.0f, 2.0f, 11.2f, 100.0f}) {
        EXPECT_NEAR(mapGrey(ToneMapper::ReinhardExtended, w, {.whitePoint = w}), 1.0f, 1e-6f) << w;
        EXPECT_LT(mapGrey(ToneMapper::ReinhardExtended, 0.9f * w, {.whitePoint = w}), 1.0f) << w;
    }
}

TEST(ToneCurves, HablePublishedValues) {
    EXPECT_NEAR(mapGrey(ToneMapper::Hable, 0.18f), 0.12834f, 6e-6f);
    EXPECT_NEAR(mapGrey(ToneMapper::Hable, 1.0f), 0.49292f, 6e-6f);
    // The exposure bias of 2 is inside: W / 2 = 5.6 is the input that reaches 1.
    EXPECT_NEAR(mapGrey(ToneMapper::Hable, 5.6f), 1.0f, 1e-6f);
}

TEST(ToneCurves, LottesPublishedValuesAndConstraints) {
    EXPECT_NEAR(mapGrey(ToneMapper::Lottes, 1.0f), 0.80615f, 6e-6f);
    // The constraints b and c were solved from.
    EXPECT_NEAR(mapGrey(ToneMapper::Lottes, 0.18f), 0.267f, 1e-6f);
    EXPECT_NEAR(mapGrey(ToneMapper::Lottes, 8.0f), 1.0f, 1e-6f);
}

TEST(ToneCurves, LottesCoefficientsMatchClosedForm) {
    // Lottes 2016: b = (-m^a + h^a * o) / ((h^(ad) - m^(ad)) o), c = (h^(ad) m^a - h^a m^(ad) o) / ((h^(ad) -
    // m^(ad)) o) with m = midIn, o = midOut, h = hdrMax; computed here in double.
    const double a = 1.6, d = 0.977, m = 0.18, o = 0.267, h = 8.0;
    const double den = (std::pow(h, a * d) - std::pow(m, a * d)) * o;
    const double b = (-std::pow(m, a) + std::pow(h, a) * o) / den;
    const double c = (std::pow(h, a * d) * std::pow(m, a) - std::pow(h, a) * std::pow(m, a * d) * o) / den;
    const auto coefficients = detail::lottesCoefficientsForTest();
    EXPECT_NEAR(coefficients.b, b, 1e-7);
    EXPECT_NEAR(coefficients.c, c, 1e-7);
}

TEST(ToneCurves, UchimuraPublishedValues) {
    EXPECT_NEAR(mapGrey(ToneMapper::Uchimura, 0.18f), 0.17899f, 6e-6f);
    EXPECT_NEAR(mapGrey(ToneMapper::Uchimura, 0.5f), 0.5f, 1e-6f); // on the linear segment (a = 1)
    EXPECT_NEAR(mapGrey(ToneMapper::Uchimura, 1.0f), 0.82783f, 6e-6f);
}

TEST(ToneCurves, NarkowiczPublishedValues) {
    EXPECT_NEAR(mapGrey(ToneMapper::AcesNarkowicz, 0.18f), 0.2669f, 6e-5f);
    EXPECT_NEAR(mapGrey(ToneMapper::AcesNarkowicz, 1.0f), 0.8038f, 6e-5f);
}

TEST(ToneCurves, HillFitPublishedValues) {
    EXPECT_NEAR(mapGrey(ToneMapper::AcesFitted, 0.18f), 0.10559f, 6e-6f);
    EXPECT_NEAR(mapGrey(ToneMapper::AcesFitted, 1.0f), 0.61912f, 6e-6f);
    // The rational fit is -0.00038 at 0 (its numerator's constant term); the output clamp makes black black.
    EXPECT_EQ(mapGrey(ToneMapper::AcesFitted, 0.0f), 0.0f);
}

TEST(ToneCurves, AcesGreysMatchPublishedCodeValues) {
    // sRGB code values of the full RRT + ODT.Academy.sRGB_100nits_dim for Rec.709 greys (aces-dev's CTL; the
    // same as OpenColorIO 2.1's built-ins). The brief allows 1e-3; the implementation holds 2e-5.
    struct Row {
        float in;
        float codeValue;
    };
    constexpr std::array<Row, 7> kTable{{{0.01f, 0.01284f},
                                         {0.18f, 0.35595f},
                                         {0.5f, 0.64720f},
                                         {1.0f, 0.81197f},
                                         {2.0f, 0.90373f},
                                         {4.0f, 0.95528f},
                                         {16.0f, 0.99974f}}};
    for (const Row& row : kTable) {
        const glm::vec3 out = srgbEncode(toneMap(ToneMapper::Aces, grey(row.in)));
        EXPECT_NEAR(out.r, row.codeValue, 2e-5f) << row.in;
        EXPECT_NEAR(out.g, row.codeValue, 2e-5f) << row.in;
        EXPECT_NEAR(out.b, row.codeValue, 2e-5f) << row.in;
    }
}

TEST(ToneCurves, AcesColorsMatchOpenColorIO) {
    // Oracle: OpenColorIO 2.1.2 (Debian python3-pyopencolorio), a processor made of
    // MatrixTransform(Rec.709 -> XYZ D65)
    // -> inverse BuiltinTransform("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD")
    // -> BuiltinTransform("ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0")
    // -> BuiltinTransform("DISPLAY - CIE-XYZ-D65_to_sRGB"), its output clamped to [0, 1] as the CTL ODT does.
    // These exercise the glow, the red modifier, both desaturations and the gamut clamp, which greys do not.
    // Tolerance 1e-4 in code value: OCIO derives its own matrices and evaluates the splines its own way.
    struct Row {
        glm::vec3 in;
        glm::vec3 codeValue;
    };
    const std::array<Row, 10> kTable{{
        {{1.0f, 0.0f, 0.0f}, {0.803756f, 0.0f, 0.024502f}},
        {{0.0f, 1.0f, 0.0f}, {0.329846f, 0.818209f, 0.169028f}},
        {{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.823408f}},
        {{0.5f, 0.2f, 0.05f}, {0.628012f, 0.392655f, 0.159657f}},
        {{0.05f, 0.1f, 0.6f}, {0.086382f, 0.229924f, 0.687873f}},
        {{4.0f, 1.0f, 0.2f}, {0.985147f, 0.836895f, 0.558990f}},
        {{0.02f, 0.03f, 0.01f}, {0.044211f, 0.074179f, 0.016368f}},
        {{10.0f, 10.0f, 0.5f}, {0.994926f, 0.990869f, 0.897212f}},
        {{0.3f, 0.9f, 0.9f}, {0.584926f, 0.793599f, 0.790609f}},
        {{100.0f, 5.0f, 1.0f}, {1.0f, 0.993734f, 0.954230f}},
    }};
    for (const Row& row : kTable) {
        const glm::vec3 out = srgbEncode(toneMap(ToneMapper::Aces, row.in));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(out[c], row.codeValue[c], 1e-4f)
                << "(" << row.in.r << ", " << row.in.g << ", " << row.in.b << ") channel " << c;
        }
    }
}

TEST(ToneCurves, AgxCurvePublishedValue) {
    EXPECT_NEAR(detail::agxCurveForTest(0.18f), 0.49673f, 6e-6f);
    // The full transform sees 0.18 * 1.000136 after the inset matrix (its rows sum to 1.000136, not 1), so
    // the curve value inside toneMap() is 0.496755; decoded with 2.2 and outset that is 0.2145 linear.
    EXPECT_NEAR(mapGrey(ToneMapper::Agx, 0.18f), std::pow(0.496755f, 2.2f), 1e-4f);
}

TEST(ToneCurves, AgxLooksDiffer) {
    const glm::vec3 color{0.5f, 0.3f, 0.1f};
    const glm::vec3 base = toneMap(ToneMapper::Agx, color, {.agxLook = AgxLook::Base});
    const glm::vec3 punchy = toneMap(ToneMapper::Agx, color, {.agxLook = AgxLook::Punchy});
    const glm::vec3 golden = toneMap(ToneMapper::Agx, color, {.agxLook = AgxLook::Golden});
    EXPECT_GT(glm::length(base - punchy), 1e-3f);
    EXPECT_GT(glm::length(base - golden), 1e-3f);
    // Golden's blue slope of 0.5 warms the picture: less blue relative to red than the base look.
    EXPECT_LT(golden.b / golden.r, base.b / base.r);
}

TEST(ToneCurves, NeutralPublishedValues) {
    EXPECT_NEAR(mapGrey(ToneMapper::Neutral, 0.18f), 0.14f, 1e-6f);
    EXPECT_NEAR(mapGrey(ToneMapper::Neutral, 1.0f), 0.869091f, 1e-6f);
    const glm::vec3 red = toneMap(ToneMapper::Neutral, {1.0f, 0.0f, 0.0f});
    EXPECT_NEAR(red.r, 0.88f, 1e-6f);
    EXPECT_NEAR(red.g, 0.01556f, 6e-6f);
    EXPECT_NEAR(red.b, 0.01556f, 6e-6f);
}

TEST(ToneCurves, NeutralIsAnOffsetInsideItsLinearRange) {
    // Every channel in [0.08, 0.8]: no toe (min >= 0.08), no compression (peak - 0.04 <= 0.76), so
    // out = in - 0.04.
    constexpr int kSteps = 24;
    for (int r = 0; r <= kSteps; ++r) {
        for (int g = 0; g <= kSteps; ++g) {
            for (int b = 0; b <= kSteps; ++b) {
                const glm::vec3 in =
                    0.08f + (0.8f - 0.08f) * glm::vec3(float(r), float(g), float(b)) / float(kSteps);
                const glm::vec3 out = toneMap(ToneMapper::Neutral, in);
                for (int c = 0; c < 3; ++c) {
                    ASSERT_NEAR(out[c], in[c] - 0.04f, 1e-6f) << r << " " << g << " " << b;
                }
            }
        }
    }
}

// --------------------------------------------------------------------------------------- ACES constants

// Independent derivation, in double, of the matrices ToneCurvesAces.cpp hard-codes (the shader has the same
// literals): the CTL's RGBtoXYZ, calculate_cat_matrix (Bradford) and calc_sat_adjust_matrix.
struct Mat3d {
    std::array<std::array<double, 3>, 3> m{}; // m[row][column], out = M * in

    Mat3d operator*(const Mat3d& o) const {
        Mat3d r;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                for (int k = 0; k < 3; ++k) {
                    r.m[i][j] += m[i][k] * o.m[k][j];
                }
            }
        }
        return r;
    }
    std::array<double, 3> operator*(const std::array<double, 3>& v) const {
        return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
                m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
                m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
    }
    [[nodiscard]] Mat3d inverse() const {
        const auto& a = m;
        const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        Mat3d r;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                // Cofactor of a[j][i] (transpose), cyclic indices give the sign.
                const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
                r.m[i][j] = (a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]) / det;
            }
        }
        return r;
    }
};

std::array<double, 3> xyToXyz(double x, double y) {
    return {x / y, 1.0, (1.0 - x - y) / y};
}

struct Chromaticities {
    double rx, ry, gx, gy, bx, by, wx, wy;
};

// RGBtoXYZ(primaries, Y = 1), as the CTL built-in.
Mat3d rgbToXyz(const Chromaticities& c) {
    const auto r = xyToXyz(c.rx, c.ry);
    const auto g = xyToXyz(c.gx, c.gy);
    const auto b = xyToXyz(c.bx, c.by);
    Mat3d p;
    for (int i = 0; i < 3; ++i) {
        p.m[i] = {r[i], g[i], b[i]};
    }
    const auto s = p.inverse() * xyToXyz(c.wx, c.wy);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            p.m[i][j] *= s[j];
        }
    }
    return p;
}

// calculate_cat_matrix with CONE_RESP_MAT_BRADFORD (the CTL stores it for row vectors; transposed here).
Mat3d bradford(double srcX, double srcY, double dstX, double dstY) {
    Mat3d cone;
    cone.m = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    const auto src = cone * xyToXyz(srcX, srcY);
    const auto dst = cone * xyToXyz(dstX, dstY);
    Mat3d scale;
    for (int i = 0; i < 3; ++i) {
        scale.m[i][i] = dst[i] / src[i];
    }
    return cone.inverse() * scale * cone;
}

Mat3d saturationMatrix(double sat, const std::array<double, 3>& rgbToY) {
    Mat3d s;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            s.m[i][j] = (1.0 - sat) * rgbToY[j] + (i == j ? sat : 0.0);
        }
    }
    return s;
}

void expectMatrixNear(const glm::mat3& actual, const Mat3d& expected, const char* name) {
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            EXPECT_NEAR(actual[column][row], expected.m[row][column], 2e-7)
                << name << " row " << row << " column " << column;
        }
    }
}

TEST(ToneCurves, AcesMatricesMatchTheCtlDerivation) {
    constexpr Chromaticities kAp0{0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.0770, 0.32168, 0.33767};
    constexpr Chromaticities kAp1{0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767};
    constexpr Chromaticities kRec709{0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290};
    const Mat3d ap0ToXyz = rgbToXyz(kAp0);
    const Mat3d ap1ToXyz = rgbToXyz(kAp1);
    const Mat3d rec709ToXyz = rgbToXyz(kRec709);
    const Mat3d d65ToD60 = bradford(kRec709.wx, kRec709.wy, kAp0.wx, kAp0.wy);
    const Mat3d d60ToD65 = bradford(kAp0.wx, kAp0.wy, kRec709.wx, kRec709.wy);

    const auto actual = detail::acesMatricesForTest();
    expectMatrixNear(actual.rec709ToAp0, ap0ToXyz.inverse() * d65ToD60 * rec709ToXyz, "rec709ToAp0");
    expectMatrixNear(actual.ap0ToAp1, ap1ToXyz.inverse() * ap0ToXyz, "ap0ToAp1");
    expectMatrixNear(actual.ap1ToXyz, ap1ToXyz, "ap1ToXyz");
    expectMatrixNear(actual.xyzToAp1, ap1ToXyz.inverse(), "xyzToAp1");
    expectMatrixNear(actual.ap1ToRec709, rec709ToXyz.inverse() * d60ToD65 * ap1ToXyz, "ap1ToRec709");
    expectMatrixNear(actual.rrtSat, saturationMatrix(0.96, ap1ToXyz.m[1]), "rrtSat");
    expectMatrixNear(actual.odtSat, saturationMatrix(0.93, ap1ToXyz.m[1]), "odtSat");
}

TEST(ToneCurves, AcesOdtAnchorsComeFromTheRrtSpline) {
    // ODT_48nits defines its knots' x as segmented_spline_c5_fwd at 0.18 * 2^-6.5, 0.18 and 0.18 * 2^6.5.
    const auto anchors = detail::acesOdtAnchorsForTest();
    EXPECT_NEAR(anchors.minX, detail::acesRrtSplineForTest(0.18f * std::exp2(-6.5f)), 1e-5f * anchors.minX);
    EXPECT_NEAR(anchors.midX, detail::acesRrtSplineForTest(0.18f), 1e-5f * anchors.midX);
    EXPECT_NEAR(anchors.maxX, detail::acesRrtSplineForTest(0.18f * std::exp2(6.5f)), 1e-5f * anchors.maxX);
    EXPECT_NEAR(anchors.midX, 4.8f, 1e-5f);
}

TEST(ToneCurves, AcesSplinesHitTheirKnots) {
    // RRT: min (0.18 * 2^-15 -> 1e-4), mid (0.18 -> 4.8), max (0.18 * 2^18 -> 1e4), flat beyond both ends.
    EXPECT_NEAR(detail::acesRrtSplineForTest(0.18f), 4.8f, 4.8e-5f);
    EXPECT_NEAR(detail::acesRrtSplineForTest(0.18f * std::exp2(-15.0f)), 1e-4f, 1e-9f);
    EXPECT_NEAR(detail::acesRrtSplineForTest(0.0f), 1e-4f, 1e-9f);
    EXPECT_NEAR(detail::acesRrtSplineForTest(0.18f * std::exp2(18.0f)), 1e4f, 0.1f);
    EXPECT_NEAR(detail::acesRrtSplineForTest(1e9f), 1e4f, 0.1f);
    // ODT 48 nits: 0.02 at the bottom, 4.8 at mid grey, 48 at the top anchor, slope 0.04 (log-log) above.
    const auto anchors = detail::acesOdtAnchorsForTest();
    EXPECT_NEAR(detail::acesOdtSplineForTest(anchors.minX), 0.02f, 2e-7f);
    EXPECT_NEAR(detail::acesOdtSplineForTest(0.0f), 0.02f, 2e-7f);
    EXPECT_NEAR(detail::acesOdtSplineForTest(anchors.midX), 4.8f, 4.8e-5f);
    EXPECT_NEAR(detail::acesOdtSplineForTest(anchors.maxX), 48.0f, 4.8e-4f);
    EXPECT_NEAR(detail::acesOdtSplineForTest(10.0f * anchors.maxX), 48.0f * std::pow(10.0f, 0.04f), 1e-3f);
}

// --------------------------------------------------------------------------------------- the contract

TEST(ToneCurves, BlackMapsToBlack) {
    for (const Configuration& configuration : allConfigurations()) {
        const glm::vec3 out = toneMap(configuration.mapper, grey(0.0f), configuration.params);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(out[c], 0.0f, 1e-6f) << configuration.label;
            EXPECT_GE(out[c], 0.0f) << configuration.label;
        }
    }
}

TEST(ToneCurves, ExtremeInputsStayFiniteAndInRange) {
    const std::vector<glm::vec3> inputs{
        grey(1e30f),
        grey(65504.0f),
        grey(1e-30f),
        grey(3.4e38f),
        {1e30f, 0, 0},
        {0, 1e30f, 0},
        {0, 0, 1e30f},
        {1e30f, 0.5e30f, 0.0f},
        {65504.0f, 0, 1},
        {1e-30f, 0.0f, 65504.0f},
        {1e-30f, 1e-30f, 0.0f},
        {-1.0f, 0.5f, -1e30f},
        {0.18f, 1e30f, 0},
        {1e-7f, 0.0f, 0.0f},
    };
    for (const Configuration& configuration : allConfigurations()) {
        for (const glm::vec3& in : inputs) {
            const glm::vec3 out = toneMap(configuration.mapper, in, configuration.params);
            for (int c = 0; c < 3; ++c) {
                EXPECT_TRUE(std::isfinite(out[c]))
                    << configuration.label << " (" << in.r << ", " << in.g << ", " << in.b << ")";
                EXPECT_GE(out[c], 0.0f) << configuration.label;
                EXPECT_LE(out[c], 1.0f) << configuration.label;
            }
        }
        // A vanishing grey stays (near) black.
        EXPECT_LT(toneMap(configuration.mapper, grey(1e-30f), configuration.params).g, 1e-6f)
            << configuration.label;
    }
}

TEST(ToneCurves, GreyRampIsMonotonic) {
    // 0, then 2000 log-spaced steps from 1e-6 to 1e4. Exact float non-decrease, no tolerance.
    std::vector<float> ramp{0.0f};
    constexpr int kSteps = 2000;
    for (int i = 0; i < kSteps; ++i) {
        ramp.push_back(std::pow(10.0f, -6.0f + 10.0f * float(i) / float(kSteps - 1)));
    }
    for (const Configuration& configuration : allConfigurations()) {
        glm::vec3 previous = toneMap(configuration.mapper, grey(ramp[0]), configuration.params);
        for (std::size_t i = 1; i < ramp.size(); ++i) {
            const glm::vec3 out = toneMap(configuration.mapper, grey(ramp[i]), configuration.params);
            for (int c = 0; c < 3; ++c) {
                ASSERT_GE(out[c], previous[c])
                    << configuration.label << " at " << ramp[i] << " channel " << c;
            }
            previous = out;
        }
    }
}

TEST(ToneCurves, GreysStayGrey) {
    for (const Configuration& configuration : allConfigurations()) {
        // AgX's golden look is a deliberate warm tint.
        if (configuration.mapper == ToneMapper::Agx && configuration.params.agxLook == AgxLook::Golden) {
            continue;
        }
        // The published AgX inset/outset matrices are not exactly grey-preserving (the inset's rows sum to
        // 1.000136, 0.999963 and 0.999952), which tints greys by up to 4.4e-4 linear (1e-4 in sRGB code value
        // at the top, far below 1/255). Likewise Hill's output matrix, published to 5 decimals, has a last
        // row summing to 0.99999 (blue 1e-5 low). Every other curve is grey in, grey out to float precision.
        float tolerance = 2e-6f;
        if (configuration.mapper == ToneMapper::Agx) {
            tolerance = 5e-4f;
        } else if (configuration.mapper == ToneMapper::AcesFitted) {
            tolerance = 1.2e-5f;
        }
        for (const float x : {0.001f, 0.18f, 1.0f, 10.0f}) {
            const glm::vec3 out = toneMap(configuration.mapper, grey(x), configuration.params);
            EXPECT_NEAR(out.r, out.g, tolerance) << configuration.label << " " << x;
            EXPECT_NEAR(out.b, out.g, tolerance) << configuration.label << " " << x;
        }
    }
}

// --------------------------------------------------------------------------------------- names

TEST(ToneCurves, NamesRoundTrip) {
    constexpr std::array<std::string_view, 11> kExpected{
        "linear",   "reinhard",       "reinhard-extended", "hable", "lottes",
        "uchimura", "aces-narkowicz", "aces-fitted",       "aces",  "agx",
        "neutral"};
    ASSERT_EQ(toneMapperNames().size(), kExpected.size());
    for (std::size_t i = 0; i < kExpected.size(); ++i) {
        const auto mapper = ToneMapper(i);
        EXPECT_EQ(toneMapperNames()[i], kExpected[i]);
        EXPECT_EQ(toneMapperName(mapper), kExpected[i]);
        const auto parsed = parseToneMapper(kExpected[i]);
        ASSERT_TRUE(parsed.has_value()) << kExpected[i];
        EXPECT_EQ(*parsed, mapper);
    }
    EXPECT_EQ(parseToneMapper("ACES-Fitted"), ToneMapper::AcesFitted); // ASCII case-insensitive
    EXPECT_FALSE(parseToneMapper("").has_value());
    EXPECT_FALSE(parseToneMapper("filmic").has_value());
    EXPECT_FALSE(parseToneMapper("aces ").has_value());
}

TEST(ToneCurves, AgxLookNamesRoundTrip) {
    constexpr std::array<std::string_view, 3> kExpected{"base", "punchy", "golden"};
    ASSERT_EQ(agxLookNames().size(), kExpected.size());
    for (std::size_t i = 0; i < kExpected.size(); ++i) {
        const auto look = AgxLook(i);
        EXPECT_EQ(agxLookNames()[i], kExpected[i]);
        EXPECT_EQ(agxLookName(look), kExpected[i]);
        EXPECT_EQ(parseAgxLook(kExpected[i]), look);
    }
    EXPECT_EQ(parseAgxLook("Golden"), AgxLook::Golden);
    EXPECT_FALSE(parseAgxLook("default").has_value());
}

} // namespace
} // namespace photopic
