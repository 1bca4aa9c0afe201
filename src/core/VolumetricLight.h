#pragma once
// Volumetric light's CPU side (Mitchell, "Volumetric Light Scattering as a Post-Process", GPU Gems 3
// ch. 13): where the sun lands on screen, how the effect fades as the sun leaves the screen, and a reference
// of the radial scattering the GPU pass computes, for tests. No GL.

#include "core/Camera.h"
#include "core/Image.h"
#include "passes/volumetriclight/VolumetricLightSettings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace photopic {

/// The rays fade out as the sun nears the image's border: full strength while the sun's centre is at least
/// kVolumetricSunFadeInside (UV, on either axis) inside it, none once it is kVolumetricSunFadeOutside
/// outside, smooth in between. The fade starts inside because the effect comes from the sun's disc on screen:
/// without it the rays would drop within the few pixels the disc takes to cross the border. By the outer
/// limit the disc (0.024 UV in radius on the testbed's 45-degree field of view) has left the image.
inline constexpr float kVolumetricSunFadeInside = 0.1f;
inline constexpr float kVolumetricSunFadeOutside = 0.05f;

struct SunOnScreen {
    glm::vec2 uv{0.5f}; ///< the sun's direction projected to UV ((0, 0) bottom-left), meaningful when inFront
    bool inFront = false; ///< the sun is in front of the camera (behind it: no rays)
    float fade = 0.0f;    ///< [0, 1]: 1 well inside the image, 0 behind the camera or off the image
};

/// The sun's screen position and fade for a camera and a world-space direction towards the sun (a point at
/// infinity: only the camera's rotation moves it). A non-finite or zero direction gives fade 0.
[[nodiscard]] SunOnScreen sunOnScreen(const Camera& camera, glm::vec3 sunDirection) noexcept;

/// The fade for a sun at `uv`: 1 at kVolumetricSunFadeInside or more inside [0, 1]^2, falling smoothly to 0
/// at kVolumetricSunFadeOutside outside (by the largest distance outside on either axis, negative inside).
[[nodiscard]] float sunScreenFade(glm::vec2 uv) noexcept;

/// The light the pass adds, computed directly: per pixel the mean over `samples` evenly spaced points on the
/// segment from the pixel towards the sun (density of the way) of decay^(64 t) times the source, times
/// intensity x weight x exposure x the sun's fade. The source is the colour where the depth is the sky
/// (+inf), 0 elsewhere (occluders). `color` and `depth` are rows top to bottom (ImageF's convention); depth
/// in R. RGB of the result holds the light, A = 1.
[[nodiscard]] ImageF volumetricLightReference(const ImageF& color, const ImageF& depth,
                                              const SunOnScreen& sun, const VolumetricLightSettings& settings,
                                              int samples);

} // namespace photopic
