#include "scenes/orbit/OrbitWorld.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace photopic::orbit {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
/// The sun's angle from the Earth's centre (seen from the ship) at time 0, and its rate: it crosses the
/// planet's disc (angular radius ~19 degrees) between ~4 s and ~8.2 s.
constexpr double kSunStartAngle = 55.0 * kDegree;
constexpr double kSunRate = -9.0 * kDegree; ///< per second

} // namespace

glm::vec3 sunDirectionAt(double seconds) {
    const glm::vec3 toEarth = glm::normalize(kEarth.centre);
    // The sun moves in the plane through the Earth's direction and the x axis, so it rises beside the
    // planet's limb as the camera sees it, not behind the ship.
    const glm::vec3 side = glm::normalize(glm::cross(toEarth, glm::vec3(0.0f, 0.0f, 1.0f)));
    const double a = kSunStartAngle + kSunRate * std::max(seconds, 0.0);
    return glm::normalize(float(std::cos(a)) * toEarth + float(std::sin(a)) * side);
}

float sunVisibility(const Planet& planet, glm::vec3 point, glm::vec3 sunDirection) {
    const glm::vec3 toCentre = planet.centre - point;
    const float along = glm::dot(toCentre, sunDirection);
    if (along <= 0.0f) {
        return 1.0f; // the planet is behind the point as seen towards the sun
    }
    const float miss = glm::length(toCentre - along * sunDirection);
    // The disc's edge sweeps the penumbra over a width of 2 * along * angular radius.
    const float w = along * kSunAngularRadius;
    const float t = std::clamp((miss - (planet.radius - w)) / (2.0f * w), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

glm::mat4 shipTransform(double seconds) {
    // The ship's long axis (model z) stands along the normal of the plane the sun moves in, so the sun
    // always lights the hull's side, never only an end; the solar arrays (model x) stay along world x.
    const glm::vec3 toEarth = glm::normalize(kEarth.centre);
    const glm::vec3 x(1.0f, 0.0f, 0.0f);
    const glm::vec3 z = glm::normalize(glm::cross(toEarth, -x));
    const glm::mat4 orientation(glm::vec4(x, 0.0f), glm::vec4(glm::cross(z, x), 0.0f), glm::vec4(z, 0.0f),
                                glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    return orientation *
           glm::rotate(glm::mat4(1.0f), float(kShipSpin * seconds), glm::vec3(0.0f, 0.0f, 1.0f));
}

glm::vec3 cameraEyeAt(double seconds, float shipRadius) {
    // The camera follows the sun round the ship, 1 rad off it in yaw, so the ship is seen lit from the front
    // three-quarters as it goes into the planet's shadow and out again; from 8.6 s it swings round to look
    // past the ship towards the sun, 0.35 rad off it (the sun's disc in the frame, the ship rim-lit).
    // Yaw is measured from +z towards +x; the sun's yaw is unwrapped about the planet's direction (-z), which
    // it crosses during the eclipse.
    const double t = std::clamp(seconds, 0.0, kScriptSeconds);
    const glm::vec3 sun = sunDirectionAt(t);
    const double sunYaw = std::atan2(-double(sun.x), -double(sun.z)) + 3.14159265358979323846;
    const double s = std::clamp((t - 8.6) / 2.6, 0.0, 1.0);
    const double swing = s * s * (3.0 - 2.0 * s);
    const double yaw = sunYaw + 1.0 + swing * (3.14159265358979323846 - 1.35);
    // Elevation follows the sun's too (it stays 17 to 32 degrees below the horizon): a little above it while
    // the camera is on the sun's side, mirrored above the ship when it looks towards the sun.
    const double sunPitch = std::asin(std::clamp(double(sun.y), -1.0, 1.0));
    const double pitch =
        (1.0 - swing) * (sunPitch + 0.2) + swing * (-sunPitch - 0.1) + 0.05 * std::sin(t * 0.5);
    const float distance = shipRadius * float(1.75 - 0.03 * t);
    return distance * glm::vec3(float(std::cos(pitch) * std::sin(yaw)), float(std::sin(pitch)),
                                float(std::cos(pitch) * std::cos(yaw)));
}

Camera orbitCameraFrom(glm::vec3 eye, glm::vec3 prevEye, int width, int height) {
    const auto viewFrom = [](glm::vec3 e) {
        return glm::lookAt(e, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    };
    Camera c;
    c.nearPlane = kNear;
    c.farPlane = kFar;
    c.verticalFov = kVerticalFov;
    c.view = viewFrom(eye);
    c.projection = perspectiveProjection(kVerticalFov, float(width) / float(height), kNear, kFar);
    c.prevViewProjection = c.projection * viewFrom(prevEye);
    c.lens.focusDistance = glm::length(eye);
    return c;
}

Camera orbitCamera(double seconds, double prevSeconds, float shipRadius, int width, int height) {
    return orbitCameraFrom(cameraEyeAt(seconds, shipRadius), cameraEyeAt(prevSeconds, shipRadius), width,
                           height);
}

} // namespace photopic::orbit
