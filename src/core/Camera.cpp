#include "core/Camera.h"

#include <cmath>
#include <limits>

namespace photopic {

namespace {

bool within(float v, float lo, float hi) noexcept {
    return v >= lo && v <= hi;
}

} // namespace

bool allFinite(const glm::mat4& m) noexcept {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) {
                return false;
            }
        }
    }
    return true;
}

const char* invalidCameraReason(const Camera& c) noexcept {
    if (!allFinite(c.view)) {
        return "camera.view has a non-finite entry";
    }
    if (!allFinite(c.projection)) {
        return "camera.projection has a non-finite entry";
    }
    if (!allFinite(c.prevViewProjection)) {
        return "camera.prevViewProjection has a non-finite entry";
    }
    if (!(std::isfinite(c.nearPlane) && c.nearPlane > 0.0f)) {
        return "camera.nearPlane must be finite and > 0";
    }
    if (std::isnan(c.farPlane) || !(c.farPlane > c.nearPlane)) {
        return "camera.farPlane must be > nearPlane (+inf for an infinite projection)";
    }
    if (!(c.verticalFov > 0.0f && c.verticalFov < 3.14159265f)) {
        return "camera.verticalFov must be in (0, pi) radians";
    }
    const Lens& l = c.lens;
    if (!(l.focalLengthMm > 0.0f && l.focalLengthMm <= 10000.0f) ||
        !(l.sensorHeightMm > 0.0f && l.sensorHeightMm <= 1000.0f)) {
        return "camera.lens: focalLengthMm must be in (0, 10000] and sensorHeightMm in (0, 1000]";
    }
    if (!within(l.fNumber, 0.5f, 256.0f) || !within(l.shutterAngleDeg, 0.0f, 360.0f) ||
        !within(l.exposureTimeS, 0.0f, 60.0f) || !within(l.iso, 1.0f, 1e6f)) {
        return "camera.lens: fNumber [0.5, 256], shutterAngleDeg [0, 360], exposureTimeS [0, 60], iso [1, "
               "1e6]";
    }
    if (!(std::isfinite(l.focusDistance) && l.focusDistance > 0.0f)) {
        return "camera.lens.focusDistance must be finite and > 0";
    }
    return nullptr;
}

glm::mat4 perspectiveProjection(float verticalFov, float aspect, float nearPlane, float farPlane) {
    const float f = 1.0f / std::tan(0.5f * verticalFov);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][3] = -1.0f;
    if (std::isinf(farPlane)) {
        p[2][2] = -1.0f;
        p[3][2] = -2.0f * nearPlane;
    } else {
        p[2][2] = -(farPlane + nearPlane) / (farPlane - nearPlane);
        p[3][2] = -2.0f * farPlane * nearPlane / (farPlane - nearPlane);
    }
    return p;
}

float halton(std::uint32_t index, std::uint32_t base) noexcept {
    // Radical inverse: the base-b digits of index mirrored about the radix point.
    float result = 0.0f;
    float fraction = 1.0f;
    while (index > 0) {
        fraction /= float(base);
        result += fraction * float(index % base);
        index /= base;
    }
    return result;
}

glm::vec2 haltonJitter(std::uint64_t frameIndex, int cycle) noexcept {
    const std::uint64_t length = cycle < 1 ? 1u : std::uint64_t(cycle);
    const auto index = std::uint32_t(frameIndex % length) + 1u;
    return {halton(index, 2) - 0.5f, halton(index, 3) - 0.5f};
}

glm::vec2 jitterClipOffset(glm::vec2 jitterPixels, int width, int height) noexcept {
    // NDC spans 2 units over the target, so one pixel is 2 / size.
    return {2.0f * jitterPixels.x / float(width), 2.0f * jitterPixels.y / float(height)};
}

glm::mat4 jitteredProjection(const glm::mat4& projection, glm::vec2 jitterPixels, int width,
                             int height) noexcept {
    // Adding the offset times clip w to clip x/y shifts NDC by the offset for every depth: for a perspective
    // matrix w = -z_view (row 3 is (0, 0, -1, 0)), for an orthographic one w = 1; both are covered by adding
    // offset * row 3 to rows 0 and 1.
    const glm::vec2 o = jitterClipOffset(jitterPixels, width, height);
    glm::mat4 p = projection;
    for (int c = 0; c < 4; ++c) {
        p[c][0] += o.x * projection[c][3];
        p[c][1] += o.y * projection[c][3];
    }
    return p;
}

float linearDepthFromWindow(float windowDepth, float nearPlane, float farPlane) noexcept {
    const float ndc = 2.0f * windowDepth - 1.0f;
    if (std::isinf(farPlane)) {
        // z_ndc = 1 + 2n / z_view  (z_view < 0)
        return ndc >= 1.0f ? std::numeric_limits<float>::infinity() : 2.0f * nearPlane / (1.0f - ndc);
    }
    return 2.0f * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
}

float windowDepthFromLinear(float linearDepth, float nearPlane, float farPlane) noexcept {
    float ndc = 0.0f;
    if (std::isinf(farPlane)) {
        ndc = 1.0f - 2.0f * nearPlane / linearDepth;
    } else {
        ndc = (farPlane + nearPlane - 2.0f * nearPlane * farPlane / linearDepth) / (farPlane - nearPlane);
    }
    return 0.5f * ndc + 0.5f;
}

float linearDepthFromReversed(float windowDepth, float nearPlane, float farPlane) noexcept {
    if (windowDepth <= 0.0f) {
        return std::isinf(farPlane) ? std::numeric_limits<float>::infinity() : farPlane;
    }
    if (std::isinf(farPlane)) {
        return nearPlane / windowDepth;
    }
    // d = n (f - z) / (z (f - n))  ->  z = n f / (d (f - n) + n)
    return nearPlane * farPlane / (windowDepth * (farPlane - nearPlane) + nearPlane);
}

void viewRays(const glm::mat4& projection, glm::vec4 (&nearRay)[3], glm::vec4 (&farRay)[3]) noexcept {
    const glm::mat4 inv = glm::inverse(projection);
    const auto point = [&](float x, float y, float z) {
        const glm::vec4 p = inv * glm::vec4(x, y, z, 1.0f);
        return glm::vec4(glm::vec3(p) / p.w, 0.0f);
    };
    for (int k = 0; k < 2; ++k) {
        const float z = k == 0 ? -1.0f : 0.0f;
        glm::vec4(&ray)[3] = k == 0 ? nearRay : farRay;
        ray[0] = point(0.0f, 0.0f, z);
        ray[1] = point(1.0f, 0.0f, z) - ray[0];
        ray[2] = point(0.0f, 1.0f, z) - ray[0];
    }
}

bool isPerspective(const glm::mat4& m) noexcept {
    // Clip w = m[2][3] z (no x, y or constant term), clip x and y without a constant term, clip z from z
    // alone.
    return m[3][3] == 0.0f && m[2][3] != 0.0f && m[0][3] == 0.0f && m[1][3] == 0.0f && m[3][0] == 0.0f &&
           m[3][1] == 0.0f && m[0][2] == 0.0f && m[1][2] == 0.0f;
}

} // namespace photopic
