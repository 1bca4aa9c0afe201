#include "core/ColorGrading.h"

#include "core/Color.h"

#include <glm/glm.hpp>

#include <cmath>

namespace photopic {

namespace {

// glm matrices are column-major: each inner line below is a column.
const glm::mat3 kRec709ToXyz{0.4124564f, 0.2126729f, 0.0193339f, //
                             0.3575761f, 0.7151522f, 0.1191920f, //
                             0.1804375f, 0.0721750f, 0.9503041f};
const glm::mat3 kBradford{0.8951f,  -0.7502f, 0.0389f,  //
                          0.2664f,  1.7135f,  -0.0685f, //
                          -0.1614f, 0.0367f,  1.0296f};

glm::vec3 xyToXyz(float x, float y) {
    return {x / y, 1.0f, (1.0f - x - y) / y};
}

} // namespace

glm::mat3 whiteBalanceMatrix(float temperature, float tint) noexcept {
    if (temperature == 0.0f && tint == 0.0f) {
        return glm::mat3(1.0f);
    }
    // Assumed scene white: D65's x moved along the daylight direction (further towards blue than towards
    // orange, as the locus is), y from the CIE daylight locus polynomial plus a tint offset (Unity's form).
    const float t = temperature * 1.5f; // full range spans roughly 4000 K .. 15000 K
    const float x = 0.31271f - t * (t < 0.0f ? 0.1f : 0.05f);
    const float y = 2.87f * x - 3.0f * x * x - 0.27509507f + tint * 0.05f;
    const glm::vec3 source = kBradford * xyToXyz(x, y);
    const glm::vec3 target = kBradford * xyToXyz(0.31271f, 0.32902f);
    const glm::mat3 scale(glm::vec3(target.x / source.x, 0, 0), glm::vec3(0, target.y / source.y, 0),
                          glm::vec3(0, 0, target.z / source.z));
    return glm::inverse(kRec709ToXyz) * glm::inverse(kBradford) * scale * kBradford * kRec709ToXyz;
}

glm::vec3 gradeColor(glm::vec3 c, const ColorGradingSettings& s) noexcept {
    c = glm::max(whiteBalanceMatrix(s.temperature, s.tint) * c, glm::vec3(0.0f));
    // Contrast as a slope in log2 space around middle grey: grey stays, stops spread or gather.
    for (int i = 0; i < 3; ++i) {
        c[i] = c[i] > 0.0f ? kGradingMiddleGrey * std::pow(c[i] / kGradingMiddleGrey, s.contrast) : 0.0f;
    }
    const float y = luma709(c);
    c = glm::max(glm::vec3(y) + (c - glm::vec3(y)) * s.saturation, glm::vec3(0.0f));
    c = glm::max(c * s.gain + s.lift, glm::vec3(0.0f));
    for (int i = 0; i < 3; ++i) {
        c[i] = std::pow(c[i], 1.0f / s.gamma[i]);
    }
    return c;
}

} // namespace photopic
