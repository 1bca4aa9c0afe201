#pragma once
// Colour grading in HDR, after the composite and before the single tone mapping (docs/architecture.md). The
// common keys `enabled`, `contrast`, `saturation`, `temperature` are fields here with their neutral values as
// defaults. The white-balance matrix is computed on the CPU (core/ColorGrading.h).

#include "core/settings/Reflect.h"

#include <glm/vec3.hpp>

namespace photopic {

struct ColorGradingSettings {
    bool enabled = false;
    float temperature = 0.0f;
    float tint = 0.0f;
    float contrast = 1.0f;
    float saturation = 1.0f;
    glm::vec3 lift{0.0f};
    glm::vec3 gamma{1.0f};
    glm::vec3 gain{1.0f};

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns colour grading on");
        v.field("temperature", temperature, Range{-1, 1},
                "white balance, > 0 warmer (shifts the assumed white)");
        v.field("tint", tint, Range{-1, 1}, "white balance, > 0 towards magenta, < 0 towards green");
        v.field("contrast", contrast, Range{0, 3}, "slope in log2 space around middle grey 0.18");
        v.field("saturation", saturation, Range{0, 3}, "0 = grey (Rec.709 luma), 1 = unchanged");
        v.field("lift", lift, Range{-1, 1}, "per channel: offset added (ASC CDL offset)");
        v.field("gamma", gamma, Range{0.1, 10}, "per channel: c^(1/gamma) (ASC CDL power = 1/gamma)");
        v.field("gain", gain, Range{0, 10}, "per channel: multiplier (ASC CDL slope)");
    }
};

} // namespace photopic
