#pragma once
// A generic Dear ImGui editor over the settings reflection (core/settings/Reflect.h): one widget per field of
// `Settings::visit`, so a new setting shows up in photopic-view without touching the viewer.

#include "core/Settings.h"

#include <string>
#include <vector>

namespace photopic::viewer {

/// Draws every field of `settings` as a widget inside the current ImGui window, one tree node per object.
/// Edits land in `settings` directly; returns true when any field changed this frame.
bool editSettings(Settings& settings);

/// The issues (ranges and rules between fields) an edited copy has, as "path: message" lines; empty when the
/// pipeline can take it. Reuses the JSON reader's checks so the editor and `--settings` files agree.
std::vector<std::string> settingsProblems(const Settings& settings);

} // namespace photopic::viewer
