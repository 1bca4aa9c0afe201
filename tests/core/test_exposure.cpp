#include "core/ExposureController.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace photopic {
namespace {

constexpr float kDt = 1.0f / 60.0f;

/// Auto exposure on, with bounds wide enough that 0.02 and 2.0 both have unclamped targets.
AutoExposureSettings wideSettings(AdaptationMode mode = AdaptationMode::Exponential) {
    AutoExposureSettings s;
    s.enabled = true;
    s.adaptation = mode;
    s.minEV = -10.0f;
    s.maxEV = 10.0f;
    return s;
}

float targetFor(float luminance) {
    return std::log2(0.18f / luminance);
}

/// Runs `frames` frames of constant luminance; returns the controller's state after them.
ExposureState run(ExposureController& c, float luminance, int frames, float dt = kDt) {
    for (int i = 0; i < frames; ++i) {
        c.update(luminance, dt);
    }
    return c.state();
}

bool allFinite(const ExposureState& s) {
    return std::isfinite(s.appliedLog2) && std::isfinite(s.targetLog2) && std::isfinite(s.meteredLuminance) &&
           std::isfinite(s.exposure);
}

void expectSameState(const ExposureState& a, const ExposureState& b) {
    EXPECT_EQ(a.appliedLog2, b.appliedLog2);
    EXPECT_EQ(a.targetLog2, b.targetLog2);
    EXPECT_EQ(a.meteredLuminance, b.meteredLuminance);
    EXPECT_EQ(a.exposure, b.exposure);
    EXPECT_EQ(a.adapting, b.adapting);
    EXPECT_EQ(a.initialized, b.initialized);
}

TEST(Exposure, FirstFrameSnapsToTarget) {
    ExposureController c(wideSettings());
    const ExposureState& s = c.update(0.02f, kDt);
    EXPECT_EQ(s.initialized, 1);
    EXPECT_EQ(s.adapting, 0);
    EXPECT_FLOAT_EQ(s.appliedLog2, targetFor(0.02f));
    EXPECT_FLOAT_EQ(s.targetLog2, targetFor(0.02f));
    EXPECT_FLOAT_EQ(s.exposure, std::exp2(targetFor(0.02f)));
    EXPECT_EQ(s.meteredLuminance, 0.02f);
}

// The eye lag: into the light with tauDarken, back into the dark with tauBrighten; after one time
// constant 1 - 1/e = 63.2% of the gap is covered.
TEST(Exposure, ExponentialStepCoversOneMinusInverseEAfterOneTimeConstant) {
    const AutoExposureSettings settings = wideSettings();
    ExposureController c(settings);
    run(c, 0.02f, 10);
    const float dark = targetFor(0.02f);
    const float bright = targetFor(2.0f);

    // Bright step: exposure falls, tauDarken = 0.3 s = 18 frames.
    const ExposureState afterTau = run(c, 2.0f, 18);
    const float coveredDown = (dark - afterTau.appliedLog2) / (dark - bright);
    EXPECT_NEAR(coveredDown, 1.0f - std::exp(-1.0f), 0.05f);
    EXPECT_GT(afterTau.appliedLog2, bright); // the lag: still over-exposed
    const ExposureState settledBright = run(c, 2.0f, 10 * 18);
    EXPECT_NEAR(settledBright.appliedLog2, bright, 0.05f);

    // Dark step back: exposure rises, tauBrighten = 1 s = 60 frames.
    const float start = settledBright.appliedLog2;
    const ExposureState afterTau2 = run(c, 0.02f, 60);
    const float coveredUp = (afterTau2.appliedLog2 - start) / (dark - start);
    EXPECT_NEAR(coveredUp, 1.0f - std::exp(-1.0f), 0.05f);
    const ExposureState settledDark = run(c, 0.02f, 10 * 60);
    EXPECT_NEAR(settledDark.appliedLog2, dark, 0.05f);
    EXPECT_TRUE(allFinite(settledDark));
}

TEST(Exposure, ExponentialMatchesClosedFormExactly) {
    // Per-frame alpha = 1 - exp(-dt/tau) composes to exp(-t/tau) for any frame times.
    AutoExposureSettings settings = wideSettings();
    settings.deadbandEV = 0.0f;
    ExposureController c(settings);
    run(c, 0.02f, 1);
    const float a0 = c.state().appliedLog2;
    const float target = targetFor(2.0f);
    double t = 0.0;
    const float dts[] = {1.0f / 30.0f, 1.0f / 144.0f, 1.0f / 60.0f, 0.05f};
    for (int i = 0; i < 40; ++i) {
        const float dt = dts[i % 4];
        c.update(2.0f, dt);
        t += double(dt);
        const double expected = target + (a0 - target) * std::exp(-t / double(settings.tauDarken));
        ASSERT_NEAR(c.state().appliedLog2, expected, 1e-4) << "t = " << t;
    }
}

TEST(Exposure, SpeedModeMatchesOneMinusExpOfSpeedTimesT) {
    AutoExposureSettings settings = wideSettings(AdaptationMode::Speed);
    settings.deadbandEV = 0.0f;
    for (const bool brighter : {true, false}) {
        ExposureController c(settings);
        const float from = brighter ? 0.02f : 2.0f;
        const float to = brighter ? 2.0f : 0.02f;
        // A brighter scene lowers exposure: speedUp (3/s); a darker one raises it: speedDown (1/s).
        const double speed = brighter ? settings.speedUp : settings.speedDown;
        run(c, from, 1);
        const double a0 = c.state().appliedLog2;
        const double target = targetFor(to);
        for (int frame = 1; frame <= 120; ++frame) {
            c.update(to, kDt);
            const double t = frame * double(kDt);
            const double covered = (c.state().appliedLog2 - a0) / (target - a0);
            ASSERT_NEAR(covered, 1.0 - std::exp(-speed * t), 1e-4)
                << "frame " << frame << " brighter " << brighter;
        }
    }
}

/// Unreal-style hybrid from distance g0: linear at s EV/s down to D, then D exp(-(s/D)(t - tl)).
double hybridClosedForm(double g0, double s, double d, double t) {
    if (g0 > d) {
        const double tl = (g0 - d) / s;
        return t <= tl ? g0 - s * t : d * std::exp(-(s / d) * (t - tl));
    }
    return g0 * std::exp(-(s / d) * t);
}

TEST(Exposure, HybridMatchesLinearThenExponentialClosedForm) {
    AutoExposureSettings settings = wideSettings(AdaptationMode::Hybrid);
    settings.deadbandEV = 0.0f;
    for (const bool brighter : {true, false}) {
        ExposureController c(settings);
        const float from = brighter ? 0.02f : 2.0f;
        const float to = brighter ? 2.0f : 0.02f;
        const double speed = brighter ? settings.speedUp : settings.speedDown;
        run(c, from, 1);
        const double target = targetFor(to);
        const double g0 = std::abs(target - c.state().appliedLog2);
        ASSERT_GT(g0, settings.transitionEV);
        const double tl = (g0 - settings.transitionEV) / speed;
        // Uneven frame times: the piecewise integration is exact, so the frame split must not matter.
        const float dts[] = {1.0f / 60.0f, 1.0f / 24.0f, 1.0f / 144.0f, 0.09f};
        const std::vector<double> checks{0.25, 0.5 * tl, tl - 0.01, tl + 0.01, tl + 0.3, tl + 1.0, tl + 2.0};
        double t = 0.0;
        std::size_t next = 0;
        int frame = 0;
        while (next < checks.size()) {
            // Land exactly on each check time.
            float dt = dts[frame++ % 4];
            if (t + double(dt) >= checks[next]) {
                dt = float(checks[next] - t);
            }
            c.update(to, dt);
            t += double(dt);
            if (std::abs(t - checks[next]) < 1e-6) {
                const double remaining = std::abs(target - c.state().appliedLog2);
                EXPECT_NEAR(remaining, hybridClosedForm(g0, speed, settings.transitionEV, t), 2e-4)
                    << "t = " << t << " brighter " << brighter;
                ++next;
            }
        }
    }
}

TEST(Exposure, HybridSlopesMatchAtTheTransition) {
    // Both branches move at s EV/s at |gap| = D: 1 ms from just outside or just inside covers the same.
    AutoExposureSettings settings = wideSettings(AdaptationMode::Hybrid);
    settings.deadbandEV = 0.0f;
    const float d = settings.transitionEV;
    const auto stepFrom = [&](float gap) {
        ExposureState s;
        s.initialized = 1;
        s.appliedLog2 = gap; // target 0, exposure falls -> speedUp
        return s.appliedLog2 - adaptExposure(settings, s, 0.0f, 1e-3f).appliedLog2;
    };
    EXPECT_NEAR(stepFrom(d + 1e-3f), settings.speedUp * 1e-3f, 1e-5f);
    EXPECT_NEAR(stepFrom(d - 1e-3f), settings.speedUp * 1e-3f, 2e-5f);
}

TEST(Exposure, DeadbandIgnoresWobbleAndHasHysteresis) {
    AutoExposureSettings settings = wideSettings();
    ExposureController c(settings);
    run(c, 0.18f, 5);
    const float settled = c.state().appliedLog2;
    // A 0.01 EV wobble (half the 0.02 EV deadband) never moves exposure.
    for (int i = 0; i < 200; ++i) {
        c.update(i % 2 ? 0.18f * std::exp2(0.01f) : 0.18f, kDt);
        ASSERT_EQ(c.state().appliedLog2, settled);
        ASSERT_EQ(c.state().adapting, 0);
    }
    // A 0.5 EV step does, and adaptation continues inside the deadband until |gap| < 0.1 deadband.
    const float step = 0.18f * std::exp2(0.5f);
    c.update(step, kDt);
    EXPECT_EQ(c.state().adapting, 1);
    EXPECT_LT(c.state().appliedLog2, settled);
    bool adaptedInsideDeadband = false;
    for (int i = 0; i < 600 && c.state().adapting; ++i) {
        const float gapBefore = std::abs(c.state().targetLog2 - c.state().appliedLog2);
        c.update(step, kDt);
        if (c.state().adapting && gapBefore < settings.deadbandEV) {
            adaptedInsideDeadband = true;
        }
    }
    EXPECT_TRUE(adaptedInsideDeadband);
    EXPECT_EQ(c.state().adapting, 0);
    EXPECT_LT(std::abs(c.state().targetLog2 - c.state().appliedLog2),
              kDeadbandExitFraction * settings.deadbandEV);
}

TEST(Exposure, FrameTimeIsClampedToMaxDt) {
    const AutoExposureSettings settings = wideSettings();
    ExposureController hitch(settings), normal(settings);
    run(hitch, 0.02f, 1);
    run(normal, 0.02f, 1);
    hitch.update(2.0f, 10.0f); // a 10 s hitch counts as maxDt = 0.1 s
    normal.update(2.0f, settings.maxDt);
    EXPECT_EQ(hitch.state().appliedLog2, normal.state().appliedLog2);

    const float before = hitch.state().appliedLog2;
    for (const float dt : {-1.0f, 0.0f, std::numeric_limits<float>::quiet_NaN()}) {
        hitch.update(2.0f, dt);
        EXPECT_EQ(hitch.state().appliedLog2, before) << dt;
        EXPECT_TRUE(allFinite(hitch.state()));
    }
    hitch.update(2.0f, std::numeric_limits<float>::infinity());
    EXPECT_LT(hitch.state().appliedLog2, before);
    EXPECT_TRUE(allFinite(hitch.state()));
}

TEST(Exposure, ResetSnapsToTheNextTarget) {
    ExposureController c(wideSettings());
    run(c, 0.02f, 100);
    c.reset();
    EXPECT_EQ(c.state().initialized, 0);
    const ExposureState& s = c.update(2.0f, kDt);
    EXPECT_FLOAT_EQ(s.appliedLog2, targetFor(2.0f));
    EXPECT_EQ(s.initialized, 1);
}

TEST(Exposure, InvalidLuminanceLeavesStateUnchanged) {
    ExposureController c(wideSettings());
    run(c, 0.02f, 1);
    c.update(2.0f, kDt); // mid-adaptation
    const ExposureState before = c.state();
    for (const float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
          -std::numeric_limits<float>::infinity(), 0.0f, -1.0f, std::numeric_limits<float>::denorm_min()}) {
        c.update(bad, kDt);
        expectSameState(c.state(), before);
        EXPECT_TRUE(allFinite(c.state())) << bad;
    }
    // Also before the first valid reading: nothing is initialised.
    ExposureController fresh(wideSettings());
    fresh.update(std::numeric_limits<float>::quiet_NaN(), kDt);
    EXPECT_EQ(fresh.state().initialized, 0);
    EXPECT_TRUE(allFinite(fresh.state()));
}

TEST(Exposure, AdaptExposureIgnoresNonFiniteTarget) {
    const AutoExposureSettings settings = wideSettings();
    ExposureState prev;
    prev.initialized = 1;
    prev.appliedLog2 = 1.0f;
    const ExposureState next = adaptExposure(settings, prev, std::numeric_limits<float>::quiet_NaN(), kDt);
    expectSameState(next, prev);
    // Not initialised: snaps whatever dt says.
    const ExposureState snapped = adaptExposure(settings, ExposureState{}, 2.5f, 0.0f);
    EXPECT_EQ(snapped.appliedLog2, 2.5f);
    EXPECT_EQ(snapped.initialized, 1);
}

TEST(Exposure, ManualEVMultipliesWithAutoExposure) {
    AutoExposureSettings settings = wideSettings();
    ExposureController c(settings);
    const ExposureState& s = c.update(0.5f, kDt, 1.5f);
    EXPECT_FLOAT_EQ(s.exposure, std::exp2(1.5f + targetFor(0.5f)));
    c.update(0.5f, kDt, -2.0f);
    EXPECT_FLOAT_EQ(c.state().exposure, std::exp2(-2.0f + targetFor(0.5f)));

    settings.enabled = false;
    ExposureController off(settings);
    off.update(0.5f, kDt, 1.5f);
    EXPECT_FLOAT_EQ(off.state().exposure, std::exp2(1.5f));
    EXPECT_FLOAT_EQ(off.state().targetLog2, targetFor(0.5f));
    // Enabling later snaps instead of sweeping from a stale value.
    settings.enabled = true;
    off.setSettings(settings);
    off.update(0.5f, kDt, 0.0f);
    EXPECT_FLOAT_EQ(off.state().appliedLog2, targetFor(0.5f));
}

TEST(Exposure, TargetIsClampedToMinMaxEV) {
    AutoExposureSettings settings; // -2 .. +2 EV (multipliers 0.25 .. 4)
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 0.18f), 0.0f);
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 100.0f), -2.0f);
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 1e-6f), 2.0f);
    settings.compensationEV = 1.0f;
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 0.18f), 1.0f);
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 0.09f), 2.0f);
    // Lmin = 1e-4 floors the luminance before the log.
    settings = wideSettings();
    settings.maxEV = 20.0f;
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 1e-7f), std::log2(0.18f) - std::log2(kExposureMinLuminance));
    EXPECT_TRUE(std::isfinite(exposureTargetLog2(settings, std::numeric_limits<float>::quiet_NaN())));
}

TEST(Exposure, CompensationCurveInterpolatesAndClampsAtTheEnds) {
    const CurvePoints curve{{-4.0f, 1.0f}, {0.0f, 0.0f}, {4.0f, -2.0f}};
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, -10.0f), 1.0f);
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, -4.0f), 1.0f);
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, -2.0f), 0.5f);
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, 0.0f), 0.0f);
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, 1.0f), -0.5f);
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, 4.0f), -2.0f);
    EXPECT_FLOAT_EQ(compensationCurveEV(curve, 10.0f), -2.0f);
    EXPECT_EQ(compensationCurveEV({}, 3.0f), 0.0f);
    EXPECT_EQ(compensationCurveEV({{2.0f, 0.75f}}, -3.0f), 0.75f);

    AutoExposureSettings settings = wideSettings();
    settings.compensationCurve = curve;
    // L = 4: x = 2, curve -1: target = log2(0.18) - 2 - 1.
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 4.0f), std::log2(0.18f) - 3.0f);
    EXPECT_FLOAT_EQ(exposureTargetLog2(settings, 1.0f / 64.0f), std::log2(0.18f) + 6.0f + 1.0f);
}

} // namespace
} // namespace photopic
