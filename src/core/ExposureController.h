#pragma once
// Auto exposure on the CPU: metered luminance -> target EV -> adaptation over time, all in log2 space.
// The GPU adaptation shader mirrors these functions line for line (float32; exp, exp2, log2, min, max only),
// and a test holds the two within 1e-3 EV over scripted sequences.
// Three adaptation models: an exponential eye lag per direction, a speed form, and Unreal's hybrid.
//
// Target (key 0.18 = mid grey; Lmin = 1e-4 keeps black finite), with clamp(a, lo, hi) = min(max(a, lo), hi):
//   x      = log2(L > Lmin ? L : Lmin)
//   target = clamp(log2(keyValue) - x + compensationEV + curve(x), minEV, maxEV)
//   curve(x): through [x, EV] points, y0 + (y1 - y0) * ((x - x0) / (x1 - x0)) on the segment holding x
//             (x0 <= x < x1), the first y at or below the first x, the last y past the last x, 0 if empty.
//
// One adaptation step (adaptExposure), gap = target - applied:
//   h = dt > 0 ? min(dt, maxDt) : 0                                        (NaN dt -> 0)
//   hysteresis: not adapting and |gap| > deadbandEV -> adapting;
//               adapting and |gap| < 0.1 deadbandEV -> not adapting (then applied stays put).
//   The rate follows the direction: gap > 0 (exposure rises; the scene got darker) uses tauBrighten or
//   speedDown, otherwise tauDarken or speedUp.
//   exponential:            alpha = clamp(1 - exp(-h / max(tau, 1e-6)), 0, 1); applied += gap * alpha
//   speed:                  alpha = clamp(1 - exp(-speed * h), 0, 1);          applied += gap * alpha
//   hybrid (Unreal's eye adaptation): s = max(speed, 1e-6) EV/s,
//     D = max(transitionEV, 1e-6), k = s / D (the exponential's slope k D equals s at |gap| = D), g = |gap|;
//     the new distance r is the exact solution over h, also when h crosses from linear into exponential:
//       g > D:  tl = (g - D) / s;  r = h <= tl ? g - s h : D exp(-k (h - tl))
//       g <= D: r = g exp(-k h)
//     applied = gap > 0 ? target - r : target + r
//   exposure = exp2(applied)   (the controller folds in the manual EV)
// The first step (initialized == 0) snaps: applied = target, adapting = 0, initialized = 1.

#include "core/settings/AutoExposureSettings.h"

#include <cstddef>
#include <type_traits>

namespace photopic {

/// Lmin of the target formula: luminance is floored here before log2, so black meters as very dark but
/// finite.
inline constexpr float kExposureMinLuminance = 1e-4f;
/// Hysteresis: once adapting, keep going until |gap| < kDeadbandExitFraction * deadbandEV.
inline constexpr float kDeadbandExitFraction = 0.1f;
/// Manual EV is clamped to +-kManualEVLimit (NaN -> 0) so 2^(manual + applied) stays a finite float.
inline constexpr float kManualEVLimit = 64.0f;

/// Exposure state, one per view. Plain float/int fields: the GPU storage buffer (std430) mirrors it as
/// `struct ExposureState { float appliedLog2; float targetLog2; float meteredLuminance; float exposure;
/// int adapting; int initialized; };` (24 bytes, no padding).
struct ExposureState {
    float appliedLog2 = 0.0f;      ///< EV, the adapted auto exposure (without the manual EV)
    float targetLog2 = 0.0f;       ///< EV, target of the last valid reading, in [minEV, maxEV]
    float meteredLuminance = 0.0f; ///< scene-linear, the last valid metered luminance (0 before the first)
    float exposure = 1.0f;         ///< total multiplier: 2^(manualEV + appliedLog2), 2^manualEV when off
    int adapting = 0;              ///< 1 while the deadband hysteresis lets exposure move
    int initialized = 0;           ///< 0 before the first valid reading and after reset(): next one snaps
};
static_assert(std::is_standard_layout_v<ExposureState> && std::is_trivially_copyable_v<ExposureState>);
static_assert(sizeof(ExposureState) == 24);
static_assert(offsetof(ExposureState, appliedLog2) == 0 && offsetof(ExposureState, targetLog2) == 4 &&
              offsetof(ExposureState, meteredLuminance) == 8 && offsetof(ExposureState, exposure) == 12 &&
              offsetof(ExposureState, adapting) == 16 && offsetof(ExposureState, initialized) == 20);

/// curve(x) of the target formula: piecewise linear through the points, held at the end values; 0 when empty.
[[nodiscard]] float compensationCurveEV(const CurvePoints& curve, float log2Luminance) noexcept;

/// Target exposure in EV for a metered luminance (formula above). Meant for meterable luminance; NaN counts
/// as Lmin and +inf saturates to minEV, so the result is always finite and inside [minEV, maxEV].
[[nodiscard]] float exposureTargetLog2(const AutoExposureSettings& settings, float meteredLuminance) noexcept;

/// One adaptation step (formula above). Pure. A non-finite targetLog2 returns `prev` unchanged. Sets
/// targetLog2, appliedLog2, adapting, initialized and exposure = exp2(appliedLog2); copies meteredLuminance.
[[nodiscard]] ExposureState adaptExposure(const AutoExposureSettings& settings, const ExposureState& prev,
                                          float targetLog2, float dt) noexcept;

/// The total multiplier: 2^(manualEV + appliedLog2) when enabled and initialized, else 2^manualEV.
[[nodiscard]] float exposureMultiplier(const AutoExposureSettings& settings, const ExposureState& state,
                                       float manualEV) noexcept;

/// Auto exposure of one view: a metered luminance and a frame time per frame (time comes from the caller).
class ExposureController {
public:
    explicit ExposureController(AutoExposureSettings settings = {});

    /// Takes effect from the next update; the adapted state carries over.
    void setSettings(const AutoExposureSettings& settings);
    [[nodiscard]] const AutoExposureSettings& settings() const { return mSettings; }

    /// One frame. manualEV is tonemapping.exposure, which multiplies with auto exposure.
    ///  - Luminance not meterable (NaN, inf, <= 0): the state stays as it was (`exposure` follows manualEV).
    ///  - Disabled: records meteredLuminance and targetLog2, stops adapting, clears `initialized` (enabling
    ///    later snaps to the target instead of sweeping from a stale value), exposure = 2^manualEV.
    ///  - Enabled: adaptExposure, then meteredLuminance = L and exposure = 2^(manualEV + appliedLog2).
    const ExposureState& update(float meteredLuminance, float dt, float manualEV = 0.0f) noexcept;

    /// Camera cut, teleport, resize: the next valid reading snaps to its target.
    void reset() noexcept;

    [[nodiscard]] const ExposureState& state() const { return mState; }

private:
    AutoExposureSettings mSettings;
    ExposureState mState;
};

} // namespace photopic
