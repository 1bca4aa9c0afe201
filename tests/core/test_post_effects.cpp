// CPU side of bloom, grading, display effects and quality tiers: the constants the shaders get, and the new
// settings keys (paths, ranges, the common keys of older files).

#include "core/Bloom.h"
#include "core/ColorGrading.h"
#include "core/DisplayEffects.h"
#include "core/Quality.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numeric>
#include <vector>

namespace photopic {
namespace {

TEST(Bloom, KneeConstantsFollowTheFormula) {
    const glm::vec4 k = bloomKneeConstants(1.0f, 0.5f);
    const float knee = 0.5f + 1e-5f;
    EXPECT_FLOAT_EQ(k.x, 1.0f);
    EXPECT_FLOAT_EQ(k.y, 1.0f - knee);
    EXPECT_FLOAT_EQ(k.z, 2.0f * knee);
    EXPECT_FLOAT_EQ(k.w, 0.25f / knee);
}

TEST(Bloom, SoftKneeIsZeroBelowContinuousAndLinearAbove) {
    const glm::vec4 k = bloomKneeConstants(1.0f, 0.5f);
    EXPECT_EQ(bloomPrefilterFactor(0.4f, k), 0.0f);                 // below T - knee
    EXPECT_GT(bloomPrefilterFactor(0.8f, k), 0.0f);                 // inside the knee
    EXPECT_NEAR(bloomPrefilterFactor(3.0f, k) * 3.0f, 2.0f, 1e-4f); // above T + knee: br - T
    // Continuous at both ends of the knee.
    for (float edge : {0.5f, 1.5f}) {
        EXPECT_NEAR(bloomPrefilterFactor(edge - 1e-3f, k) * (edge - 1e-3f),
                    bloomPrefilterFactor(edge + 1e-3f, k) * (edge + 1e-3f), 3e-3f);
    }
    // A hard threshold (knee 0) passes nothing at or below T.
    const glm::vec4 hard = bloomKneeConstants(2.0f, 0.0f);
    EXPECT_NEAR(bloomPrefilterFactor(2.0f, hard), 0.0f, 1e-4f);
    EXPECT_NEAR(bloomPrefilterFactor(4.0f, hard) * 4.0f, 2.0f, 1e-4f);
}

TEST(Bloom, LevelWeightsSumToOne) {
    for (float radius : {0.0f, 0.3f, 0.7f, 1.0f}) {
        for (int levels : {1, 2, 6, 9}) {
            float sum = 0;
            for (int i = 0; i < levels; ++i) {
                sum += bloomLevelWeight(radius, i, levels);
            }
            EXPECT_NEAR(sum, 1.0f, 1e-5f) << radius << " " << levels;
        }
    }
    EXPECT_FLOAT_EQ(bloomLevelWeight(0.7f, 0, 6), 0.3f);
}

TEST(Bloom, MipChainShape) {
    EXPECT_EQ(bloomMipSize({1920, 1080}, 2, 0), glm::ivec2(960, 540));
    EXPECT_EQ(bloomMipSize({1920, 1080}, 4, 1), glm::ivec2(240, 135));
    EXPECT_EQ(bloomMipCount({1920, 1080}, 2, 6), 6);
    EXPECT_EQ(bloomMipCount({16, 16}, 2, 6), 2); // 8, 4: a 2-texel level is not kept
    EXPECT_EQ(bloomMipCount({2, 2}, 2, 6), 1);   // tiny images still get one level
}

TEST(Bloom, LevelsCoverTheFrameWithWholeTexels) {
    EXPECT_EQ(bloomLevelScale(2, 0), 2);
    EXPECT_EQ(bloomLevelScale(4, 3), 32);
    EXPECT_EQ(bloomLevelFrame({1920, 1080}, 2, 0), glm::ivec2(960, 540));
    EXPECT_EQ(bloomLevelFrame({1920, 1080}, 2, 3), glm::ivec2(120, 68)); // 67.5: the last row partly out
    EXPECT_EQ(bloomLevelFrame({61, 37}, 4, 0), glm::ivec2(16, 10));
    EXPECT_EQ(bloomLevelFrame({3, 3}, 4, 4), glm::ivec2(1, 1));
}

// The blur's weights are the 17-texel Gaussian of sigma 2, renormalised.
TEST(Bloom, BlurWeightsAreTheTruncatedGaussian) {
    const auto w = bloomBlurWeights();
    double sum = w[0];
    for (int k = 1; k <= kBloomBlurReach; ++k)
        sum += 2.0 * w[std::size_t(k)];
    EXPECT_NEAR(sum, 1.0, 1e-6);
    for (int k = 1; k <= kBloomBlurReach; ++k) {
        EXPECT_NEAR(w[std::size_t(k)] / w[0], std::exp(-double(k * k) / (2.0 * kBloomBlurSigma * kBloomBlurSigma)),
                    1e-6)
            << k;
    }
}

// The prefilter's weights are binomial: they sum to 1, are symmetric, and the quarter-size one is the
// half-size one at twice the spacing convolved with it.
TEST(Bloom, PrefilterWeightsAreBinomial) {
    for (const int divisor : {2, 4}) {
        const auto w = bloomPrefilterWeights(divisor);
        EXPECT_EQ(w.size(), divisor == 2 ? 4u : 10u);
        EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-7);
        for (std::size_t i = 0; i < w.size(); ++i)
            EXPECT_FLOAT_EQ(w[i], w[w.size() - 1 - i]);
    }
    const auto half = bloomPrefilterWeights(2);
    const auto quarter = bloomPrefilterWeights(4);
    for (std::size_t k = 0; k < quarter.size(); ++k) {
        double want = 0.0;
        for (std::size_t i = 0; i < half.size(); ++i) // [1 3 3 1] at spacing 2 ...
            for (std::size_t j = 0; j < half.size(); ++j) // ... convolved with [1 3 3 1]
                want += 2 * i + j == k ? double(half[i]) * double(half[j]) : 0.0;
        EXPECT_NEAR(quarter[k], want, 1e-7) << k;
    }
}

TEST(ColorGrading, NeutralWhiteBalanceIsIdentity) {
    const glm::mat3 m = whiteBalanceMatrix(0, 0);
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            EXPECT_FLOAT_EQ(m[c][r], c == r ? 1.0f : 0.0f);
        }
    }
}

TEST(ColorGrading, TemperatureWarmsAndTintShiftsGreenMagenta) {
    const glm::vec3 grey(0.18f);
    const glm::vec3 warm = whiteBalanceMatrix(0.5f, 0) * grey;
    const glm::vec3 cool = whiteBalanceMatrix(-0.5f, 0) * grey;
    EXPECT_GT(warm.r / warm.b, 1.05f);
    EXPECT_LT(cool.r / cool.b, 0.95f);
    const glm::vec3 magenta = whiteBalanceMatrix(0, 0.5f) * grey;
    EXPECT_LT(magenta.g, 0.5f * (magenta.r + magenta.b));
    // A small change stays close to identity (no jump away from 0).
    const glm::vec3 tiny = whiteBalanceMatrix(0.001f, 0) * grey;
    EXPECT_NEAR(tiny.r, 0.18f, 1e-3f);
}

TEST(ColorGrading, ContrastPivotsOnMiddleGreySaturationOnLuma) {
    ColorGradingSettings s;
    s.contrast = 1.5f;
    const glm::vec3 grey = gradeColor(glm::vec3(0.18f), s);
    EXPECT_NEAR(grey.g, 0.18f, 1e-5f);
    EXPECT_NEAR(gradeColor(glm::vec3(0.72f), s).g, 0.18f * std::pow(4.0f, 1.5f), 1e-4f); // +2 stops -> +3
    s = {};
    s.saturation = 0;
    const glm::vec3 c = gradeColor({1.0f, 0.2f, 0.1f}, s);
    EXPECT_NEAR(c.r, c.g, 1e-6f);
    EXPECT_NEAR(c.g, c.b, 1e-6f);
    s = {};
    s.gain = glm::vec3(2.0f);
    s.lift = glm::vec3(0.1f);
    s.gamma = glm::vec3(2.0f);
    EXPECT_NEAR(gradeColor(glm::vec3(0.5f), s).r, std::sqrt(1.1f), 1e-5f);
    EXPECT_EQ(gradeColor(glm::vec3(0.3f), ColorGradingSettings{}), glm::vec3(0.3f));
}

TEST(DisplayEffects, VignetteReachesItsIntensityAtTheCorners) {
    EXPECT_FLOAT_EQ(vignetteFactor(0.5f, 0.5f, 0.4f, 2.0f), 1.0f);
    EXPECT_NEAR(vignetteFactor(0.0f, 0.0f, 0.4f, 2.0f), 0.6f, 1e-6f);
    EXPECT_NEAR(vignetteFactor(1.0f, 0.5f, 0.4f, 2.0f), 1.0f - 0.4f * 0.5f, 1e-5f); // r^2 = 0.5 at an edge
}

TEST(DisplayEffects, DazzleOnlyWhenExposureIsAboveTarget) {
    EXPECT_EQ(dazzleAmount(-1.0f, 0.0f, 2.0f, 1.0f), 0.0f);
    EXPECT_FLOAT_EQ(dazzleAmount(1.0f, 0.0f, 2.0f, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(dazzleAmount(5.0f, 0.0f, 2.0f, 0.8f), 0.8f);
}

TEST(Quality, TiersShrinkWorkAndLegacyIsLdr) {
    EXPECT_TRUE(qualityTier(Quality::Ultra).hdrPath);
    EXPECT_GT(qualityTier(Quality::Ultra).bloomMips, qualityTier(Quality::High).bloomMips);
    EXPECT_GT(qualityTier(Quality::High).bloomMips, qualityTier(Quality::Medium).bloomMips);
    EXPECT_GT(qualityTier(Quality::Medium).bloomMips, qualityTier(Quality::Low).bloomMips);
    EXPECT_EQ(qualityTier(Quality::Medium).bloomFirstDivisor, 4);
    EXPECT_FALSE(qualityTier(Quality::Low).lensFlare);
    const QualityTier legacy = qualityTier(Quality::Legacy);
    EXPECT_FALSE(legacy.hdrPath);
    EXPECT_FALSE(legacy.bloom);
    EXPECT_FALSE(legacy.lensFlare);
    EXPECT_EQ(qualityName(Quality::Legacy), "legacy");
}

TEST(PostEffectSettings, LegacyKeysLoad) {
    const char* doc = R"({"postEffects": {
        "bloom": {"enabled": true, "threshold": 1.0, "intensity": 0.5},
        "fxaa": {"enabled": true},
        "vignette": {"enabled": false, "intensity": 0.5, "chromaticAberration": 0.003},
        "colorGrading": {"enabled": false, "contrast": 1.0, "saturation": 1.0, "temperature": 0.0}}})";
    Settings s;
    // Older files' bloom pairs a threshold with an additive intensity: threshold mode.
    ASSERT_TRUE(readSettingsJson(R"({"postEffects": {"bloom": {"mode": "threshold"}}})", s).empty());
    const auto issues = readSettingsJson(doc, s);
    ASSERT_TRUE(issues.empty()) << formatSettingsIssues(issues);
    EXPECT_TRUE(s.fxaa.enabled);
    EXPECT_FLOAT_EQ(s.bloom.intensity, 0.5f);
    EXPECT_FLOAT_EQ(s.vignette.chromaticAberration, 0.003f);
}

TEST(PostEffectSettings, IssuesNamePathsAndRanges) {
    Settings s;
    auto issues = readSettingsJson(R"({"postEffects": {"bloom": {"knee": 2}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::OutOfRange);
    EXPECT_EQ(issues[0].path, "postEffects.bloom.knee");
    issues = readSettingsJson(R"({"postEffects": {"bloom": {"mode": "additive"}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::BadEnum);
    issues = readSettingsJson(R"({"postEffects": {"bloom": {"intensity": 2}}})", s); // mix factor > 1
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::Constraint);
    EXPECT_EQ(issues[0].path, "postEffects.bloom.intensity");
    issues = readSettingsJson(R"({"postEffects": {"quality": "epic"}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].path, "postEffects.quality");
    issues = readSettingsJson(R"({"postEffects": {"colorGrading": {"lift": [0, 0]}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::WrongType);
    issues = readSettingsJson(R"({"postEffects": {"ssao": {"enabled": true, "quality": "ultra"}}})", s);
    EXPECT_TRUE(issues.empty());
    issues = readSettingsJson(R"({"postEffects": {"ssao": {"radius": 0}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::OutOfRange);
    EXPECT_EQ(issues[0].path, "postEffects.ssao.radius");
    issues = readSettingsJson(R"({"postEffects": {"ssgi": {"enabled": true}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::UnknownKey); // no key for an effect that does not exist
    applySettingsOverride(s, "quality=legacy");
    EXPECT_EQ(s.quality, Quality::Legacy);
    applySettingsOverride(s, "grain.intensity=0.1");
    EXPECT_FLOAT_EQ(s.grain.intensity, 0.1f);
}

TEST(PostEffectSettings, DefaultsListExactlyTheImplementedEffects) {
    const nlohmann::json post = settingsToJsonValue(Settings{})["postEffects"];
    for (const char* key : {"bloom", "colorGrading", "fxaa", "lensFlare", "vignette", "grain", "dazzle"}) {
        ASSERT_TRUE(post.contains(key)) << key;
        EXPECT_TRUE(post[key].contains("enabled")) << key;
    }
    EXPECT_EQ(post["quality"], "high");
    EXPECT_EQ(post["bloom"]["mode"], "energy-conserving");
    EXPECT_TRUE(post["bloom"]["enabled"].get<bool>());
    for (const char* off : {"colorGrading", "fxaa", "lensFlare", "vignette", "grain", "dazzle"}) {
        EXPECT_FALSE(post[off]["enabled"].get<bool>()) << off;
    }
    Settings loaded;
    ASSERT_TRUE(readSettingsJson(settingsToJson(Settings{}), loaded).empty());
}

} // namespace
} // namespace photopic
