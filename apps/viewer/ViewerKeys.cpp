#include "ViewerKeys.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace photopic::viewer {
namespace {

constexpr std::array<KeyBinding, 19> kKeys{{
    {"1", "ambient occlusion (ssao.enabled)"},
    {"2", "contact shadows (contactShadows.enabled)"},
    {"3", "volumetric light (volumetricLight.enabled)"},
    {"4", "depth of field (dof.enabled)"},
    {"5", "motion blur (motionBlur.enabled)"},
    {"6", "colour grading (colorGrading.enabled)"},
    {"7", "lens flare (lensFlare.enabled)"},
    {"8", "FXAA (aa.mode fxaa / none)"},
    {"9", "SMAA (aa.mode smaa / none)"},
    {"0", "next tone curve (tonemapping.mode)"},
    {"B", "bloom (bloom.enabled)"},
    {"R", "screen-space reflections (ssr.enabled)"},
    {"O", "outlines (outline.enabled)"},
    {"V", "vignette and chromatic aberration (vignette.enabled)"},
    {"T", "TAA (aa.mode taa / none)"},
    {"X", "auto exposure (autoExposure.enabled)"},
    {"F12", "save the settings JSON (the --save file, named in the status line)"},
    {"drag", "orbit a 3D scene's camera about its target (left button)"},
    {"wheel", "zoom a 3D scene's camera"},
}};

std::string toggle(bool& enabled, std::string_view name, std::string_view key) {
    enabled = !enabled;
    return fmt::format("{} {} ({})", name, enabled ? "on" : "off", key);
}

/// Switches between `mode` and none; the older fxaa/taa switches are cleared so aa.mode alone decides.
std::string toggleAntiAliasing(Settings& s, AntiAliasing mode, std::string_view name, std::string_view key) {
    const bool on = s.antiAliasing() != mode;
    s.aa.mode = on ? mode : AntiAliasing::None;
    s.fxaa.enabled = false;
    s.taa.enabled = false;
    return fmt::format("{} {} ({})", name, on ? "on" : "off", key);
}

std::string nextToneCurve(Settings& s) {
    const auto names = toneMapperNames();
    const std::size_t next = (static_cast<std::size_t>(s.tonemapping.mode) + 1) % names.size();
    s.tonemapping.mode = static_cast<ToneMapper>(next);
    return fmt::format("tone curve {} (0)", names[next]);
}

/// A finite number of at most 1e6 (pixels, wheel steps), or nullopt.
std::optional<double> number(std::string_view text) {
    double v = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(v) || std::abs(v) > 1e6) {
        return std::nullopt;
    }
    return v;
}

} // namespace

ScriptedEvent parseScriptedEvent(std::string_view text) {
    const auto bad = [&] {
        return std::invalid_argument(fmt::format(
            "--press: '{}' is not a key (1-9, 0, B, R, O, V, T, X, F12), drag:DX:DY or wheel:STEPS", text));
    };
    ScriptedEvent e;
    if (text.starts_with("drag:")) {
        const std::string_view rest = text.substr(5);
        const std::size_t colon = rest.find(':');
        const auto dx = number(rest.substr(0, colon));
        const auto dy = colon == std::string_view::npos ? std::nullopt : number(rest.substr(colon + 1));
        if (!dx || !dy) {
            throw bad();
        }
        e.kind = ScriptedEvent::Kind::Drag;
        e.x = *dx;
        e.y = *dy;
        return e;
    }
    if (text.starts_with("wheel:")) {
        const auto steps = number(text.substr(6));
        if (!steps) {
            throw bad();
        }
        e.kind = ScriptedEvent::Kind::Wheel;
        e.x = *steps;
        return e;
    }
    std::string key;
    for (const char c : text) {
        key += char(std::toupper(static_cast<unsigned char>(c)));
    }
    Settings probe;
    if (key != "F12" && !applyToggleKey(key, probe)) {
        throw bad();
    }
    e.key = key;
    return e;
}

std::span<const KeyBinding> viewerKeys() {
    return kKeys;
}

std::optional<std::string> applyToggleKey(std::string_view key, Settings& s) {
    if (key.size() != 1) {
        return std::nullopt;
    }
    const char k = char(std::toupper(static_cast<unsigned char>(key[0])));
    const std::string name(1, k);
    switch (k) {
    case '1':
        return toggle(s.gtao.enabled, "ambient occlusion", name);
    case '2':
        return toggle(s.contactShadows.enabled, "contact shadows", name);
    case '3':
        return toggle(s.volumetricLight.enabled, "volumetric light", name);
    case '4':
        return toggle(s.dof.enabled, "depth of field", name);
    case '5':
        return toggle(s.motionBlur.enabled, "motion blur", name);
    case '6':
        return toggle(s.colorGrading.enabled, "colour grading", name);
    case '7':
        return toggle(s.lensFlare.enabled, "lens flare", name);
    case '8':
        return toggleAntiAliasing(s, AntiAliasing::Fxaa, "FXAA", name);
    case '9':
        return toggleAntiAliasing(s, AntiAliasing::Smaa, "SMAA", name);
    case '0':
        return nextToneCurve(s);
    case 'B':
        return toggle(s.bloom.enabled, "bloom", name);
    case 'R':
        return toggle(s.ssr.enabled, "reflections", name);
    case 'O':
        return toggle(s.outline.enabled, "outlines", name);
    case 'V':
        return toggle(s.vignette.enabled, "vignette", name);
    case 'T':
        return toggleAntiAliasing(s, AntiAliasing::Taa, "TAA", name);
    case 'X':
        return toggle(s.autoExposure.enabled, "auto exposure", name);
    default:
        return std::nullopt;
    }
}

} // namespace photopic::viewer
