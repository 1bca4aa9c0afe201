#include "scenes/SyntheticHdr.h"

#include <cmath>
#include <cstring>

namespace photopic {

ImageF makeSyntheticHdr(int width, int height) {
    ImageF image(width, height);
    const float h = float(height);
    struct Light {
        float x, y, radius, r, g, b;
    };
    // Positions and radii in image heights; the sun is ~14 stops above the floor's dark squares.
    const Light lights[] = {{1.2f, 0.22f, 0.035f, 4000.0f, 3600.0f, 3000.0f},
                            {0.35f, 0.62f, 0.012f, 60.0f, 40.0f, 20.0f},
                            {0.55f, 0.64f, 0.010f, 20.0f, 40.0f, 60.0f}};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            const float u = float(x) / h, v = float(y) / h;
            float r, g, b;
            if (v < 0.55f) {
                const float t = v / 0.55f;
                r = 0.4f + 0.8f * t;
                g = 0.6f + 0.7f * t;
                b = 1.5f + 0.2f * t;
            } else {
                // A floor checker rotated 30 degrees: hard, aliased diagonal edges for FXAA.
                const float cu = u * 0.866f - v * 0.5f, cv = u * 0.5f + v * 0.866f;
                const bool light = (int(std::floor(cu * 12.0f)) + int(std::floor(cv * 12.0f))) % 2 == 0;
                r = g = b = light ? 0.5f : 0.02f;
            }
            for (const Light& l : lights) {
                if (std::hypot(u - l.x, v - l.y) < l.radius) {
                    r = l.r;
                    g = l.g;
                    b = l.b;
                }
            }
            p[0] = r;
            p[1] = g;
            p[2] = b;
            p[3] = 1.0f;
        }
    }
    return image;
}

ImageF mirroredTo(const ImageF& image, int width, int height) {
    const auto mirror = [](int i, int n) {
        const int m = i % (2 * n);
        return m < n ? m : 2 * n - 1 - m;
    };
    ImageF out(width, height);
    for (int y = 0; y < height; ++y) {
        const int sy = mirror(y, image.height);
        for (int x = 0; x < width; ++x) {
            std::memcpy(out.at(x, y), image.at(mirror(x, image.width), sy), 4 * sizeof(float));
        }
    }
    return out;
}

} // namespace photopic
