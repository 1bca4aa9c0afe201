#pragma once
// Auto exposure (eye adaptation): metering -> target -> adaptation, all in log2 (EV) space.
// The math is in core/ExposureController.h and core/Metering.h.
//
// Older settings files' keys stay readable: "enabled" and "keyValue" are fields; "speed" (sets speedUp and
// speedDown), "min" and "max" (exposure multipliers: minEV = log2(min), maxEV = log2(max)) are aliases, read
// but never written. Defaults: key 0.18, multipliers 0.25..4 = -2..+2 EV, tauBrighten 1 s, tauDarken 0.3 s
// (an eye that lags visibly), the big engines' speeds (3 / 1 EV/s) and percentiles (10 / 90), `enabled` off.

#include "core/settings/Reflect.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace photopic {

/// Most points a compensation curve may have: the shader holds them in a fixed-size uniform array.
inline constexpr std::size_t kMaxCompensationCurvePoints = 16;

/// How the luminance that drives exposure is measured (core/Metering.h implements each on the CPU).
enum class MeteringMode {
    Average,   ///< geometric mean of every pixel's luminance
    Histogram, ///< log2 histogram, mean of the [lowPercent, highPercent] window
    Spot,      ///< geometric mean of 1/5/9/13 taps on a disc (kSpotTaps in core/Metering.h)
    Center,    ///< geometric mean weighted by a Gaussian around the image centre (centerWeight)
    Mask,      ///< geometric mean weighted by a grey mask image
    Subject,   ///< the probed luma under the subject of the view (core/Subjects.h). No subject: no
               ///< reading, exposure holds (or the screen centre with subjects.fallback = center)
};

/// How exposure follows its target (core/ExposureController.h implements each).
enum class AdaptationMode {
    Exponential, ///< eye lag: alpha = 1 - exp(-dt / tau), tau per direction
    Speed,       ///< alpha = 1 - exp(-speed * dt), speed per direction
    Hybrid,      ///< Unreal: linear speed EV/s far from the target, exponential within transitionEV
};

/// JSON names, in enum order.
inline std::span<const std::string_view> meteringModeNames() {
    static constexpr std::array<std::string_view, 6> kNames{"average", "histogram", "spot",
                                                            "center",  "mask",      "subject"};
    return kNames;
}
inline std::span<const std::string_view> adaptationModeNames() {
    static constexpr std::array<std::string_view, 3> kNames{"exponential", "speed", "hybrid"};
    return kNames;
}

struct AutoExposureSettings {
    /// Spot metering: a disc in image UV (u right, v down, (0, 0) = top-left of the image).
    struct SpotMetering {
        float u = 0.5f;
        float v = 0.5f;
        float radius = 0.1f;
        int taps = 9;

        template <class V>
        void visit(V& vis) { // not `v`: that is a field here
            vis.field("u", u, Range{0, 1}, "UV: disc centre, horizontal");
            vis.field("v", v, Range{0, 1}, "UV: disc centre, vertical (v = 0: top row)");
            vis.field("radius", radius, Range{0, 1}, "image heights: disc radius");
            vis.field("taps", taps, Range{1, 13}, "1, 5, 9 or 13: the first `taps` entries of kSpotTaps");
            vis.require(taps == 1 || taps == 5 || taps == 9 || taps == 13, "taps", "must be 1, 5, 9 or 13");
        }
    };

    /// Mask metering: per-pixel weights from a grey image (its Rec.709 luma; negative, non-finite -> 0).
    struct MaskMetering {
        std::string path;

        template <class V>
        void visit(V& v) {
            v.field("path", path, "file (empty: none): grey image stretched over the frame, sampled nearest");
        }
    };

    bool enabled = false;
    MeteringMode metering = MeteringMode::Average;
    AdaptationMode adaptation = AdaptationMode::Exponential;

    float keyValue = 0.18f;
    float compensationEV = 0.0f;
    float minEV = -2.0f;
    float maxEV = 2.0f;
    CurvePoints compensationCurve;

    // Rates by direction. Exposure rises when the scene darkens, falls when it brightens; the eye adapts to
    // light faster than to dark (tauBrighten 1 s / tauDarken 0.3 s; Unreal "Speed Up"/"Speed Down" and Bevy's
    // speed_brighten/speed_darken, 3 / 1 EV/s, are named after the scene, as speedUp/speedDown are here).
    float tauBrighten = 1.0f;
    float tauDarken = 0.3f;
    float speedUp = 3.0f;
    float speedDown = 1.0f;
    float transitionEV = 1.5f;
    float deadbandEV = 0.02f;
    float maxDt = 0.1f;

    float histogramLog2Min = -12.0f;
    float histogramLog2Max = 16.0f;
    float lowPercent = 10.0f;
    float highPercent = 90.0f;

    SpotMetering spot; ///< disc for metering = spot
    MaskMetering mask; ///< weight image for metering = mask

    /// True when x increases strictly from point to point and the count fits. y may take any shape: metering
    /// reads the image before exposure, so the target stays a function of the scene and cannot oscillate.
    [[nodiscard]] bool compensationCurveValid() const {
        if (compensationCurve.size() > kMaxCompensationCurvePoints) {
            return false;
        }
        for (std::size_t i = 1; i < compensationCurve.size(); ++i) {
            if (!(compensationCurve[i].x > compensationCurve[i - 1].x)) {
                return false;
            }
        }
        return true;
    }

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns auto exposure on; off: exposure = 2^tonemapping.exposure");
        v.field("metering", metering, meteringModeNames(), "what is measured");
        v.field("adaptation", adaptation, adaptationModeNames(), "how exposure follows");
        // The older keys' aliases come before the fields they feed: a file holding both keeps the new key.
        v.alias(
            "speed", Range{0.001, 100},
            [&](float s) {
                speedUp = s;
                speedDown = s;
            },
            "older key: sets speedUp and speedDown");
        // 2^-20 .. 2^20: the multipliers whose log2 lies in minEV/maxEV's range.
        v.alias(
            "min", Range{9.5367431640625e-07, 1048576.0}, [&](float m) { minEV = std::log2(m); },
            "older key: the lowest exposure as a multiplier, minEV = log2(min)");
        v.alias(
            "max", Range{9.5367431640625e-07, 1048576.0}, [&](float m) { maxEV = std::log2(m); },
            "older key: the highest exposure as a multiplier, maxEV = log2(max)");
        v.field("keyValue", keyValue, Range{0.001, 10}, "scene-linear: what the metered L maps to");
        v.field("compensationEV", compensationEV, Range{-10, 10}, "EV: added to the target before clamping");
        v.field("minEV", minEV, Range{-20, 20}, "EV: lowest auto exposure (-2: x0.25), <= maxEV");
        v.field("maxEV", maxEV, Range{-20, 20}, "EV: highest auto exposure (2: x4)");
        v.field("compensationCurve", compensationCurve, Range{-32, 32},
                "[log2 L, EV] points, x and y in the range, x strictly increasing, at most 16 (empty: none): "
                "piecewise linear, flat past the ends; its EV at log2 L is added to the target");
        v.field("tauBrighten", tauBrighten, Range{0.001, 30}, "s: time constant while exposure rises");
        v.field("tauDarken", tauDarken, Range{0.001, 30}, "s: time constant while exposure falls");
        v.field("speedUp", speedUp, Range{0.001, 100},
                "1/s (speed), EV/s (hybrid): how fast exposure follows when the scene brightens");
        v.field("speedDown", speedDown, Range{0.001, 100},
                "1/s (speed), EV/s (hybrid): how fast exposure follows when the scene darkens");
        v.field("transitionEV", transitionEV, Range{0.01, 20}, "EV: hybrid turns exponential this close");
        v.field("deadbandEV", deadbandEV, Range{0, 4}, "EV: adapt beyond it, stop below a tenth of it");
        v.field("maxDt", maxDt, Range{0.001, 10}, "s: frame time is clamped to [0, maxDt]");
        v.field("histogramLog2Min", histogramLog2Min, Range{-32, 32}, "log2 L: low edge of bin 1, < log2Max");
        v.field("histogramLog2Max", histogramLog2Max, Range{-32, 32}, "log2 L: high edge of bin 254");
        v.field("lowPercent", lowPercent, Range{0, 100}, "%: darkest share left out of the mean");
        v.field("highPercent", highPercent, Range{0, 100}, "%: window top, > lowPercent");
        v.object("spot", spot);
        v.object("mask", mask);
        v.require(minEV <= maxEV, "minEV", "must not exceed maxEV");
        v.require(histogramLog2Min < histogramLog2Max, "histogramLog2Min", "must be below histogramLog2Max");
        v.require(lowPercent < highPercent, "lowPercent", "must be below highPercent");
        v.require(compensationCurveValid(), "compensationCurve",
                  "x (log2 luminance) must increase strictly from point to point, at most 16 points");
    }
};

} // namespace photopic
