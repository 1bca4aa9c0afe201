#pragma once
// Sub-pixel jitter that Pipeline::beginFrame hands a 3D host for its projection.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class JitterMode {
    Auto, ///< jitter while a temporal pass (anti-aliasing, accumulation) is on; zero otherwise
    On,   ///< always jitter (hosts that accumulate frames themselves)
    Off,  ///< never jitter
};

inline std::span<const std::string_view> jitterModeNames() {
    static constexpr std::array<std::string_view, 3> kNames{"auto", "on", "off"};
    return kNames;
}

struct TemporalSettings {
    JitterMode jitter = JitterMode::Auto;
    int jitterCycle = 8;

    template <class V>
    void visit(V& v) {
        v.field("jitter", jitter, jitterModeNames(),
                "sub-pixel camera jitter: auto (when a temporal effect needs it), on, off");
        v.field("jitterCycle", jitterCycle, Range{1, 1024},
                "frames: length of the Halton(2, 3) jitter sequence");
    }
};

} // namespace photopic
