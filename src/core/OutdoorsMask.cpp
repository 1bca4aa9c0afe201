#include "core/OutdoorsMask.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace photopic {

glm::vec2 worldToMaskUv(const SceneRect& rect, glm::vec2 world) noexcept {
    const float u = (world.x - rect.x) / rect.width;
    const float v = 1.0f - (world.y - rect.y) / rect.height;
    return {u, v};
}

OutdoorsMask::OutdoorsMask(int width, int height, std::vector<std::uint8_t> texels, SceneRect rect)
    : mWidth(width)
    , mHeight(height)
    , mTexels(std::move(texels))
    , mRect(rect) {
    if (width < 1 || height < 1 || mTexels.size() != std::size_t(width) * std::size_t(height)) {
        throw std::invalid_argument("outdoors mask: " + std::to_string(mTexels.size()) +
                                    " bytes do not make a " + std::to_string(width) + "x" +
                                    std::to_string(height) + " mask");
    }
    if (!(rect.width > 0.0f) || !(rect.height > 0.0f)) {
        throw std::invalid_argument("outdoors mask: the scene rect needs a positive width and height");
    }
}

float OutdoorsMask::sampleUv(glm::vec2 uv) const noexcept {
    if (mTexels.empty()) {
        return 0.0f;
    }
    const float u = std::isnan(uv.x) ? 0.5f : std::clamp(uv.x, 0.0f, 1.0f);
    const float v = std::isnan(uv.y) ? 0.5f : std::clamp(uv.y, 0.0f, 1.0f);
    // Texel centres at (i + 0.5) / W: the bilinear cell starts half a texel to the left.
    const float px = u * float(mWidth) - 0.5f;
    const float py = v * float(mHeight) - 0.5f;
    const float fx = std::floor(px);
    const float fy = std::floor(py);
    const float tx = px - fx;
    const float ty = py - fy;
    const int x0 = std::clamp(int(fx), 0, mWidth - 1);
    const int y0 = std::clamp(int(fy), 0, mHeight - 1);
    const int x1 = std::clamp(int(fx) + 1, 0, mWidth - 1);
    const int y1 = std::clamp(int(fy) + 1, 0, mHeight - 1);
    auto at = [&](int x, int y) {
        return float(mTexels[std::size_t(y) * std::size_t(mWidth) + std::size_t(x)]);
    };
    const float top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * tx;
    const float bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * tx;
    return (top + (bottom - top) * ty) * (1.0f / 255.0f);
}

} // namespace photopic
