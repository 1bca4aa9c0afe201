#pragma once
// Quality tiers (from full quality to old hardware): how much of the frame order runs and at what resolution.
// The tier table is in core/Quality.h. Beside the tier, each costly effect has its own preset
// (`ssao.quality`, `contactShadows.quality`, ...), named alike and chosen per effect.

#include <array>
#include <cstddef>
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

/// One effect's preset: how many samples, steps or slices it spends per pixel. What each preset means is
/// the effect's own table (its settings' `quality` field says); high is every effect's default.
enum class EffectQuality { Low, Medium, High, Ultra };

inline std::span<const std::string_view> effectQualityNames() {
    static constexpr std::array<std::string_view, 4> kNames{"low", "medium", "high", "ultra"};
    return kNames;
}

/// The count an effect runs with: `count` where it is set (> 0), else its preset's from `counts` (low,
/// medium, high and ultra's). An effect's count key defaults to 0, the preset's.
[[nodiscard]] constexpr int countOrPreset(int count, EffectQuality quality,
                                          const std::array<int, 4>& counts) noexcept {
    return count > 0 ? count : counts[static_cast<std::size_t>(quality)];
}

} // namespace photopic
