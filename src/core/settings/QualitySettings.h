#pragma once
// Quality tiers (from full quality to old hardware): how much of the frame order runs and at what resolution.
// The tier table is in core/Quality.h.

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class Quality {
    Ultra,  ///< every effect, bloom chain from half size with 7 levels
    High,   ///< every effect, 6 levels (default)
    Medium, ///< bloom from quarter size with 5 levels, lens flare at 1/8 size
    Low,    ///< bloom from quarter size with 4 levels, no lens flare, no chromatic aberration
    Legacy, ///< the LDR path (RGBA8): no bloom, no lens flare (too costly on old hardware)
};

inline std::span<const std::string_view> qualityNames() {
    static constexpr std::array<std::string_view, 5> kNames{"ultra", "high", "medium", "low", "legacy"};
    return kNames;
}

} // namespace photopic
