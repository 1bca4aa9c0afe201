#pragma once
// The quality tiers (high tiers run the multi-pass bloom, the legacy tier only a cheap glow):
// what each tier runs and at what size. One table, tested in tests/core, read by the pipeline.

#include "core/settings/QualitySettings.h"

namespace photopic {

struct QualityTier {
    bool hdrPath = true;       ///< false: the LDR (RGBA8) path, as on a GPU without RGBA16F targets
    bool bloom = true;         ///< the bloom chain runs (when bloom.enabled)
    int bloomFirstDivisor = 2; ///< level 0 of the chain is the image / this (2 or 4)
    int bloomMips = 6;         ///< levels when bloom.mipCount is 0
    bool glow = false;        ///< LDR path: a single cheap glow in the uber pass instead (when bloom.enabled)
    bool lensFlare = true;    ///< the lens flare runs (when lensFlare.enabled)
    int lensFlareDivisor = 4; ///< the flare buffer is the image / this
    bool chromaticAberration = true;
    bool fxaa = true;
    bool grain = true;
};

[[nodiscard]] QualityTier qualityTier(Quality quality) noexcept;
[[nodiscard]] std::string_view qualityName(Quality quality) noexcept;

} // namespace photopic
