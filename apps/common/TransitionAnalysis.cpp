#include "common/TransitionAnalysis.h"

#include <fmt/format.h>

#include <cmath>

namespace photopic {

namespace {

/// Window before a crossing in which the gap may already peak (the probe taps reach the doorway first).
constexpr float kLeadS = 0.5f;
/// Window after a crossing in which the gap peaks (a few probes at 5-10 Hz).
constexpr float kPeakSearchS = 1.5f;
/// 1 - 0.632: an exponential has 36.8% of its gap left after one time constant.
constexpr float kRemainingAfterTau = 0.36787944f;

float gapAt(const TelemetrySample& s) {
    return s.appliedLog2 - s.targetLog2;
}

/// Time at which |gap| first falls to `level` at or after `from` (gap keeps the sign of `sign`), linear
/// between samples; false when it does not before `end`.
bool firstTimeGapBelow(std::span<const TelemetrySample> s, std::size_t from, std::size_t end, float level,
                       float sign, float& time, std::size_t& index) {
    for (std::size_t i = from + 1; i < end; ++i) {
        const float g = gapAt(s[i]) * sign;
        if (g <= level) {
            const float gPrev = gapAt(s[i - 1]) * sign;
            const float f = gPrev > g ? (gPrev - level) / (gPrev - g) : 1.0f;
            time = s[i - 1].timeS + (s[i].timeS - s[i - 1].timeS) * f;
            index = i;
            return true;
        }
    }
    return false;
}

} // namespace

std::vector<Transition> analyzeTransitions(std::span<const TelemetrySample> samples,
                                           const AutoExposureSettings& settings, float settleEV) {
    std::vector<std::size_t> crossings;
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const bool wasOut = samples[i - 1].outdoors >= 0.5f;
        const bool isOut = samples[i].outdoors >= 0.5f;
        if (wasOut != isOut) {
            crossings.push_back(i);
        }
    }
    std::vector<Transition> out;
    for (std::size_t k = 0; k < crossings.size(); ++k) {
        const std::size_t c = crossings[k];
        const std::size_t end = k + 1 < crossings.size() ? crossings[k + 1] : samples.size();
        Transition t;
        t.kind = samples[c].outdoors >= 0.5f ? TransitionKind::StepOutside : TransitionKind::StepInside;
        t.crossingIndex = c;
        t.crossingTimeS = samples[c].timeS;
        const float expectedSign = t.kind == TransitionKind::StepOutside ? 1.0f : -1.0f;
        std::size_t first = c;
        while (first > 0 && samples[first - 1].timeS >= t.crossingTimeS - kLeadS &&
               (k == 0 || first - 1 >= crossings[k - 1])) {
            --first;
        }
        std::size_t start = c;
        float best = -1.0f;
        for (std::size_t i = first; i < end && samples[i].timeS <= t.crossingTimeS + kPeakSearchS; ++i) {
            const float g = gapAt(samples[i]) * expectedSign;
            if (g > best) {
                best = g;
                start = i;
            }
        }
        t.startIndex = start;
        t.startTimeS = samples[start].timeS;
        t.initialGapEV = gapAt(samples[start]);
        const float sign = t.initialGapEV >= 0.0f ? 1.0f : -1.0f;
        const float g0 = std::abs(t.initialGapEV);
        t.expectedTauS = sign > 0 ? settings.tauDarken : settings.tauBrighten;
        float time = 0.0f;
        std::size_t index = 0;
        if (g0 > 0.0f && firstTimeGapBelow(samples, start, end, kRemainingAfterTau * g0, sign, time, index)) {
            t.fitted = true;
            t.fittedTauS = time - t.startTimeS;
        }
        if (g0 <= settleEV) {
            t.settled = true;
            t.settledIndex = start;
        } else if (firstTimeGapBelow(samples, start, end, settleEV, sign, time, index)) {
            t.settled = true;
            t.settleTimeS = time - t.startTimeS;
            t.settledIndex = index;
        }
        out.push_back(t);
    }
    return out;
}

std::string describeTransition(const Transition& t) {
    const bool outside = t.kind == TransitionKind::StepOutside;
    std::string text = fmt::format("t={:.2f} s {}: applied {:+.2f} EV {} target", t.crossingTimeS,
                                   outside ? "step outside" : "step inside", t.initialGapEV,
                                   t.initialGapEV >= 0 ? "over" : "under");
    text += t.settled ? fmt::format(", settled to 0.1 EV in {:.2f} s", t.settleTimeS) : ", did not settle";
    if (t.fitted) {
        text += fmt::format(", tau {:.3f} s ({} {:.3f} s, {:+.1f}%)", t.fittedTauS,
                            t.initialGapEV >= 0 ? "tauDarken" : "tauBrighten", t.expectedTauS,
                            100.0 * double(t.tauError()));
    }
    return text;
}

} // namespace photopic
