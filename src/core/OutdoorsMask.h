#pragma once
// The outdoors (roof) mask on the CPU: 8-bit, 255 = open sky, 0 = under a roof,
// queried bilinearly at a world position for "is this subject outdoors?" without touching the GPU.
//
// Coordinate contract (every caller goes through worldToMaskUv):
//   world: x right, y DOWN (map / Foundry pixels); the scene rect is [x, x + width) x [y, y + height).
//   mask UV: u = (wx - rect.x) / rect.width, v = 1 - (wy - rect.y) / rect.height   (V flipped).
//   The mask is stored the way a GL texture is: row 0 at v = 0, i.e. the BOTTOM of the map (its largest world
//   y). Texel (i, j) has its centre at uv = ((i + 0.5) / W, (j + 0.5) / H); sampling is bilinear between
//   texel centres and clamps to the edge texels, like GL_LINEAR + GL_CLAMP_TO_EDGE on an R8 texture.

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace photopic {

/// The map area the mask covers, in world units (y down).
struct SceneRect {
    float x = 0.0f;
    float y = 0.0f;
    float width = 1.0f;
    float height = 1.0f;
};

/// World position -> mask UV with V flipped (see the contract above). Not clamped.
[[nodiscard]] glm::vec2 worldToMaskUv(const SceneRect& rect, glm::vec2 world) noexcept;

class OutdoorsMask {
public:
    OutdoorsMask() = default;
    /// `texels` holds width * height bytes, row 0 = v = 0 = the bottom of the map. Throws
    /// std::invalid_argument when the size does not match or is not positive.
    OutdoorsMask(int width, int height, std::vector<std::uint8_t> texels, SceneRect rect);

    [[nodiscard]] bool empty() const { return mTexels.empty(); }
    [[nodiscard]] int width() const { return mWidth; }
    [[nodiscard]] int height() const { return mHeight; }
    [[nodiscard]] const SceneRect& rect() const { return mRect; }
    [[nodiscard]] const std::vector<std::uint8_t>& texels() const { return mTexels; }

    /// Bilinear outdoors value in [0, 1] at mask UV (v up). 0 when the mask is empty; NaN UV reads as 0.5.
    [[nodiscard]] float sampleUv(glm::vec2 uv) const noexcept;
    /// Bilinear outdoors value in [0, 1] at a world position.
    [[nodiscard]] float atWorld(float x, float y) const noexcept {
        return sampleUv(worldToMaskUv(mRect, {x, y}));
    }

private:
    int mWidth = 0;
    int mHeight = 0;
    std::vector<std::uint8_t> mTexels;
    SceneRect mRect;
};

} // namespace photopic
