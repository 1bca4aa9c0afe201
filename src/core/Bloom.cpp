#include "core/Bloom.h"

#include <algorithm>
#include <cmath>

namespace photopic {

glm::vec4 bloomKneeConstants(float threshold, float kneeFraction) noexcept {
    // The 1e-5 keeps 1 / (4 knee) finite when the knee is 0 (a hard threshold).
    const float knee = threshold * kneeFraction + 1e-5f;
    return {threshold, threshold - knee, 2.0f * knee, 0.25f / knee};
}

float bloomPrefilterFactor(float brightness, const glm::vec4& knee) noexcept {
    float rq = std::clamp(brightness - knee.y, 0.0f, knee.z);
    rq = rq * rq * knee.w;
    return std::max(rq, brightness - knee.x) / std::max(brightness, 1e-4f);
}

glm::ivec2 bloomMipSize(glm::ivec2 size, int firstDivisor, int level) noexcept {
    const int divisor = firstDivisor << level;
    return {std::max(1, size.x / divisor), std::max(1, size.y / divisor)};
}

int bloomMipCount(glm::ivec2 size, int firstDivisor, int wanted) noexcept {
    int levels = 0;
    while (levels < std::max(1, wanted)) {
        const glm::ivec2 s = bloomMipSize(size, firstDivisor, levels);
        if (std::min(s.x, s.y) < 4 && levels > 0) {
            break;
        }
        ++levels;
    }
    return levels;
}

int bloomLevelScale(int firstDivisor, int level) noexcept {
    return firstDivisor << level;
}

glm::ivec2 bloomLevelFrame(glm::ivec2 size, int firstDivisor, int level) noexcept {
    const int scale = bloomLevelScale(firstDivisor, level);
    return {std::max(1, (size.x + scale - 1) / scale), std::max(1, (size.y + scale - 1) / scale)};
}

std::array<float, kBloomBlurReach + 1> bloomBlurWeights() noexcept {
    std::array<float, kBloomBlurReach + 1> w{};
    double sum = 0.0;
    for (int i = 0; i <= kBloomBlurReach; ++i) {
        const double g = std::exp(-double(i * i) / (2.0 * kBloomBlurSigma * kBloomBlurSigma));
        w[std::size_t(i)] = float(g);
        sum += (i == 0 ? 1.0 : 2.0) * g;
    }
    for (float& v : w) {
        v = float(double(v) / sum);
    }
    return w;
}

std::span<const float> bloomPrefilterWeights(int firstDivisor) noexcept {
    static constexpr std::array<float, 4> kHalf{1.0f / 8, 3.0f / 8, 3.0f / 8, 1.0f / 8};
    static constexpr std::array<float, 10> kQuarter{1.0f / 64,  3.0f / 64,  6.0f / 64, 10.0f / 64,
                                                    12.0f / 64, 12.0f / 64, 10.0f / 64, 6.0f / 64,
                                                    3.0f / 64,  1.0f / 64};
    if (firstDivisor == 4) {
        return kQuarter;
    }
    return kHalf;
}

float bloomLevelWeight(float radius, int level, int levels) noexcept {
    if (level >= levels) {
        return 0.0f;
    }
    const float reaching = std::pow(radius, float(level));
    return level == levels - 1 ? reaching : reaching * (1.0f - radius);
}

} // namespace photopic
