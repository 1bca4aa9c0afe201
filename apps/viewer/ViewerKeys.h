#pragma once
// photopic-view's keys: one key switches one effect of the live settings (a pure function of the settings,
// tested without a window), F12 saves the settings, and the mouse steers a 3D scene's camera.

#include "core/Settings.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace photopic::viewer {

/// One bound key: its name as the help and --press write it, and what it does.
struct KeyBinding {
    std::string_view key;
    std::string_view action;
};

/// Every key the viewer binds, in the order the help lists them (the toggles, then F12 and the mouse).
[[nodiscard]] std::span<const KeyBinding> viewerKeys();

/// Applies the toggle bound to `key` ("1".."9", "0", "B", "R", "O", "V", "T", "X"; case-insensitive) to
/// `settings` and returns what it did ("bloom off (B)"); nullopt, with `settings` untouched, for a key
/// bound to no toggle (F12 among them: saving is the viewer's, not a settings change).
std::optional<std::string> applyToggleKey(std::string_view key, Settings& settings);

/// One --press item: a key press, a drag of the left button or wheel steps, replayed one per frame
/// through the same paths as the keyboard and mouse (tests, recorded demos).
struct ScriptedEvent {
    enum class Kind { Key, Drag, Wheel };
    Kind kind = Kind::Key;
    std::string key; ///< Key: a viewerKeys() name ("B", "F12")
    double x = 0.0;  ///< Drag: pixels right; Wheel: steps away from the user
    double y = 0.0;  ///< Drag: pixels down
};

/// Parses "B", "f12", "drag:DX:DY" or "wheel:STEPS"; throws std::invalid_argument naming the item and what
/// is accepted.
ScriptedEvent parseScriptedEvent(std::string_view text);

/// Radians of orbit per pixel dragged, and the zoom factor per wheel step (< 1: a step away from the user
/// zooms in).
inline constexpr float kOrbitRadiansPerPixel = 0.005f;
inline constexpr float kZoomPerWheelStep = 0.9f;

} // namespace photopic::viewer
