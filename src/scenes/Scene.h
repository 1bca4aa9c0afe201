#pragma once
// Built-in scenes: procedural, deterministic HDR content that hosts the library through its public API only,
// as any other host would. A scene renders frame N the same way every time, from the caller's FrameTime, into
// textures it owns, and returns them as the frame's FrameInputs: colour always; a 3D scene adds depth,
// normals, motion and its camera. The caller hands them to Pipeline::execute as they are.

#include "core/Settings.h"
#include "core/settings/SettingsDescriber.h"
#include "gl/Objects.h"
#include "pipeline/Pipeline.h"
#include "scenes/InteractiveCamera.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// A file a scene reads (named by its settings, e.g. --set canvas.motion=FILE) is missing or malformed.
/// what() names the file (and the line where there is one). Thrown from resize() or render(); the CLI
/// exits 2.
class SceneInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Scene {
public:
    virtual ~Scene() = default;

    [[nodiscard]] virtual std::string_view name() const = 0;

    /// Post settings the scene is meant to be seen with (e.g. the tabletop turns auto exposure on). The
    /// caller applies --settings and --set on top.
    [[nodiscard]] virtual Settings defaultSettings() const { return {}; }

    /// Applies one "key=value" to the scene's own settings (the CLI's `--set NAME.key=value` with NAME
    /// removed). Returns issues with JSON paths that start with the scene's name; nothing changes when there
    /// are issues.
    virtual std::vector<SettingsIssue> applyOverride(std::string_view assignment) = 0;
    /// The scene's settings as JSON (for logs and `photopic scene NAME --print-settings`).
    [[nodiscard]] virtual std::string settingsJson() const = 0;

    virtual void resize(Extent extent) = 0;

    /// Names of the scene's own telemetry columns (written after frame,time_s, before the pipeline's).
    [[nodiscard]] virtual std::vector<std::string> telemetryColumns() const = 0;

    /// Renders frame `time.frameIndex` into the scene's textures, prepares the pipeline for it (subjects; a
    /// 3D scene's beginFrame and lighting stage), writes one value per telemetry column into `telemetry`, and
    /// returns the frame's inputs for Pipeline::execute (textures and camera valid until the next call).
    virtual FrameInputs render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) = 0;

    /// The camera an interactive host steers (photopic-view: drag to orbit, wheel to zoom), or nullptr when
    /// the scene has none (2D scenes, scripted cameras). Valid for the scene's lifetime; a change shows from
    /// the next render().
    [[nodiscard]] virtual InteractiveCamera* interactiveCamera() { return nullptr; }
};

struct SceneInfo {
    std::string name;
    std::string description;
    std::function<std::unique_ptr<Scene>()> make;
    /// The scene's own settings for the settings reference (docs/settings.md), keys "NAME.key": usually
    /// describeSceneSettings<ItsSettingsStruct> (scenes/SceneSettings.h). A plain function, not a Scene
    /// method, so the reference is built without a GL context.
    std::vector<SettingDoc> (*describeSettings)(std::string_view sceneName) = nullptr;
};

/// Every built-in scene (scenes/SceneRegistry.cpp lists them).
const std::vector<SceneInfo>& builtInScenes();
/// "gradient, canvas, ...": the built-in scenes' names in builtInScenes()'s order, for help texts and errors.
std::string builtInSceneNames();
/// Makes the named scene; throws std::invalid_argument listing the known names.
std::unique_ptr<Scene> makeScene(std::string_view name);

/// `--set` assignments split by their root, each list in order: "NAME.key=value" goes to the scene named NAME
/// (with "NAME." removed), every other one to the post settings.
struct SplitOverrides {
    std::vector<std::string> scene;
    std::vector<std::string> post;
};
SplitOverrides splitSceneOverrides(std::string_view sceneName, std::span<const std::string> overrides);

/// Applies the scene's own assignments (as splitSceneOverrides returns them); throws SettingsError listing
/// every issue.
void applySceneOverrides(Scene& scene, std::span<const std::string> sceneOverrides);

} // namespace photopic
