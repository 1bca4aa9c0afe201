#pragma once
// Colour grading in HDR, after the composite and before the single tone mapping (docs/architecture.md). The
// common keys `enabled`, `contrast`, `saturation`, `temperature` are fields here with their neutral values as
// defaults. The white-balance matrix is computed on the CPU (core/ColorGrading.h).

#include "core/settings/Reflect.h"

#include <glm/vec3.hpp>

namespace photopic {

struct ColorGradingSettings {
    bool enabled = false;     ///< default off
    float temperature = 0.0f; ///< [-1, 1], default 0: white balance, > 0 warmer (shifts the assumed white)
    float tint = 0.0f;        ///< [-1, 1], default 0: white balance, > 0 towards magenta, < 0 towards green
    float contrast = 1.0f;    ///< [0, 3], default 1: slope in log2 space around middle grey 0.18
    float saturation = 1.0f;  ///< [0, 3], default 1: 0 = grey (Rec.709 luma), 1 = unchanged
    glm::vec3 lift{0.0f};     ///< per channel, [-1, 1], default 0: offset added (ASC CDL offset)
    glm::vec3 gamma{1.0f};    ///< per channel, [0.1, 10], default 1: c^(1/gamma) (ASC CDL power = 1/gamma)
    glm::vec3 gain{1.0f};     ///< per channel, [0, 10], default 1: multiplier (ASC CDL slope)

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("temperature", temperature, Range{-1, 1});
        v.field("tint", tint, Range{-1, 1});
        v.field("contrast", contrast, Range{0, 3});
        v.field("saturation", saturation, Range{0, 3});
        v.field("lift", lift, Range{-1, 1});
        v.field("gamma", gamma, Range{0.1, 10});
        v.field("gain", gain, Range{0, 10});
    }
};

} // namespace photopic
