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
    return glm::rotate(glm::mat4(1.0f), float(kShipSpin * seconds), glm::vec3(0.0f, 0.0f, 1.0f));
}

glm::vec3 cameraEyeAt(double seconds, float shipRadius) {
    // Three quarters of a turn around the ship over the script, rising and falling a little, closing in as
    // it goes: it starts with the sun behind the camera (the ship lit from the front) and ends looking
    // past the ship towards the sun as it comes out of the planet's shadow.
    const double yaw = 4.17 - 0.425 * seconds;
    const double pitch = 0.22 + 0.12 * std::sin(seconds * 0.5);
    const float distance = shipRadius * float(1.75 - 0.03 * std::min(seconds, kScriptSeconds));
    return distance * glm::vec3(float(std::cos(pitch) * std::sin(yaw)), float(std::sin(pitch)),
                                float(std::cos(pitch) * std::cos(yaw)));
}

Camera orbitCamera(double seconds, double prevSeconds, float shipRadius, int width, int height) {
    const auto viewAt = [&](double t) {
        return glm::lookAt(cameraEyeAt(t, shipRadius), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    };
    Camera c;
    c.nearPlane = kNear;
    c.farPlane = kFar;
    c.verticalFov = kVerticalFov;
    c.view = viewAt(seconds);
    c.projection = perspectiveProjection(kVerticalFov, float(width) / float(height), kNear, kFar);
    c.prevViewProjection = c.projection * viewAt(prevSeconds);
    c.lens.focusDistance = glm::length(cameraEyeAt(seconds, shipRadius));
    return c;
}

} // namespace photopic::orbit
