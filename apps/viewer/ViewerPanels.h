#pragma once
// photopic-view's Dear ImGui panels: Dynamic Exposure, the selected token's debug readout, the exposure
// telemetry, every setting, Save JSON and the keys.

#include "Viewer.h"

#include "core/Settings.h"
#include "pipeline/Pipeline.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace photopic::viewer {

/// The part of the frame the panels read and write; the Pipeline itself is only touched through setSettings.
struct UiState {
    Settings edited;                   ///< what the widgets show; applied when it has no problems
    std::vector<std::string> problems; ///< why `edited` is not applied yet
    std::string message;               ///< last Save / Reset result
    float dt = 0.0f;
    bool dragging = false; ///< the left button went down outside the panels and is still down
    double cursorX = 0.0;  ///< window coordinates of the cursor last frame, while dragging
    double cursorY = 0.0;
    std::size_t scripted = 0; ///< --press events used so far
};

/// Writes `settings` to `path`, the result in ui.message.
void saveSettings(const Settings& settings, const std::filesystem::path& path, UiState& ui);
/// Applies `ui.edited` to the pipeline when it has no problems (as an edit in the panels does).
void applyEdited(Pipeline& pipeline, UiState& ui);
/// Every panel, this frame.
void drawPanels(Pipeline& pipeline, const ViewerOptions& options, UiState& ui);

} // namespace photopic::viewer
