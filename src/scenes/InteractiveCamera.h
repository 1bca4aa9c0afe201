#pragma once
// A 3D scene's camera that an interactive host (photopic-view) steers: drag to orbit about a target, wheel
// to zoom. A scene hands one out through Scene::interactiveCamera() and supplies two things: the view the
// camera has now and how to hold a view (e.g. as its still-camera settings); OrbitView holds the maths.

#include <glm/vec3.hpp>

namespace photopic {

/// An eye looking at a target, y up; the orbit and zoom steps on it.
struct OrbitView {
    glm::vec3 eye{0.0f, 0.0f, 1.0f};
    glm::vec3 target{0.0f};

    /// Elevation stays within this many radians of straight up or down (the view's up vector stays defined).
    static constexpr float kPoleMargin = 0.02f;
    /// Closest and farthest zoom, in the scene's units.
    float minDistance = 0.05f;
    float maxDistance = 1000.0f;

    [[nodiscard]] float distance() const;
    /// Turns the eye about the target (see InteractiveCamera::orbit); the distance is kept.
    void orbit(float yaw, float pitch);
    /// Scales the distance by `factor`, clamped to [minDistance, maxDistance]; the direction is kept.
    void zoom(float factor);
};

class InteractiveCamera {
public:
    virtual ~InteractiveCamera() = default;
    /// Moves the eye about the target at the same distance: `yaw` radians about the world's up axis (+y),
    /// positive towards the camera's right; `pitch` radians of elevation, positive up (it stays short of
    /// straight up or down). The camera keeps looking at the target.
    void orbit(float yaw, float pitch);
    /// Scales the eye's distance to the target by `factor` (< 1 closer, > 1 farther; <= 0 is ignored).
    void zoom(float factor);

protected:
    /// The view the next move starts from.
    [[nodiscard]] virtual OrbitView currentView() const = 0;
    /// Keeps `view` as the camera from now on.
    virtual void holdView(const OrbitView& view) = 0;
};

} // namespace photopic
