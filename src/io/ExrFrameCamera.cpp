#include "io/ExrFrame.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

// A frame's camera attributes (OpenEXR's conventions) turned into a GL Camera and back: cameraFromExr,
// frameCamera, exrFromCamera, dataWindowCrop.
namespace photopic {

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Camera conventions

/// OpenEXR's left-handed camera space (+z forward) <-> GL's right-handed view space (-z forward).
const glm::mat4 kFlipZ =
    glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 0, 1));
constexpr float kFallbackNear = 0.1f;

glm::vec4 row(const glm::mat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}
void setRow(glm::mat4& m, int r, const glm::vec4& v) {
    for (int c = 0; c < 4; ++c)
        m[c][r] = v[c];
}

struct GlCamera {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float nearPlane = kFallbackNear;
    float farPlane = std::numeric_limits<float>::infinity();
    float verticalFov = 1.0f;
};

/// near/far from the clip attributes, else from K's z row read as RenderMan's NDC depth z_ndc = a + b / z
/// (z = camera depth = K's w after normalisation): n = -b / a, f = b / (1 - a), a = 1 for an infinite far.
void nearFar(const ExrCameraAttributes& a, const glm::vec4& zRow, GlCamera& camera) {
    if (a.nearClip && a.farClip) {
        camera.nearPlane = *a.nearClip;
        camera.farPlane = *a.farClip;
        return;
    }
    const float scale = std::max(std::abs(zRow.z), std::abs(zRow.w));
    const bool depthOnly =
        scale > 0.0f && std::abs(zRow.x) <= 1e-6f * scale && std::abs(zRow.y) <= 1e-6f * scale;
    if (depthOnly) {
        // In GL view space the camera depth is -z, so the row is (0, 0, -a, b).
        const double aa = -double(zRow.z);
        const double bb = double(zRow.w);
        const double n = aa != 0.0 ? -bb / aa : 0.0;
        const double f =
            std::abs(1.0 - aa) < 1e-6 ? std::numeric_limits<double>::infinity() : bb / (1.0 - aa);
        if (std::isfinite(n) && n > 0.0 && f > n) {
            camera.nearPlane = float(n);
            camera.farPlane = float(f);
        }
    }
    if (a.nearClip)
        camera.nearPlane = *a.nearClip;
    if (a.farClip)
        camera.farPlane = *a.farClip;
}

GlCamera glCamera(const ExrCameraAttributes& a) {
    const glm::mat4& worldToCamera = *a.worldToCamera;
    const glm::mat4& worldToNdc = *a.worldToNDC;
    if (!allFinite(worldToCamera))
        throw std::invalid_argument("worldToCamera has a non-finite entry");
    if (!allFinite(worldToNdc))
        throw std::invalid_argument("worldToNDC has a non-finite entry");
    const float det = glm::determinant(worldToCamera);
    if (!std::isfinite(det) || std::abs(det) < 1e-12f)
        throw std::invalid_argument("worldToCamera is not invertible");

    GlCamera camera;
    camera.view = kFlipZ * worldToCamera;
    // GL view space -> OpenEXR NDC (homogeneous).
    glm::mat4 k = worldToNdc * glm::inverse(worldToCamera) * kFlipZ;
    const glm::vec4 w = row(k, 3);
    const float wScale = std::max({std::abs(w.x), std::abs(w.y), std::abs(w.z), std::abs(w.w)});
    if (!(w.z < 0.0f) || std::abs(w.x) > 1e-5f * wScale || std::abs(w.y) > 1e-5f * wScale ||
        std::abs(w.w) > 1e-5f * wScale)
        throw std::invalid_argument(
            "worldToNDC is not a perspective projection of worldToCamera's camera space (its w must be "
            "proportional to camera depth)");
    k *= -1.0f / w.z; // w = -z_view, as GL's perspective projections have it
    nearFar(a, row(k, 2), camera);

    const float n = camera.nearPlane;
    const float f = camera.farPlane;
    if (!(std::isfinite(n) && n > 0.0f) || std::isnan(f) || !(f > n))
        throw std::invalid_argument(
            "near/far clip planes must satisfy 0 < near < far (nearClipPlane, farClipPlane)");
    glm::mat4 p(0.0f);
    setRow(p, 0, 2.0f * row(k, 0) - row(k, 3));
    setRow(p, 1, row(k, 3) - 2.0f * row(k, 1));
    setRow(p, 2,
           std::isinf(f) ? glm::vec4(0, 0, -1, -2.0f * n)
                         : glm::vec4(0, 0, -(f + n) / (f - n), -2.0f * f * n / (f - n)));
    setRow(p, 3, glm::vec4(0, 0, -1, 0));
    camera.projection = p;
    if (!(p[1][1] > 0.0f) || !(p[0][0] > 0.0f))
        throw std::invalid_argument("worldToNDC flips the image or is degenerate (x must map right, y down)");
    camera.verticalFov = 2.0f * std::atan(1.0f / p[1][1]);
    return camera;
}

void requireRange(const char* name, float value, float lo, float hi) {
    if (!(value >= lo && value <= hi))
        throw std::invalid_argument("attribute " + std::string(name) + " = " + std::to_string(value) +
                                    " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

Lens lensFromExr(const ExrCameraAttributes& a, float verticalFov) {
    Lens lens;
    const float tanHalf = std::tan(0.5f * verticalFov);
    const std::optional<float> sensorHeight =
        a.sensorOverallDimensions ? std::optional<float>(a.sensorOverallDimensions->y) : std::nullopt;
    if (a.pinholeFocalLength)
        requireRange("pinholeFocalLength", *a.pinholeFocalLength, 1e-3f, 10000.0f);
    if (sensorHeight)
        requireRange("sensorOverallDimensions.y", *sensorHeight, 1e-3f, 1000.0f);
    if (a.pinholeFocalLength && sensorHeight) {
        lens.focalLengthMm = *a.pinholeFocalLength;
        lens.sensorHeightMm = *sensorHeight;
    } else if (a.pinholeFocalLength) {
        lens.focalLengthMm = *a.pinholeFocalLength;
        lens.sensorHeightMm = 2.0f * lens.focalLengthMm * tanHalf;
    } else {
        lens.sensorHeightMm = sensorHeight.value_or(lens.sensorHeightMm);
        lens.focalLengthMm = lens.sensorHeightMm / (2.0f * tanHalf);
    }
    if (a.aperture) {
        requireRange("aperture", *a.aperture, 0.5f, 256.0f);
        lens.fNumber = *a.aperture;
    }
    if (a.focus) {
        if (!(std::isfinite(*a.focus) && *a.focus > 0.0f))
            throw std::invalid_argument("attribute focus must be finite and > 0");
        lens.focusDistance = *a.focus;
    }
    if (a.shutterAngle) {
        requireRange("shutterAngle", *a.shutterAngle, 0.0f, 360.0f);
        lens.shutterAngleDeg = *a.shutterAngle;
    }
    if (a.expTime) {
        requireRange("expTime", *a.expTime, 0.0f, 60.0f);
        lens.exposureTimeS = *a.expTime;
    }
    if (a.isoSpeed) {
        requireRange("isoSpeed", *a.isoSpeed, 1.0f, 1e6f);
        lens.iso = *a.isoSpeed;
    }
    return lens;
}

} // namespace

std::optional<Camera> cameraFromExr(const ExrCameraAttributes& attributes, int width, int height,
                                    const ExrCameraAttributes* previous) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("cameraFromExr: the frame has no pixels");
    if (!attributes.worldToCamera || !attributes.worldToNDC)
        return std::nullopt;
    const GlCamera current = glCamera(attributes);
    Camera camera;
    camera.view = current.view;
    camera.projection = current.projection;
    camera.nearPlane = current.nearPlane;
    camera.farPlane = current.farPlane;
    camera.verticalFov = current.verticalFov;
    camera.lens = lensFromExr(attributes, current.verticalFov);
    camera.prevViewProjection = camera.viewProjection();
    if (previous != nullptr && previous->worldToCamera && previous->worldToNDC) {
        const GlCamera last = glCamera(*previous);
        camera.prevViewProjection = last.projection * last.view;
    }
    if (const char* reason = invalidCameraReason(camera))
        throw std::invalid_argument(reason);
    return camera;
}

std::optional<Camera> frameCamera(const ExrFrame& frame, const ExrCameraAttributes* previous) {
    std::optional<Camera> camera =
        cameraFromExr(frame.camera, frame.displaySize.x, frame.displaySize.y, previous);
    const glm::ivec2 dataSize(frame.width(), frame.height());
    if (!camera || (frame.dataOrigin == glm::ivec2(0) && frame.displaySize == dataSize))
        return camera;
    const glm::mat4 crop = dataWindowCrop(frame.displaySize, frame.dataOrigin, dataSize);
    camera->projection = crop * camera->projection;
    camera->prevViewProjection = crop * camera->prevViewProjection;
    if (const char* reason = invalidCameraReason(*camera))
        throw std::invalid_argument(std::string("cropped to the data window: ") + reason);
    return camera;
}

ExrCameraAttributes exrFromCamera(const Camera& camera, int width, int height) {
    ExrCameraAttributes a;
    a.worldToCamera = kFlipZ * camera.view;
    const glm::mat4 clip = camera.projection * camera.view;
    const float n = camera.nearPlane;
    const float f = camera.farPlane;
    // RenderMan's NDC depth z_ndc = a + b / z for camera depth z = clip w: 0 at near, 1 at far.
    const float depthA = std::isinf(f) ? 1.0f : f / (f - n);
    const float depthB = std::isinf(f) ? -n : -n * f / (f - n);
    glm::mat4 ndc(0.0f);
    setRow(ndc, 0, 0.5f * (row(clip, 0) + row(clip, 3)));
    setRow(ndc, 1, 0.5f * (row(clip, 3) - row(clip, 1)));
    setRow(ndc, 2, depthA * row(clip, 3) + depthB * glm::vec4(0, 0, 0, 1));
    setRow(ndc, 3, row(clip, 3));
    a.worldToNDC = ndc;
    a.nearClip = n;
    a.farClip = f;
    const Lens& lens = camera.lens;
    a.focus = lens.focusDistance;
    a.aperture = lens.fNumber;
    if (lens.exposureTimeS > 0.0f)
        a.expTime = lens.exposureTimeS;
    a.isoSpeed = lens.iso;
    a.pinholeFocalLength = lens.focalLengthMm;
    a.sensorOverallDimensions =
        glm::vec2(lens.sensorHeightMm * float(width) / float(std::max(height, 1)), lens.sensorHeightMm);
    a.shutterAngle = lens.shutterAngleDeg;
    return a;
}

glm::mat4 dataWindowCrop(glm::ivec2 displaySize, glm::ivec2 dataOrigin, glm::ivec2 dataSize) {
    // Display-window pixels x right and y up: the data window spans [ox, ox + w] x [H - oy - h, H - oy].
    const glm::vec2 display(displaySize);
    const glm::vec2 size(dataSize);
    const glm::vec2 lower(float(dataOrigin.x), display.y - float(dataOrigin.y) - size.y);
    glm::mat4 crop(1.0f);
    crop[0][0] = display.x / size.x;
    crop[1][1] = display.y / size.y;
    // ndc' = ndc * D / d + (D - 2 lower) / d - 1, times clip w.
    crop[3][0] = (display.x - 2.0f * lower.x) / size.x - 1.0f;
    crop[3][1] = (display.y - 2.0f * lower.y) / size.y - 1.0f;
    return crop;
}

} // namespace photopic
