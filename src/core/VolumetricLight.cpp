#include "core/VolumetricLight.h"

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

bool finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The source at pixel (x, y): the sky's colour, 0 for occluders and outside the image.
glm::vec3 sourceAt(const ImageF& color, const ImageF& depth, int x, int y) {
    if (x < 0 || y < 0 || x >= color.width || y >= color.height) {
        return glm::vec3(0.0f);
    }
    const float z = depth.at(x, y)[0];
    if (!(std::isinf(z) && z > 0.0f)) {
        return glm::vec3(0.0f);
    }
    const float* c = color.at(x, y);
    glm::vec3 v(c[0], c[1], c[2]);
    return finite(v) ? glm::clamp(v, glm::vec3(0.0f), glm::vec3(65504.0f)) : glm::vec3(0.0f);
}

/// Bilinear source at a point in pixel units (x right, y down; pixel centres at + 0.5), 0 off the image.
glm::vec3 sourceBilinear(const ImageF& color, const ImageF& depth, glm::vec2 p) {
    if (p.x < 0.0f || p.y < 0.0f || p.x > float(color.width) || p.y > float(color.height)) {
        return glm::vec3(0.0f);
    }
    const glm::vec2 q = p - 0.5f;
    const int x0 = int(std::floor(q.x));
    const int y0 = int(std::floor(q.y));
    const float fx = q.x - float(x0);
    const float fy = q.y - float(y0);
    const auto clampedAt = [&](int x, int y) {
        return sourceAt(color, depth, std::clamp(x, 0, color.width - 1), std::clamp(y, 0, color.height - 1));
    };
    return glm::mix(glm::mix(clampedAt(x0, y0), clampedAt(x0 + 1, y0), fx),
                    glm::mix(clampedAt(x0, y0 + 1), clampedAt(x0 + 1, y0 + 1), fx), fy);
}

} // namespace

float sunScreenFade(glm::vec2 uv) noexcept {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        return 0.0f;
    }
    const float outside = std::max({-uv.x, uv.x - 1.0f, -uv.y, uv.y - 1.0f});
    const float f = std::clamp((kVolumetricSunFadeOutside - outside) /
                                   (kVolumetricSunFadeOutside + kVolumetricSunFadeInside),
                               0.0f, 1.0f);
    return f * f * (3.0f - 2.0f * f);
}

SunOnScreen sunOnScreen(const Camera& camera, glm::vec3 sunDirection) noexcept {
    SunOnScreen s;
    const float len = glm::length(sunDirection);
    if (!finite(sunDirection) || !(len > 0.0f)) {
        return s;
    }
    // A direction is a point at infinity: w = 0, so the view's translation does not move it.
    const glm::vec4 clip = camera.viewProjection() * glm::vec4(sunDirection / len, 0.0f);
    if (!(clip.w > 1e-6f * (std::abs(clip.x) + std::abs(clip.y) + 1e-6f))) {
        return s;
    }
    s.inFront = true;
    s.uv = 0.5f + 0.5f * glm::vec2(clip.x, clip.y) / clip.w;
    s.fade = sunScreenFade(s.uv);
    return s;
}

ImageF volumetricLightReference(const ImageF& color, const ImageF& depth, const SunOnScreen& sun,
                                const VolumetricLightSettings& settings, int samples) {
    ImageF out(color.width, color.height, 0.0f);
    const float scale = settings.intensity * settings.weight * settings.exposure * sun.fade;
    // The sun in pixel units, rows top to bottom.
    const glm::vec2 sunPx(sun.uv.x * float(color.width), (1.0f - sun.uv.y) * float(color.height));
    for (int y = 0; y < color.height; ++y) {
        for (int x = 0; x < color.width; ++x) {
            float* o = out.at(x, y);
            o[3] = 1.0f;
            if (!(scale > 0.0f) || samples <= 0) {
                continue;
            }
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            const glm::vec2 toSun = (sunPx - p) * settings.density;
            glm::vec3 sum(0.0f);
            for (int i = 0; i < samples; ++i) {
                const float t = (float(i) + 0.5f) / float(samples);
                sum += std::pow(settings.decay, 64.0f * t) * sourceBilinear(color, depth, p + t * toSun);
            }
            const glm::vec3 v = sum * (scale / float(samples));
            o[0] = v.x;
            o[1] = v.y;
            o[2] = v.z;
        }
    }
    return out;
}

} // namespace photopic
