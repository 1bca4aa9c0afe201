#include "scenes/InteractiveCamera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photopic {

float OrbitView::distance() const {
    return glm::length(eye - target);
}

void OrbitView::orbit(float yaw, float pitch) {
    const glm::vec3 offset = eye - target;
    const float r = glm::length(offset);
    if (!(r > 0.0f) || !std::isfinite(yaw) || !std::isfinite(pitch)) {
        return;
    }
    // Spherical coordinates about +y: azimuth in the xz plane, elevation from it.
    const float elevation = std::asin(std::clamp(offset.y / r, -1.0f, 1.0f));
    const float azimuth = std::atan2(offset.x, offset.z);
    const float limit = std::numbers::pi_v<float> / 2.0f - kPoleMargin;
    // The camera looks along -offset, so its right is +azimuth: a positive yaw moves the eye to its right.
    const float a = azimuth + yaw;
    const float e = std::clamp(elevation + pitch, -limit, limit);
    eye = target + r * glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
}

void OrbitView::zoom(float factor) {
    const float r = distance();
    if (!(factor > 0.0f) || !std::isfinite(factor) || !(r > 0.0f)) {
        return;
    }
    const float d = std::clamp(r * factor, minDistance, maxDistance);
    eye = target + (eye - target) * (d / r);
}

void InteractiveCamera::orbit(float yaw, float pitch) {
    OrbitView view = currentView();
    view.orbit(yaw, pitch);
    holdView(view);
}

void InteractiveCamera::zoom(float factor) {
    OrbitView view = currentView();
    view.zoom(factor);
    holdView(view);
}

} // namespace photopic
