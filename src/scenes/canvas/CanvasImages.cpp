#include "scenes/canvas/CanvasImages.h"

#include "core/Hash.h"

#include "core/Color.h"
#include "io/ImageIO.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace photopic {

namespace {

/// Deterministic uniform [0, 1) from a few integers.
float random01(std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0) {
    const std::uint32_t h = hash32(a ^ hash32(b ^ hash32(c + 0x9e3779b9U)));
    return float(h >> 8) / float(1u << 24);
}

glm::vec3 fromSrgb(float r, float g, float b) {
    return srgbDecode(glm::vec3(r, g, b));
}

enum class Paint { Matte, Gloss, Glitter };

struct Stroke {
    glm::vec2 centre; ///< image heights, y down
    float angle = 0;  ///< rad, image space (y down)
    float halfLength = 0;
    float halfWidth = 0;
    glm::vec3 color{0};
    Paint paint = Paint::Matte;
};

// The painting's composition, in image heights with y down: sky above 0.45, hills to 0.66, water below, a
// sun.
constexpr float kHorizon = 0.45f;
constexpr float kShore = 0.66f;

glm::vec2 sunCentre(float aspect) {
    return {0.70f * aspect, 0.21f};
}

Stroke makeStroke(std::uint32_t seed, std::uint32_t i, float aspect) {
    const auto r = [&](std::uint32_t k) { return random01(seed, i, k); };
    Stroke s;
    s.centre = {r(0) * (aspect + 0.1f) - 0.05f, r(1) * 1.1f - 0.05f};
    const glm::vec2 sun = sunCentre(aspect);
    const glm::vec2 toSun = s.centre - sun;
    const float sunDistance = glm::length(toSun);
    const float jitter = (r(2) - 0.5f) * 0.5f;
    float v = r(3);
    if (sunDistance < 0.11f) {
        // Strokes around the sun follow circles (a Van Gogh swirl) and carry glitter.
        s.angle = std::atan2(toSun.y, toSun.x) + 0.5f * std::numbers::pi_v<float> + jitter * 0.4f;
        s.color = glm::mix(fromSrgb(0.98f, 0.84f, 0.30f), fromSrgb(0.95f, 0.55f, 0.15f), v);
        s.paint = r(4) < 0.55f ? Paint::Glitter : Paint::Gloss;
    } else if (s.centre.y < kHorizon) {
        const float swirl = std::sin(s.centre.x * 7.0f + s.centre.y * 5.0f) * 0.6f;
        s.angle = swirl + jitter;
        const glm::vec3 deep = fromSrgb(0.16f, 0.27f, 0.58f), light = fromSrgb(0.55f, 0.70f, 0.88f),
                        cloud = fromSrgb(0.90f, 0.90f, 0.82f);
        s.color = v < 0.15f ? cloud : glm::mix(deep, light, v * (1.0f - s.centre.y / kHorizon * 0.5f));
        s.paint = r(4) < 0.4f ? Paint::Gloss : Paint::Matte;
    } else if (s.centre.y < kShore) {
        s.angle = -0.35f + 0.3f * std::sin(s.centre.x * 4.0f) + jitter;
        const glm::vec3 grass = fromSrgb(0.30f, 0.48f, 0.20f), ochre = fromSrgb(0.66f, 0.52f, 0.24f),
                        shade = fromSrgb(0.14f, 0.26f, 0.16f);
        s.color = v < 0.5f ? glm::mix(shade, grass, v * 2.0f) : glm::mix(grass, ochre, (v - 0.5f) * 2.0f);
        s.paint = r(4) < 0.25f ? Paint::Gloss : Paint::Matte;
    } else {
        s.angle = jitter * 0.3f;
        const glm::vec3 sea = fromSrgb(0.08f, 0.25f, 0.40f), teal = fromSrgb(0.20f, 0.50f, 0.55f),
                        glint = fromSrgb(0.85f, 0.80f, 0.60f);
        // The sun's path on the water: pale strokes with glitter under the sun.
        const bool path = std::abs(s.centre.x - sun.x) < 0.08f + 0.15f * (s.centre.y - kShore);
        s.color = path && v < 0.6f ? glint : glm::mix(sea, teal, v);
        s.paint = path ? Paint::Glitter : (r(4) < 0.5f ? Paint::Gloss : Paint::Matte);
    }
    const float size = 0.6f + 0.8f * r(5);
    s.halfLength = (sunDistance < 0.11f ? 0.035f : 0.07f) * size;
    s.halfWidth = (sunDistance < 0.11f ? 0.008f : 0.014f) * (0.7f + 0.6f * r(6));
    return s;
}

/// Exponent n of the Blinn-Phong lobe encoded as B (CanvasMaterial.h): the inverse of decodeShininess.
std::uint8_t encodeShininess(float n) {
    return std::uint8_t(std::clamp(std::lround(std::log2(n) / kMaxShininessLog2 * 255.0f), 1L, 255L));
}

/// What the strokes leave besides colour, a value a pixel (row-major): the surface normal and the paint.
struct PaintedSurface {
    int width = 0;
    std::vector<glm::vec3> normal;
    std::vector<Paint> paint;

    PaintedSurface(int w, int h)
        : width(w)
        , normal(std::size_t(w) * std::size_t(h), glm::vec3(0, 0, 1))
        , paint(std::size_t(w) * std::size_t(h), Paint::Matte) {}

    [[nodiscard]] std::size_t index(int x, int y) const {
        return std::size_t(y) * std::size_t(width) + std::size_t(x);
    }
};

/// Ground: a warm underpainting and the canvas weave (a faint bump at ~1/180 of the height per thread).
void paintGround(ImageF& color, PaintedSurface& surface) {
    const int w = color.width, h = color.height;
    const float H = float(h);
    const float weave = 2.0f * std::numbers::pi_v<float> * 120.0f;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float u = (float(x) + 0.5f) / H, v = (float(y) + 0.5f) / H;
            const glm::vec3 ground =
                glm::mix(fromSrgb(0.62f, 0.58f, 0.50f), fromSrgb(0.45f, 0.36f, 0.26f), v);
            float* c = color.at(x, y);
            c[0] = ground.r;
            c[1] = ground.g;
            c[2] = ground.b;
            c[3] = 1.0f;
            surface.normal[surface.index(x, y)] =
                glm::normalize(glm::vec3(0.04f * std::sin(u * weave), 0.04f * std::sin(v * weave), 1.0f));
        }
    }
}

/// Stroke `i` (`s`) over its bounding box, so the cost is its area, not strokes x pixels.
void paintStroke(const Stroke& s, std::uint32_t seed, std::uint32_t i, ImageF& color,
                 PaintedSurface& surface) {
    const int w = color.width, h = color.height;
    const float H = float(h);
    const glm::vec2 along(std::cos(s.angle), std::sin(s.angle)), across(-along.y, along.x);
    const float reach = s.halfLength + s.halfWidth;
    const int x0 = std::max(0, int((s.centre.x - reach) * H)),
              x1 = std::min(w - 1, int((s.centre.x + reach) * H));
    const int y0 = std::max(0, int((s.centre.y - reach) * H)),
              y1 = std::min(h - 1, int((s.centre.y + reach) * H));
    const float bristleWidth = std::max(s.halfWidth / 5.0f, 1.2f / H);
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 d = glm::vec2((float(x) + 0.5f) / H, (float(y) + 0.5f) / H) - s.centre;
            const float sAlong = glm::dot(d, along) / s.halfLength, tAcross = glm::dot(d, across);
            if (std::abs(sAlong) >= 1.0f) {
                continue;
            }
            // Round-ended taper; the brush runs dry towards its end (positive sAlong) bristle by bristle.
            const float halfWidth = s.halfWidth * std::sqrt(1.0f - sAlong * sAlong);
            const float edge = (halfWidth - std::abs(tAcross)) * H; // px inside the stroke's edge
            if (edge <= 0.0f) {
                continue;
            }
            const int bristle = int(std::floor(tAcross / bristleWidth));
            const float dry = random01(seed, i, std::uint32_t(bristle + 1000));
            if (sAlong > 0.4f && dry < (sAlong - 0.4f) * 1.4f) {
                continue;
            }
            const float alpha = std::min(edge, 1.0f);
            const float streak = 0.85f + 0.3f * random01(seed, i, std::uint32_t(bristle + 5000));
            const std::size_t k = surface.index(x, y);
            float* c = color.at(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                c[ch] = c[ch] + (std::min(s.color[ch] * streak, 0.8f) - c[ch]) * alpha;
            }
            // Impasto: grooves between bristles and a ridge at the stroke's edges tilt the normal across it.
            const float phase = tAcross / bristleWidth * 2.0f * std::numbers::pi_v<float>;
            const float tilt = 0.25f * std::sin(phase) +
                               0.35f * std::clamp(tAcross / std::max(halfWidth, 1e-6f), -1.0f, 1.0f) *
                                   (std::abs(tAcross) > 0.7f * halfWidth ? 1.0f : 0.0f);
            // Image space is y down; the canvas frame (the normals') is y up.
            const glm::vec3 n = glm::normalize(glm::vec3(across.x * tilt, -across.y * tilt, 1.0f));
            surface.normal[k] = glm::normalize(glm::mix(surface.normal[k], n, alpha));
            if (alpha > 0.5f) {
                surface.paint[k] = s.paint;
            }
        }
    }
}

/// Material: normals everywhere; varnish and glitter only on the chosen tiles, so the others have no
/// material.
void writeMaterial(const ProceduralCanvasInfo& info, const PaintedSurface& surface, Image8& material) {
    const int w = info.width, h = info.height;
    const TileGrid grid = makeTileGrid(w, h, info.tileSize);
    const std::vector<std::uint8_t> chosen = chooseTiles(grid, info.occupancy, info.seed);
    const int facet = std::max(2, int(std::lround(float(h) / 216.0f))); // glitter flake size, px
    const std::uint8_t varnish = encodeShininess(40.0f), gloss = encodeShininess(160.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t k = surface.index(x, y);
            std::uint8_t* m = material.at(x, y);
            glm::vec3 n = surface.normal[k];
            m[2] = 0;
            m[3] = 0;
            if (chosen[std::size_t(grid.tileOfImagePixel(x, y, h))]) {
                if (surface.paint[k] == Paint::Glitter) {
                    // One flat flake per facet cell, tilted up to ~17 degrees: each catches the lamp at its
                    // own tilt, which is what makes glitter twinkle as the device moves.
                    const std::uint32_t cx = std::uint32_t(x / facet), cy = std::uint32_t(y / facet);
                    const float theta = 0.30f * std::sqrt(random01(info.seed + 7u, cx, cy));
                    const float phi = 2.0f * std::numbers::pi_v<float> * random01(info.seed + 11u, cx, cy);
                    n = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
                    m[3] = 255;
                } else {
                    m[2] = surface.paint[k] == Paint::Gloss ? gloss : varnish;
                }
            }
            encodeMaterialNormal(n, m[0], m[1]);
        }
    }
}

} // namespace

CanvasImages makeProceduralCanvas(const ProceduralCanvasInfo& info) {
    const int w = info.width, h = info.height;
    const float aspect = float(w) / float(h);
    CanvasImages out{ImageF(w, h), Image8(w, h)};
    PaintedSurface surface(w, h);
    paintGround(out.color, surface);
    // Strokes, painted in order.
    const int strokes = int(900.0f * aspect);
    for (int i = 0; i < strokes; ++i) {
        paintStroke(makeStroke(info.seed, std::uint32_t(i), aspect), info.seed, std::uint32_t(i), out.color,
                    surface);
    }
    writeMaterial(info, surface, out.material);
    return out;
}

ImageF loadCanvasColor(const std::filesystem::path& path, int width, int height) {
    const ImageF src = readImage(path);
    ImageF out(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float sx = std::clamp((float(x) + 0.5f) * float(src.width) / float(width) - 0.5f, 0.0f,
                                        float(src.width - 1));
            const float sy = std::clamp((float(y) + 0.5f) * float(src.height) / float(height) - 0.5f, 0.0f,
                                        float(src.height - 1));
            const int ix = std::min(int(sx), src.width - 2 < 0 ? 0 : src.width - 2);
            const int iy = std::min(int(sy), src.height - 2 < 0 ? 0 : src.height - 2);
            const int jx = std::min(ix + 1, src.width - 1), jy = std::min(iy + 1, src.height - 1);
            const float fx = sx - float(ix), fy = sy - float(iy);
            float* o = out.at(x, y);
            for (int c = 0; c < 4; ++c) {
                const float top = src.at(ix, iy)[c] + (src.at(jx, iy)[c] - src.at(ix, iy)[c]) * fx;
                const float bottom = src.at(ix, jy)[c] + (src.at(jx, jy)[c] - src.at(ix, jy)[c]) * fx;
                o[c] = top + (bottom - top) * fy;
            }
            o[3] = 1.0f;
        }
    }
    return out;
}

Image8 loadCanvasMaterial(const std::filesystem::path& path, int width, int height) {
    const Image8 src = readPng8(path);
    for (int y = 0; y < src.height; ++y) {
        for (int x = 0; x < src.width; ++x) {
            const std::uint8_t* m = src.at(x, y);
            const float nx = float(m[0]) / 255.0f * 2.0f - 1.0f, ny = float(m[1]) / 255.0f * 2.0f - 1.0f;
            // One code step of slack: (128, 255) is a valid, fully tilted normal once rounded.
            if (nx * nx + ny * ny > 1.0f + 2.0f / 255.0f) {
                throw IoError(
                    path, fmt::format("not a material map: pixel ({}, {}) has normal x, y = ({:.3f}, {:.3f}) "
                                      "outside the unit disc (R, G encode the normal's x, y as (v + 1) / 2)",
                                      x, y, nx, ny));
            }
        }
    }
    Image8 out(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int sx = std::min(src.width - 1, int((std::int64_t(x) * src.width) / width));
            const int sy = std::min(src.height - 1, int((std::int64_t(y) * src.height) / height));
            std::copy_n(src.at(sx, sy), 4, out.at(x, y));
        }
    }
    return out;
}

} // namespace photopic
