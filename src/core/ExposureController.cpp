#include "core/ExposureController.h"

#include "core/Metering.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace photopic {

namespace {

/// Smallest time constant, speed and transition the step divides by (settings ranges keep far above it).
constexpr float kMinDivisor = 1e-6f;

/// Finite float test written with comparisons only, as the shader does (isnan may be optimised away there).
bool isFiniteValue(float x) noexcept {
    return x >= -kMaxMeterableLuminance && x <= kMaxMeterableLuminance;
}

/// GLSL clamp(x, lo, hi) = min(max(x, lo), hi).
float clampGlsl(float x, float lo, float hi) noexcept {
    return std::min(std::max(x, lo), hi);
}

/// Distance to the target after h seconds of hybrid adaptation from distance g (>= 0): linear at s EV/s while
/// farther than D, exponential with rate k = s / D inside, integrated exactly across the switch.
float hybridRemaining(float g, float speed, float transitionEV, float h) noexcept {
    const float s = std::max(speed, kMinDivisor);
    const float d = std::max(transitionEV, kMinDivisor);
    const float k = s / d;
    if (g > d) {
        const float tLinear = (g - d) / s;
        if (h <= tLinear) {
            return g - s * h;
        }
        return d * std::exp(-k * (h - tLinear));
    }
    return g * std::exp(-k * h);
}

} // namespace

float compensationCurveEV(const CurvePoints& curve, float log2Luminance) noexcept {
    if (curve.empty()) {
        return 0.0f;
    }
    if (log2Luminance <= curve.front().x) {
        return curve.front().y;
    }
    for (std::size_t i = 1; i < curve.size(); ++i) {
        if (log2Luminance < curve[i].x) {
            const glm::vec2 a = curve[i - 1];
            const glm::vec2 b = curve[i];
            const float t = (log2Luminance - a.x) / (b.x - a.x);
            return a.y + (b.y - a.y) * t;
        }
    }
    return curve.back().y;
}

float exposureTargetLog2(const AutoExposureSettings& settings, float meteredLuminance) noexcept {
    const float l = meteredLuminance > kExposureMinLuminance ? meteredLuminance : kExposureMinLuminance;
    const float x = std::log2(l);
    const float target = std::log2(settings.keyValue) - x + settings.compensationEV +
                         compensationCurveEV(settings.compensationCurve, x);
    return clampGlsl(target, settings.minEV, settings.maxEV);
}

ExposureState adaptExposure(const AutoExposureSettings& settings, const ExposureState& prev, float targetLog2,
                            float dt) noexcept {
    if (!isFiniteValue(targetLog2)) {
        return prev;
    }
    ExposureState s = prev;
    s.targetLog2 = targetLog2;
    if (prev.initialized == 0 || !isFiniteValue(prev.appliedLog2)) {
        s.appliedLog2 = targetLog2;
        s.adapting = 0;
        s.initialized = 1;
        s.exposure = std::exp2(s.appliedLog2);
        return s;
    }

    const float h = dt > 0.0f ? std::min(dt, settings.maxDt) : 0.0f;
    const float gap = targetLog2 - prev.appliedLog2;
    const float absGap = std::abs(gap);
    if (s.adapting == 0 && absGap > settings.deadbandEV) {
        s.adapting = 1;
    } else if (s.adapting != 0 && absGap < kDeadbandExitFraction * settings.deadbandEV) {
        s.adapting = 0;
    }

    if (s.adapting != 0) {
        const bool rising = gap > 0.0f; // exposure goes up: the scene got darker
        switch (settings.adaptation) {
        case AdaptationMode::Exponential: {
            const float tau = std::max(rising ? settings.tauBrighten : settings.tauDarken, kMinDivisor);
            const float alpha = clampGlsl(1.0f - std::exp(-h / tau), 0.0f, 1.0f);
            s.appliedLog2 = prev.appliedLog2 + gap * alpha;
            break;
        }
        case AdaptationMode::Speed: {
            const float speed = rising ? settings.speedDown : settings.speedUp;
            const float alpha = clampGlsl(1.0f - std::exp(-speed * h), 0.0f, 1.0f);
            s.appliedLog2 = prev.appliedLog2 + gap * alpha;
            break;
        }
        case AdaptationMode::Hybrid: {
            const float speed = rising ? settings.speedDown : settings.speedUp;
            const float r = hybridRemaining(absGap, speed, settings.transitionEV, h);
            s.appliedLog2 = rising ? targetLog2 - r : targetLog2 + r;
            break;
        }
        }
    }
    s.exposure = std::exp2(s.appliedLog2);
    return s;
}

float exposureMultiplier(const AutoExposureSettings& settings, const ExposureState& state,
                         float manualEV) noexcept {
    const float manual =
        isFiniteValue(manualEV) ? clampGlsl(manualEV, -kManualEVLimit, kManualEVLimit) : 0.0f;
    if (settings.enabled && state.initialized != 0) {
        return std::exp2(manual + state.appliedLog2);
    }
    return std::exp2(manual);
}

ExposureController::ExposureController(AutoExposureSettings settings)
    : mSettings(std::move(settings)) {}

void ExposureController::setSettings(const AutoExposureSettings& settings) {
    mSettings = settings;
}

const ExposureState& ExposureController::update(float meteredLuminance, float dt, float manualEV) noexcept {
    if (!isMeterableLuminance(meteredLuminance)) {
        mState.exposure = exposureMultiplier(mSettings, mState, manualEV);
        return mState;
    }
    const float target = exposureTargetLog2(mSettings, meteredLuminance);
    if (!mSettings.enabled) {
        mState.meteredLuminance = meteredLuminance;
        mState.targetLog2 = target;
        mState.adapting = 0;
        mState.initialized = 0;
    } else {
        mState = adaptExposure(mSettings, mState, target, dt);
        mState.meteredLuminance = meteredLuminance;
    }
    mState.exposure = exposureMultiplier(mSettings, mState, manualEV);
    return mState;
}

void ExposureController::reset() noexcept {
    mState.adapting = 0;
    mState.initialized = 0;
}

} // namespace photopic
