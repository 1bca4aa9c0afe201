#pragma once
// Circle-of-confusion math for depth of field, on the CPU (the source of truth the CoC pass's constants come
// from) and physical exposure from the camera's lens. No GL.
//
// Thin lens (focal length f, f-number N, focused at F): a point at distance z images to a disc on the
// sensor of diameter c = (f / N) f |z - F| / (z (F - f)). In pixels of an image H pixels high on a sensor h
// high, the signed radius (negative in front of the focus, positive behind) is
//   r(z) = K (z - F) / z = K - K F / z,   K = f^2 H / (2 N (F - f) h),
// an affine function of 1 / z, so the shader evaluates scale / z + bias.

#include "core/Camera.h"
#include "passes/dof/DofSettings.h"

namespace photopic {

/// r(z) = scale / z + bias pixels (signed: < 0 near, > 0 far), before the clamp to +-maxCocRadius.
struct CocModel {
    float scale = 0.0f;
    float bias = 0.0f;
    /// Artistic mode: r(z) = bokehRadius clamp((z - focalDistance) / focalRange, -1, 1) instead.
    bool artistic = false;
    float focalDistance = 10.0f;
    float focalRange = 5.0f;
    float bokehRadius = 4.0f;
    float maxRadius = 16.0f; ///< pixels

    /// Signed CoC radius in pixels of a point at linear view depth z (+inf: the far limit), clamped.
    [[nodiscard]] float radius(float z) const noexcept;
};

/// The CoC model for an image `imageHeight` pixels high. Physical mode: from the camera's lens (a focus
/// closer than the focal length, where the thin lens has no real image, is held just beyond it).
[[nodiscard]] CocModel cocModel(const DofSettings& settings, const Lens& lens,
                                int imageHeight) noexcept;

/// The shutter's open time in seconds: the lens's exposure time when set, else the shutter angle's
/// fraction of the frame time `dt`.
[[nodiscard]] float shutterTime(const Lens& lens, float dt) noexcept;
/// The fraction of the frame time the shutter is open, in [0, 1].
[[nodiscard]] float shutterFraction(const Lens& lens, float dt) noexcept;

} // namespace photopic
