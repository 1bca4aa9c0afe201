#include "core/Settings.h"

#include <array>

namespace photopic {

std::span<const std::string_view> presetNames() {
    static constexpr std::array<std::string_view, 3> kNames{"stills", "realtime", "neutral"};
    return kNames;
}

Settings Settings::stills() {
    Settings s;
    s.bloom = BloomSettings::stills();
    // AgX (base): of the curves that roll off to white it keeps the most stops between code 10 and 250, crushes
    // and clips the least and turns hues the least on the measured images and colours (docs/looks.md).
    s.tonemapping.mode = ToneMapper::Agx;
    s.tonemapping.agxLook = AgxLook::Base;
    return s;
}

Settings Settings::realtime() {
    return {};
}

Settings Settings::neutral() {
    Settings s;
    s.bloom.enabled = false;
    s.lensFlare.enabled = false;
    s.vignette.enabled = false;
    s.grain.enabled = false;
    s.dazzle.enabled = false;
    s.colorGrading.enabled = false;
    return s;
}

std::optional<Settings> Settings::preset(std::string_view name) {
    if (name == "stills") {
        return stills();
    }
    if (name == "realtime") {
        return realtime();
    }
    if (name == "neutral") {
        return neutral();
    }
    return std::nullopt;
}

void Settings::applyLook(const Settings& look) {
    tonemapping.mode = look.tonemapping.mode;
    tonemapping.agxLook = look.tonemapping.agxLook;
    bloom = look.bloom;
    lensFlare = look.lensFlare;
    vignette = look.vignette;
    grain = look.grain;
    dazzle = look.dazzle;
    colorGrading = look.colorGrading;
}

} // namespace photopic
