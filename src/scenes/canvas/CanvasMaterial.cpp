#include "scenes/canvas/CanvasMaterial.h"

#include "core/Hash.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace photopic {

float sparkleCosine() {
    return std::pow(kSparkleGate, 1.0f / kSparkleExponent);
}

glm::vec3 decodeMaterialNormal(std::uint8_t r, std::uint8_t g) {
    const float x = float(r) / 255.0f * 2.0f - 1.0f;
    const float y = float(g) / 255.0f * 2.0f - 1.0f;
    return {x, y, std::sqrt(std::max(0.0f, 1.0f - x * x - y * y))};
}

void encodeMaterialNormal(glm::vec3 n, std::uint8_t& r, std::uint8_t& g) {
    const glm::vec3 u = glm::normalize(n);
    const auto code = [](float v) {
        return std::uint8_t(std::lround(std::clamp((v + 1.0f) * 0.5f, 0.0f, 1.0f) * 255.0f));
    };
    r = code(u.x);
    g = code(u.y);
}

float decodeShininess(std::uint8_t b) {
    return b == 0 ? 0.0f : std::exp2(kMaxShininessLog2 * float(b) / 255.0f);
}

TileGrid makeTileGrid(int width, int height, int tileSize) {
    return {.tileSize = tileSize,
            .tilesX = (width + tileSize - 1) / tileSize,
            .tilesY = (height + tileSize - 1) / tileSize};
}

std::vector<std::uint8_t> chooseTiles(const TileGrid& grid, double fraction, std::uint32_t seed) {
    const int n = grid.count();
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [seed](int a, int b) {
        const std::uint32_t ha = hash32(std::uint32_t(a) ^ hash32(seed)),
                            hb = hash32(std::uint32_t(b) ^ hash32(seed));
        return ha != hb ? ha < hb : a < b;
    });
    const int chosen = int(std::lround(std::clamp(fraction, 0.0, 1.0) * double(n)));
    std::vector<std::uint8_t> flags(std::size_t(n), 0);
    for (int i = 0; i < chosen; ++i) {
        flags[std::size_t(order[std::size_t(i)])] = 1;
    }
    return flags;
}

std::vector<std::uint8_t> tileOccupancy(const Image8& material, const TileGrid& grid) {
    std::vector<std::uint8_t> flags(std::size_t(grid.count()), 0);
    for (int y = 0; y < material.height; ++y) {
        for (int x = 0; x < material.width; ++x) {
            if (hasMaterial(material.at(x, y))) {
                flags[std::size_t(grid.tileOfImagePixel(x, y, material.height))] = 1;
            }
        }
    }
    return flags;
}

glm::vec3 canvasPosition(float x, float y, float width, float height) {
    return {(x + 0.5f - 0.5f * width) / height, (y + 0.5f - 0.5f * height) / height, 0.0f};
}

glm::vec3 shadeCanvasPixel(glm::vec3 base, const std::uint8_t* material, glm::vec3 position,
                           const CanvasLighting& lighting) {
    const glm::vec3 n = decodeMaterialNormal(material[0], material[1]);
    const glm::vec3& l = lighting.light;
    const float nl = glm::dot(n, l);
    glm::vec3 c = base * lighting.lightColor * (lighting.ambient + std::max(nl, 0.0f));
    const float shininess = decodeShininess(material[2]);
    if (shininess > 0.0f && nl > 0.0f) {
        const glm::vec3 v = glm::normalize(glm::vec3(0, 0, lighting.viewDistance) - position);
        const glm::vec3 h = glm::normalize(l + v);
        c += lighting.specular * std::pow(std::max(glm::dot(n, h), 0.0f), shininess) * lighting.lightColor;
    }
    if (material[3] >= 128) {
        const float sparkle = std::pow(std::max(nl, 0.0f), kSparkleExponent);
        if (sparkle > kSparkleGate) {
            c += sparkle * lighting.lightColor * lighting.sparkleExposure;
        }
    }
    return c;
}

} // namespace photopic
