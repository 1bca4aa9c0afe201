// Transition analysis on synthetic telemetry made with core's ExposureController: it must find each crossing,
// the blow-out sign and recover tauDarken / tauBrighten.

#include "core/ExposureController.h"
#include "common/TransitionAnalysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace photopic {
namespace {

struct Walk {
    float insideLuma = 0.05f;
    float outsideLuma = 2.0f;
    float stepOut = 4.0f;
    float stepIn = 12.0f;
    float probeHz = 10.0f; ///< the luma the controller sees only changes this often
};

std::vector<TelemetrySample> simulate(const AutoExposureSettings& ae, const Walk& w, float fps,
                                      float seconds) {
    ExposureController controller(ae);
    std::vector<TelemetrySample> samples;
    const float dt = 1.0f / fps;
    const int frames = int(seconds * fps);
    const int probeEvery = std::max(1, int(std::lround(fps / w.probeHz)));
    float held = 0.0f;
    for (int i = 0; i < frames; ++i) {
        const float t = float(i) * dt;
        const bool outside = t >= w.stepOut && t < w.stepIn;
        // A little flicker indoors, as torches do.
        const float luma = outside ? w.outsideLuma : w.insideLuma * (1.0f + 0.02f * std::sin(7.0f * t));
        if (i % probeEvery == 0) {
            held = luma;
        }
        const ExposureState& s = controller.update(held, dt);
        samples.push_back({t, held, s.targetLog2, s.appliedLog2, outside ? 1.0f : 0.0f});
    }
    return samples;
}

AutoExposureSettings eyeLagSettings() {
    AutoExposureSettings ae;
    ae.enabled = true;
    ae.minEV = -4.0f;
    ae.maxEV = 4.0f;
    return ae; // tauBrighten 1 s, tauDarken 0.3 s
}

TEST(TransitionAnalysis, RecoversBothTimeConstantsWithinTenPercent) {
    const AutoExposureSettings ae = eyeLagSettings();
    const auto samples = simulate(ae, {}, 30.0f, 20.0f);
    const auto transitions = analyzeTransitions(samples, ae);
    ASSERT_EQ(transitions.size(), 2u);

    const Transition& out = transitions[0];
    EXPECT_EQ(out.kind, TransitionKind::StepOutside);
    EXPECT_NEAR(out.crossingTimeS, 4.0f, 1.0f / 30.0f);
    // Blow-out: 5.3 EV over target, less the first step the controller takes in the frame the target jumps.
    EXPECT_NEAR(out.initialGapEV, std::log2(2.0f / 0.05f) * std::exp(-1.0f / 30.0f / ae.tauDarken), 0.1f);
    ASSERT_TRUE(out.fitted);
    EXPECT_NEAR(out.fittedTauS, ae.tauDarken, 0.1f * ae.tauDarken);
    EXPECT_EQ(out.expectedTauS, ae.tauDarken);
    ASSERT_TRUE(out.settled);
    // Exponential: ln(5.3 / 0.1) tau = 3.97 tau.
    EXPECT_NEAR(out.settleTimeS, std::log(out.initialGapEV / 0.1f) * ae.tauDarken, 0.1f);

    const Transition& in = transitions[1];
    EXPECT_EQ(in.kind, TransitionKind::StepInside);
    EXPECT_NEAR(in.crossingTimeS, 12.0f, 1.0f / 30.0f);
    EXPECT_LT(in.initialGapEV, -5.0f); // too dark right after stepping in
    ASSERT_TRUE(in.fitted);
    EXPECT_NEAR(in.fittedTauS, ae.tauBrighten, 0.1f * ae.tauBrighten);
    EXPECT_EQ(in.expectedTauS, ae.tauBrighten);
    ASSERT_TRUE(in.settled);
    EXPECT_GT(in.settleTimeS, 3.0f);
    EXPECT_LT(in.settleTimeS, 6.0f);
    EXPECT_NE(describeTransition(in).find("tauBrighten"), std::string::npos);
}

TEST(TransitionAnalysis, OtherTimeConstantsAndFrameRates) {
    for (const float fps : {15.0f, 24.0f, 60.0f}) {
        AutoExposureSettings ae = eyeLagSettings();
        ae.tauBrighten = 2.0f;
        ae.tauDarken = 0.5f;
        const auto transitions = analyzeTransitions(simulate(ae, {}, fps, 22.0f), ae);
        ASSERT_EQ(transitions.size(), 2u) << fps;
        EXPECT_NEAR(transitions[0].fittedTauS, 0.5f, 0.05f) << fps;
        EXPECT_NEAR(transitions[1].fittedTauS, 2.0f, 0.2f) << fps;
        EXPECT_LT(std::abs(transitions[0].tauError()), 0.1f) << fps;
        EXPECT_LT(std::abs(transitions[1].tauError()), 0.1f) << fps;
    }
}

TEST(TransitionAnalysis, ClampedTargetsStillShowTheLag) {
    AutoExposureSettings ae = eyeLagSettings();
    ae.minEV = -2.0f; // multiplier bounds 0.25 .. 4
    ae.maxEV = 2.0f;
    const auto transitions = analyzeTransitions(simulate(ae, {}, 30.0f, 20.0f), ae);
    ASSERT_EQ(transitions.size(), 2u);
    // From log2(0.18 / 0.05) = 1.85 down to the clamp at -2, less the first step.
    EXPECT_NEAR(transitions[0].initialGapEV, 3.85f * std::exp(-1.0f / 30.0f / ae.tauDarken), 0.1f);
    EXPECT_NEAR(transitions[0].fittedTauS, ae.tauDarken, 0.1f * ae.tauDarken);
    EXPECT_NEAR(transitions[1].fittedTauS, ae.tauBrighten, 0.1f * ae.tauBrighten);
}

TEST(TransitionAnalysis, NoCrossingNoTransition) {
    std::vector<TelemetrySample> samples(100);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        samples[i].timeS = float(i) / 30.0f;
    }
    EXPECT_TRUE(analyzeTransitions(samples, eyeLagSettings()).empty());
    EXPECT_TRUE(analyzeTransitions({}, eyeLagSettings()).empty());
}

} // namespace
} // namespace photopic
