#pragma once
// The host's camera and lens as the 3D passes see it, and the sub-pixel jitter a temporal pass asks the host
// to add to its projection. No GL here: the conventions (docs/architecture.md, "Inputs") are GL's, so a host
// that renders with OpenGL hands its matrices over as they are.
//
// Conventions:
// - View space is right-handed, the camera looks down -z, +y is up (OpenGL). `view` maps world -> view.
// - `projection` maps view -> clip with GL's clip conventions (NDC z in [-1, 1], or [0, 1] when the host uses
//   glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); reversed Z is a depth-input flag, not a different matrix
//   API). It is the unjittered projection: the pipeline applies its own jitter where it needs it.
// - `prevViewProjection` is last frame's unjittered projection * view, for reprojection.
// - Distances are in scene units (metres unless the host says otherwise); the lens's focal length and sensor
//   size are in millimetres, like a camera's.

#include <glm/glm.hpp>

#include <cstdint>

namespace photopic {

/// A thin-lens camera model: enough for depth of field (f-number, focus, focal length), motion blur (shutter)
/// and physical exposure (aperture, shutter, ISO).
struct Lens {
    float focalLengthMm = 50.0f;    ///< mm, (0, 10000], the lens's focal length
    float sensorHeightMm = 24.0f;   ///< mm, (0, 1000], the sensor's height (full frame: 24 mm)
    float fNumber = 2.8f;           ///< N, [0.5, 256], aperture as an f-number
    float focusDistance = 10.0f;    ///< scene units, (0, inf), distance to the plane in focus
    float shutterAngleDeg = 180.0f; ///< degrees, [0, 360], shutter open time as a fraction of the frame
    float exposureTimeS = 0.0f;     ///< s, [0, 60]; 0: derived from the shutter angle and the frame time
    float iso = 100.0f;             ///< ISO sensitivity, [1, 1e6]

    friend bool operator==(const Lens&, const Lens&) = default;
};

struct Camera {
    glm::mat4 view{1.0f};               ///< world -> view (right-handed, -z forward)
    glm::mat4 projection{1.0f};         ///< view -> clip, unjittered
    glm::mat4 prevViewProjection{1.0f}; ///< last frame's unjittered projection * view
    float nearPlane = 0.1f;             ///< scene units, > 0
    float farPlane = 1000.0f;           ///< scene units, > near; may be +inf (infinite projection)
    float verticalFov = 1.0471976f;     ///< radians, (0, pi), the full vertical field of view
    Lens lens;
    /// A cut (new shot, teleport): histories are not reused and prevViewProjection is ignored this frame.
    bool cut = false;

    [[nodiscard]] glm::mat4 viewProjection() const { return projection * view; }
};

/// Whether every entry of `m` is finite.
[[nodiscard]] bool allFinite(const glm::mat4& m) noexcept;

/// Why a camera cannot be used, or nullptr when it can: a non-finite matrix entry, near <= 0, far <= near,
/// a field of view outside (0, pi), or a lens value outside its range.
[[nodiscard]] const char* invalidCameraReason(const Camera& camera) noexcept;

/// Perspective projection with GL clip conventions (z in [-1, 1]); far may be +inf.
[[nodiscard]] glm::mat4 perspectiveProjection(float verticalFov, float aspect, float nearPlane,
                                              float farPlane);

/// Element `index` (from 1) of the Halton low-discrepancy sequence in `base`, in [0, 1).
[[nodiscard]] float halton(std::uint32_t index, std::uint32_t base) noexcept;

/// Sub-pixel jitter for frame `frameIndex`: Halton(2, 3) at index (frameIndex mod cycle) + 1, centred, in
/// pixels in [-0.5, 0.5) (x right, y up, like NDC). `cycle` >= 1. Index 1 is used for frame 0, so the
/// sequence never starts at the pixel corner.
[[nodiscard]] glm::vec2 haltonJitter(std::uint64_t frameIndex, int cycle) noexcept;

/// The clip-space offset that moves the image by `jitterPixels` on a `width` x `height` target: add it to
/// projection[2][0..1] of a perspective matrix (or use jitteredProjection).
[[nodiscard]] glm::vec2 jitterClipOffset(glm::vec2 jitterPixels, int width, int height) noexcept;
/// `projection` with the image moved by `jitterPixels` (perspective and orthographic matrices alike).
[[nodiscard]] glm::mat4 jitteredProjection(const glm::mat4& projection, glm::vec2 jitterPixels, int width,
                                           int height) noexcept;

/// The view-space rays through the image, for passes that rebuild a pixel's view position from its depth: the
/// points at NDC z = -1 (`nearRay`) and z = 0 (`farRay`) on the ray through NDC (x, y), each as the point at
/// x = y = 0 ([0]) and its slopes in x ([1]) and y ([2]), w = 0. The projection's w row does not depend on x
/// or y, so both points are affine in them: point(x, y) = ray[0] + x ray[1] + y ray[2].
void viewRays(const glm::mat4& projection, glm::vec4 (&nearRay)[3], glm::vec4 (&farRay)[3]) noexcept;
/// Whether `projection` is a perspective one whose view rays all start at the eye and whose NDC z depends
/// on view z alone (glm::perspective and glm::frustum, jittered or not): then a view ray is (x, y, -1) times
/// the depth, which the screen-space passes' perspective programs use.
[[nodiscard]] bool isPerspective(const glm::mat4& projection) noexcept;

/// Linear view depth (positive distance along -z, scene units) of a GL window depth in [0, 1] written with
/// a standard perspective projection (glDepthRange(0, 1), NDC z in [-1, 1]). far may be +inf.
[[nodiscard]] float linearDepthFromWindow(float windowDepth, float nearPlane, float farPlane) noexcept;
/// The inverse: window depth of a point `linearDepth` in front of the camera.
[[nodiscard]] float windowDepthFromLinear(float linearDepth, float nearPlane, float farPlane) noexcept;
/// Linear view depth of a reversed-Z window depth (near -> 1, far -> 0; glClipControl(GL_LOWER_LEFT,
/// GL_ZERO_TO_ONE)); far may be +inf, where depth = near / z.
[[nodiscard]] float linearDepthFromReversed(float windowDepth, float nearPlane, float farPlane) noexcept;

} // namespace photopic
