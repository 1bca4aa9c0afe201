#pragma once
// The orbit scene's world, GL-free: where the ship, the planets, the sun and the camera are at a given script
// time, and the analytic queries the renderer's shaders mirror (orbit_world.h.glsl): the planet's occlusion
// of the sun seen from the ship, the camera's path.
//
// World space: metres, right-handed, +y up. The ship sits at the origin (its model spins slowly about its
// long axis, z); the Earth-like planet is below and ahead of it, the Mars-like one far away. The scene is
// lit by one sun at infinity. Instead of moving the ship along its orbit, the script turns the sun's
// direction: seen from the ship the two are the same, and the ship stays at the origin where floats are
// finest. The sun starts well clear of the Earth, passes behind it (the ship is in the planet's shadow, an
// eclipse of a few seconds), and comes out on the other side, so auto exposure adapts both ways.

#include "core/Camera.h"

#include <glm/glm.hpp>

namespace photopic::orbit {

struct Planet {
    glm::vec3 centre{0.0f}; ///< m
    float radius = 1.0f;    ///< m
};

inline constexpr Planet kEarth{{0.0f, -2600.0f, -4200.0f}, 1600.0f};
inline constexpr Planet kMars{{7000.0f, 1800.0f, -9000.0f}, 320.0f};
/// radians: the sun's disc, larger than the real sun's 0.0047 so that it covers a few pixels.
inline constexpr float kSunAngularRadius = 0.02f;
inline constexpr float kNear = 0.1f;               ///< m
inline constexpr float kFar = 60000.0f;            ///< m, past the farthest planet's far side
inline constexpr float kVerticalFov = 0.87266463f; ///< 50 degrees
inline constexpr double kScriptSeconds = 12.0;     ///< the scripted pass: approach, eclipse, sunrise
inline constexpr float kShipSpin = 0.05f;          ///< rad/s about the ship's long axis

/// Object ids in the object-id output (0: the background).
namespace ids {
inline constexpr unsigned kEarth = 100;
inline constexpr unsigned kMars = 101;
/// The ship's parts (or a model's mesh instances) take kFirstShip + their index.
inline constexpr unsigned kFirstShip = 1;
} // namespace ids

/// Direction towards the sun at script time `seconds` (unit, world space).
[[nodiscard]] glm::vec3 sunDirectionAt(double seconds);

/// Visibility in [0, 1] of the sun's disc (angular radius kSunAngularRadius) from `point` past `planet`:
/// 1 unoccluded, 0 in the umbra, a smooth penumbra whose width grows with the distance to the planet.
[[nodiscard]] float sunVisibility(const Planet& planet, glm::vec3 point, glm::vec3 sunDirection);

/// The ship's model matrix at script time `seconds`: a fixed orientation, then its spin about its long axis.
[[nodiscard]] glm::mat4 shipTransform(double seconds);

/// The orbiting camera's eye at script time `seconds` around a ship of bounding radius `shipRadius`.
[[nodiscard]] glm::vec3 cameraEyeAt(double seconds, float shipRadius);

/// A camera at `eye` (previous frame at `prevEye`) looking at the ship (the origin), y up, on a `width` x
/// `height` target: unjittered projection, kNear/kFar.
[[nodiscard]] Camera orbitCameraFrom(glm::vec3 eye, glm::vec3 prevEye, int width, int height);

/// The camera of script time `seconds` (previous frame at `prevSeconds`; equal times: a still camera) on a
/// `width` x `height` target: unjittered projection, kNear/kFar.
[[nodiscard]] Camera orbitCamera(double seconds, double prevSeconds, float shipRadius, int width, int height);

} // namespace photopic::orbit
