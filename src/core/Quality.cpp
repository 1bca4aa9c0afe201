#include "core/Quality.h"

namespace photopic {

QualityTier qualityTier(Quality quality) noexcept {
    QualityTier t;
    switch (quality) {
    case Quality::Ultra:
        t.bloomMips = 7;
        break;
    case Quality::High:
        break;
    case Quality::Medium:
        // A quarter-size start costs a quarter of the chain's traffic; the widest glow barely changes.
        t.bloomFirstDivisor = 4;
        t.bloomMips = 5;
        t.lensFlareDivisor = 8;
        break;
    case Quality::Low:
        t.bloomFirstDivisor = 4;
        t.bloomMips = 4;
        t.lensFlare = false;
        t.chromaticAberration = false;
        break;
    case Quality::Legacy:
        t.hdrPath = false;
        t.bloom = false;
        t.glow = true; // highlights still glow on the cheapest tier, without the blur chain
        t.bloomMips = 0;
        t.lensFlare = false;
        t.chromaticAberration = false;
        t.grain = false;
        break;
    }
    return t;
}

std::string_view qualityName(Quality quality) noexcept {
    return qualityNames()[static_cast<std::size_t>(quality)];
}

} // namespace photopic
