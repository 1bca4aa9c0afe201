#pragma once
// photopic-view: a built-in scene through the pipeline in a GLFW window, with Dear ImGui panels that tune
// every setting live, the Dynamic Exposure controls (adaptation bounds and timing) and a read-only
// debug readout of the selected subject.

#include "ViewerKeys.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic::viewer {

enum ExitCode : int { kOk = 0, kFailure = 1, kBadInput = 2 };

/// Bad command-line input (unknown scene, bad size, bad --set): exit 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// No display, or no GL 4.5 core context on it: exit 1.
class DisplayError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ViewerOptions {
    std::string scene = "tabletop";
    /// Image files (EXR, Radiance HDR, PNG) to view instead of a scene: one is a still, several play as a
    /// sequence in the order given.
    std::vector<std::filesystem::path> files;
    /// How EXR files are read, as `photopic image` reads them: --aovs, --layer, --aov, --camera (one camera
    /// or a track by frame number) and --lens.
    std::string aovPreset;
    std::string layer;
    std::vector<std::string> aovs;
    std::filesystem::path camera;
    std::string lens;
    bool sizeGiven = false; ///< --size was named; otherwise a file sets the window's size
    std::filesystem::path settingsFile;
    /// --preset: the look over the scene's defaults; empty: stills for files (as `photopic image`), the
    /// scene's own look for a scene.
    std::string preset;
    std::vector<std::string> overrides; ///< "key=value"; "SCENE.key=value" goes to the scene
    int width = 1280;
    int height = 720;
    int frames = 0;                   ///< > 0: run that many frames, then exit
    std::optional<float> fixedDt;     ///< seconds per frame; unset: the measured frame delta, clamped
    std::filesystem::path screenshot; ///< with frames: the last window frame as PNG
    std::filesystem::path save = "photopic_view.json";
    bool saveGiven = false;           ///< --save was named: with --frames, save on exit
    std::vector<ScriptedEvent> press; ///< --press: one event per frame from frame 1
};

/// Opens the window and runs until it is closed (or `frames` have run). Throws InputError, DisplayError,
/// SettingsError.
int run(const ViewerOptions& options);

} // namespace photopic::viewer
