#pragma once
// Anti-aliasing: one mode for the frame (`aa`), with SSAA's level and filter (SSAA runs the host's sub-frames
// through passes/ssaa/'s accumulator, outside the frame order). Each method's own settings sit beside its pass: passes/taa/TaaSettings.h, passes/smaa/SmaaSettings.h,
// passes/fxaa/FxaaSettings.h. FXAA and SMAA work on the display-referred image after tone mapping; TAA
// resolves in the HDR domain before metering; SSAA renders several jittered sub-frames through the host and
// accumulates them in HDR.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class AntiAliasing {
    None,
    Fxaa,    ///< FXAA 3.11 on display-referred values
    Smaa,    ///< SMAA 1x on display-referred values
    Taa,     ///< temporal resolve with motion vectors (needs jitter from the host and motion or depth)
    Ssaa,    ///< jittered sub-frames accumulated in HDR (built-in scenes and two-stage hosts)
    TaaSmaa, ///< SMAA's edges, then TAA's temporal gather
};

inline std::span<const std::string_view> antiAliasingNames() {
    static constexpr std::array<std::string_view, 6> kNames{"none", "fxaa", "smaa",
                                                            "taa",  "ssaa", "taa+smaa"};
    return kNames;
}

enum class SsaaFilter {
    Box,            ///< every sub-frame alike
    BlackmanHarris, ///< sub-frames near the pixel centre count more
};

inline std::span<const std::string_view> ssaaFilterNames() {
    static constexpr std::array<std::string_view, 2> kNames{"box", "blackman-harris"};
    return kNames;
}

struct AntiAliasingSettings {
    AntiAliasing mode = AntiAliasing::None;
    int level = 2;
    SsaaFilter ssaaFilter = SsaaFilter::Box;

    template <class V>
    void visit(V& v) {
        v.field("mode", mode, antiAliasingNames(),
                "the anti-aliasing method. The older switches `fxaa.enabled` and `taa.enabled` still select "
                "FXAA and TAA when this is none");
        v.field("level", level, Range{1, 4}, "SSAA: 2^level sub-frames per frame");
        v.field("ssaaFilter", ssaaFilter, ssaaFilterNames(),
                "SSAA reconstruction: box weighs every sub-frame alike, blackman-harris weighs those near "
                "the pixel centre more");
    }
};

} // namespace photopic
