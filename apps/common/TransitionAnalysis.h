#pragma once
// Eye-lag transitions in exposure telemetry (the exposure lags, then settles): where a subject crosses
// between indoors and outdoors, how far the applied exposure started from its target, how long it took to
// settle and which time constant it followed. GL-free: the demo and the acceptance tests read it from
// telemetry rows.
//
// For each crossing of outdoors through 0.5 at sample c (outdoors[c - 1] < 0.5 <= outdoors[c] steps outside;
// the reverse steps inside), within the window [c - 0.5 s, next crossing or the end):
//   gap(i) = applied(i) - target(i)   (EV; > 0 over-exposed: the blow-out of stepping into light)
//   start  = the sample of largest |gap| in [c - 0.5 s, c + 1.5 s] (the target moves over a few probes while
//            the probe taps cross the threshold; the decay is measured from its peak)
//   fitted tau   = time from start until |gap| first falls to (1 - 0.632) |gap(start)| with the same sign,
//                  linear between samples (an exponential e^(-t/tau) covers 63.2% of its gap in tau)
//   settle time  = time from start until |gap| first falls to settleEV
//   expected tau = tauDarken when exposure falls (gap > 0), tauBrighten when it rises.

#include "core/settings/AutoExposureSettings.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace photopic {

/// One frame of telemetry.
struct TelemetrySample {
    float timeS = 0.0f;        ///< s of frame time
    float measuredLuma = 0.0f; ///< scene-linear luma under the subject
    float targetLog2 = 0.0f;   ///< EV
    float appliedLog2 = 0.0f;  ///< EV
    float outdoors = 0.0f;     ///< 0..1
};

enum class TransitionKind {
    StepOutside, ///< indoors -> outdoors: the scene brightens, exposure starts too high and falls
    StepInside,  ///< outdoors -> indoors: the scene darkens, exposure starts too low and rises
};

struct Transition {
    TransitionKind kind = TransitionKind::StepOutside;
    std::size_t crossingIndex = 0; ///< first sample on the new side
    float crossingTimeS = 0.0f;
    std::size_t startIndex = 0; ///< sample of the largest gap
    float startTimeS = 0.0f;
    float initialGapEV = 0.0f;    ///< applied - target at the start (> 0: over-exposed)
    bool settled = false;         ///< |gap| reached settleEV inside the window
    float settleTimeS = 0.0f;     ///< s from the start to |gap| <= settleEV (valid when settled)
    std::size_t settledIndex = 0; ///< first settled sample (valid when settled)
    bool fitted = false;          ///< |gap| reached 36.8% of the initial gap inside the window
    float fittedTauS = 0.0f;      ///< s, time to cover 63.2% of the initial gap
    float expectedTauS = 0.0f;    ///< s, tauDarken or tauBrighten by the direction exposure moved
    [[nodiscard]] float tauError() const {
        return expectedTauS > 0 ? fittedTauS / expectedTauS - 1.0f : 0.0f;
    }
};

/// Finds and measures every crossing (rules above). `settings` supplies tauDarken and tauBrighten.
[[nodiscard]] std::vector<Transition> analyzeTransitions(std::span<const TelemetrySample> samples,
                                                         const AutoExposureSettings& settings,
                                                         float settleEV = 0.1f);

/// One line per transition: "t=3.97 s step outside: applied +2.85 EV over target, settled to 0.1 EV in
/// 1.07 s, tau 0.301 s (tauDarken 0.300 s, +0.3%)".
[[nodiscard]] std::string describeTransition(const Transition& t);

} // namespace photopic
