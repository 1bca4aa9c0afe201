#pragma once
// The tabletop acceptance (issue 5): at the indoor -> outdoor crossing the applied exposure starts well above
// its target and settles with tauDarken; at the outdoor -> indoor crossing it starts well below and settles
// with tauBrighten; both fitted time constants within 10% of the model. Shared by the CPU-probe and GPU
// walks.

#include "common/TransitionAnalysis.h"
#include "core/settings/AutoExposureSettings.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <span>
#include <utility>
#include <vector>

namespace photopic::test {

/// Checks the two crossings in `samples`; returns {stepping out, stepping in} for frame-level checks (empty
/// vector when the checks already failed).
inline std::vector<Transition> expectEyeLag(std::span<const TelemetrySample> samples,
                                            const AutoExposureSettings& ae) {
    const auto transitions = analyzeTransitions(samples, ae);
    for (const Transition& t : transitions) {
        std::printf("%s\n", describeTransition(t).c_str());
    }
    if (transitions.size() < 2) {
        ADD_FAILURE() << "expected two crossings, found " << transitions.size();
        return {};
    }
    const Transition& out = transitions[0];
    const Transition& in = transitions[1];
    EXPECT_EQ(out.kind, TransitionKind::StepOutside);
    EXPECT_EQ(in.kind, TransitionKind::StepInside);
    EXPECT_LT(in.crossingTimeS, 20.0f); // the walk crosses both ways within its first 20 s
    // Stepping out: exposure starts well above its target (the blow-out) and falls with tauDarken.
    EXPECT_GT(out.initialGapEV, 2.0f);
    EXPECT_TRUE(out.fitted && out.settled);
    EXPECT_NEAR(out.fittedTauS, ae.tauDarken, 0.1f * ae.tauDarken);
    // Stepping in: it starts well below and rises with tauBrighten.
    EXPECT_LT(in.initialGapEV, -2.0f);
    EXPECT_TRUE(in.fitted && in.settled);
    EXPECT_NEAR(in.fittedTauS, ae.tauBrighten, 0.1f * ae.tauBrighten);
    if (!(out.fitted && out.settled && in.fitted && in.settled)) {
        return {};
    }
    return {out, in};
}

} // namespace photopic::test
