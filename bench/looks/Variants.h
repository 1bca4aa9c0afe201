#pragma once
// The tone curves the library offers, as this measure names and runs them: every ToneMapper, and AgX once per
// look (the look changes the curve's hue handling, so each is a candidate of its own).

#include "core/ToneCurves.h"

#include <string>
#include <vector>

namespace looks {

struct Variant {
    std::string label; ///< "aces-fitted", "agx", "agx-punchy", ...: the tables' row name
    photopic::ToneMapper mapper;
    photopic::AgxLook look; ///< Base for every curve but AgX's looks
    std::string modeName;   ///< tonemapping.mode value
    std::string lookName;   ///< tonemapping.agxLook value
};

/// In enum order, AgX's looks after its base.
inline std::vector<Variant> allVariants() {
    using namespace photopic;
    std::vector<Variant> out;
    for (std::string_view name : toneMapperNames()) {
        const ToneMapper mapper = *parseToneMapper(name);
        if (mapper != ToneMapper::Agx) {
            out.push_back({std::string(name), mapper, AgxLook::Base, std::string(name), "base"});
            continue;
        }
        for (std::string_view lookName : agxLookNames()) {
            const AgxLook look = *parseAgxLook(lookName);
            std::string label(name);
            if (look != AgxLook::Base) {
                // append() rather than "-" + string: GCC 12 gives a false -Wrestrict on the latter.
                label.append("-").append(lookName);
            }
            out.push_back({label, mapper, look, std::string(name), std::string(lookName)});
        }
    }
    return out;
}

} // namespace looks
