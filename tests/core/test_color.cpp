// Colour math: sRGB transfer functions, Rec.709 luma, Frostbite EV100 helpers.

#include "core/Color.h"

#include <gtest/gtest.h>

#include <cmath>

namespace photopic {
namespace {

TEST(Color, Luma709UsesRec709Weights) {
    EXPECT_FLOAT_EQ(luma709({1.0f, 0.0f, 0.0f}), 0.2126f);
    EXPECT_FLOAT_EQ(luma709({0.0f, 1.0f, 0.0f}), 0.7152f);
    EXPECT_FLOAT_EQ(luma709({0.0f, 0.0f, 1.0f}), 0.0722f);
    EXPECT_NEAR(luma709(glm::vec3(0.18f)), 0.18f, 1e-7f); // the weights sum to 1: greys keep their value
}

TEST(Color, SrgbEncodeKnownValues) {
    // Reference values computed in double from IEC 61966-2-1.
    EXPECT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_NEAR(srgbEncode(1.0f), 1.0f, 1e-7f);
    EXPECT_NEAR(srgbEncode(0.001f), 0.01292f, 1e-8f); // linear segment
    EXPECT_NEAR(srgbEncode(0.0031308f), 0.040449936f, 1e-7f);
    EXPECT_NEAR(srgbEncode(0.18f), 0.461356129500f, 1e-6f);
    EXPECT_NEAR(srgbEncode(0.5f), 0.735356983052f, 1e-6f);
    EXPECT_NEAR(srgbDecode(0.5f), 0.214041140482f, 1e-7f);
    EXPECT_NEAR(srgbDecode(0.04045f), 0.003130804954f, 1e-9f);
    EXPECT_NEAR(srgbDecode(1.0f), 1.0f, 1e-6f);
}

TEST(Color, SrgbEncodeClampsToUnitRange) {
    EXPECT_EQ(srgbEncode(-1.0f), 0.0f);
    EXPECT_EQ(srgbEncode(-1e30f), 0.0f);
    EXPECT_NEAR(srgbEncode(2.0f), 1.0f, 1e-7f);
    EXPECT_NEAR(srgbEncode(1e30f), 1.0f, 1e-7f);
}

TEST(Color, SrgbPiecesMeetAtTheBreakPoint) {
    // IEC 61966-2-1's rounded constants leave the power segment 2.9e-8 below the linear one at 0.0031308
    // (12.92 * 0.0031308 = 0.040449936, 1.055 * 0.0031308^(1/2.4) - 0.055 = 0.040449907): a step of a few
    // float ulps, far below any display quantisation. We keep the standard's constants, so the check is
    // closeness, not order.
    const float below = srgbEncode(std::nextafter(0.0031308f, 0.0f));
    const float above = srgbEncode(std::nextafter(0.0031308f, 1.0f));
    EXPECT_NEAR(below, above, 5e-8f);
    EXPECT_NEAR(srgbDecode(std::nextafter(0.04045f, 0.0f)), srgbDecode(std::nextafter(0.04045f, 1.0f)),
                1e-8f);
}

TEST(Color, SrgbRoundTripDenseGrid) {
    // Relative error below 1e-6 over [0, 1] in both directions, 2^20 + 1 samples each.
    constexpr int kSteps = 1 << 20;
    float worstLinear = 0.0f;
    float worstEncoded = 0.0f;
    for (int i = 0; i <= kSteps; ++i) {
        const float x = float(i) / float(kSteps);
        if (x > 0.0f) {
            worstLinear = std::max(worstLinear, std::abs(srgbDecode(srgbEncode(x)) - x) / x);
            worstEncoded = std::max(worstEncoded, std::abs(srgbEncode(srgbDecode(x)) - x) / x);
        } else {
            EXPECT_EQ(srgbDecode(srgbEncode(x)), 0.0f);
        }
    }
    EXPECT_LT(worstLinear, 1e-6f);
    EXPECT_LT(worstEncoded, 1e-6f);

    // Also across the linear segment's small values, log spaced down to 1e-30.
    for (int i = 0; i <= 300; ++i) {
        const float x = std::pow(10.0f, -30.0f + 0.1f * float(i)) * 0.999f;
        if (x > 1.0f) {
            break;
        }
        EXPECT_NEAR(srgbDecode(srgbEncode(x)), x, 1e-6f * x) << x;
    }
}

TEST(Color, SrgbEncodeIsMonotonic) {
    float previous = srgbEncode(0.0f);
    for (int i = 1; i <= 100000; ++i) {
        const float y = srgbEncode(float(i) / 100000.0f);
        ASSERT_GE(y, previous) << i;
        previous = y;
    }
}

TEST(Color, SrgbVectorOverloadsMatchScalar) {
    const glm::vec3 v{0.002f, 0.18f, 0.9f};
    const glm::vec3 e = srgbEncode(v);
    const glm::vec3 d = srgbDecode(v);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(e[c], srgbEncode(v[c]));
        EXPECT_EQ(d[c], srgbDecode(v[c]));
    }
}

TEST(Color, Ev100FromCamera) {
    // f/16, 1/100 s, ISO 100 ("sunny 16"): log2(256 * 100) = 14.6439.
    EXPECT_NEAR(ev100FromCamera(16.0f, 1.0f / 100.0f, 100.0f), 14.6439f, 1e-4f);
    // f/1, 1 s, ISO 100 is EV 0 by definition; doubling ISO lowers EV100 by one stop.
    EXPECT_NEAR(ev100FromCamera(1.0f, 1.0f, 100.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(ev100FromCamera(16.0f, 0.01f, 200.0f), ev100FromCamera(16.0f, 0.01f, 100.0f) - 1.0f, 1e-5f);
}

TEST(Color, Ev100FromLuminance) {
    EXPECT_NEAR(ev100FromLuminance(1.0f), 3.0f, 1e-6f); // log2(1 * 100 / 12.5)
    EXPECT_NEAR(ev100FromLuminance(1.0f, 200.0f), 4.0f, 1e-6f);
    EXPECT_NEAR(ev100FromLuminance(1.0f, 100.0f, 25.0f), 2.0f, 1e-6f);
    // A black frame gives a finite EV (luminance is floored at the smallest normal float).
    EXPECT_TRUE(std::isfinite(ev100FromLuminance(0.0f)));
    EXPECT_TRUE(std::isfinite(exposureFromEv100(ev100FromLuminance(0.0f))));
}

TEST(Color, ExposureFromEv100) {
    EXPECT_NEAR(exposureFromEv100(0.0f), 1.0f / 1.2f, 1e-7f);
    EXPECT_NEAR(exposureFromEv100(3.0f), 1.0f / 9.6f, 1e-7f);
    // Metering an average luminance L and exposing with the result puts L at K / (S * 1.2) = 0.1042 whatever
    // L is (Frostbite's auto-exposure places the scene average a little below middle grey).
    for (const float luminance : {0.01f, 1.0f, 250.0f, 1e5f}) {
        EXPECT_NEAR(luminance * exposureFromEv100(ev100FromLuminance(luminance)), 12.5f / 120.0f, 1e-6f)
            << luminance;
    }
}

} // namespace
} // namespace photopic
