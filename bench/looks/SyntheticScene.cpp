// The looks measure's own test image: what the data images lack, saturated lights of every hue and exposure
// ramps of the colours of the hue table, so the table's figures can be seen.

#include "ImageRuns.h"

#include "core/Color.h"

#include <glm/vec3.hpp>

#include <array>
#include <cmath>

namespace looks {

using photopic::ImageF;

namespace {

constexpr int kWidth = 480, kHeight = 270;

void fill(ImageF& image, int x0, int y0, int w, int h, glm::vec3 c) {
    for (int y = y0; y < y0 + h; ++y) {
        for (int x = x0; x < x0 + w; ++x) {
            float* p = image.at(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
        }
    }
}

glm::vec3 srgb8(int r, int g, int b) {
    return photopic::srgbDecode(glm::vec3(float(r), float(g), float(b)) / 255.0f);
}

// The 24 patches under light of 1.0 (the 18% grey patch near 0.18, mid exposure at 0 EV): the published sRGB
// values of the ColorChecker Classic (X-Rite/BabelColor), row by row.
void drawChart(ImageF& image) {
    static constexpr std::array<std::array<int, 3>, 24> kPatches = {{
        {115, 82, 68},   {194, 150, 130}, {98, 122, 157},  {87, 108, 67},   {133, 128, 177}, {103, 189, 170},
        {214, 126, 44},  {80, 91, 166},   {193, 90, 99},   {94, 60, 108},   {157, 188, 64},  {224, 163, 46},
        {56, 61, 150},   {70, 148, 73},   {175, 54, 60},   {231, 199, 31},  {187, 86, 149},  {8, 133, 161},
        {243, 243, 242}, {200, 200, 200}, {160, 160, 160}, {122, 122, 121}, {85, 85, 85},    {52, 52, 52},
    }};
    for (int i = 0; i < 24; ++i) {
        const auto& c = kPatches[std::size_t(i)];
        fill(image, 8 + (i % 6) * 38, 8 + (i / 6) * 38, 34, 34, srgb8(c[0], c[1], c[2]));
    }
}

// Six discs of light, radius 36 px, each a core of luminance 0.18 * 2^9 halving every 3 px outwards: every
// exposure from 9 EV over mid grey (r = 0) down to -3 EV (the rim) appears on one disc, 3 px an EV.
void drawLights(ImageF& image) {
    const glm::vec3 hues[6] = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {1, 0, 1}};
    for (int i = 0; i < 6; ++i) {
        const glm::vec3 colour = 0.9f * hues[i] + glm::vec3(0.1f);
        const glm::vec3 core = colour * (0.18f * 512.0f / photopic::luma709(colour));
        const int cx = kSyntheticLightX + (i % 3) * 74, cy = kSyntheticLightY + (i / 3) * 76;
        for (int y = cy - 36; y <= cy + 36; ++y) {
            for (int x = cx - 36; x <= cx + 36; ++x) {
                const float r = std::hypot(float(x - cx), float(y - cy));
                if (r > 36.0f) {
                    continue;
                }
                const glm::vec3 c = core * std::exp2(-r / 3.0f);
                float* p = image.at(x, y);
                p[0] = c.r;
                p[1] = c.g;
                p[2] = c.b;
            }
        }
    }
}

// Light skin, blue sky and red, each scaled to luminance 0.18 * 2^EV with EV from -2 (left) to +6 (right),
// the range of the hue table.
void drawRamps(ImageF& image) {
    const glm::vec3 colours[3] = {srgb8(194, 150, 130), srgb8(98, 122, 157), glm::vec3(1.0f, 0.1f, 0.1f)};
    for (int row = 0; row < 3; ++row) {
        const glm::vec3 unit = colours[row] / photopic::luma709(colours[row]);
        for (int x = 8; x < kWidth - 8; ++x) {
            const float ev = -2.0f + 8.0f * float(x - 8) / float(kWidth - 17);
            fill(image, x, 172 + row * 32, 1, 28, unit * 0.18f * std::exp2(ev));
        }
    }
}

} // namespace

ImageF makeSyntheticScene() {
    ImageF image(kWidth, kHeight, 0.0f);
    fill(image, 0, 0, kWidth, kHeight, glm::vec3(0.01f)); // a dim grey room, 4.2 stops under mid grey
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 1.0f;
    }
    drawChart(image);
    drawLights(image);
    drawRamps(image);
    return image;
}

} // namespace looks
