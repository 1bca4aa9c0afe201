#pragma once
// `photopic scene NAME`: renders a built-in scene's frames through the pipeline, with per-frame telemetry;
// `--truth KIND`: the testbed's ray-traced references instead; `--list`: the scenes.

#include "Command.h"
#include "Commands.h"

#include <filesystem>
#include <memory>

namespace photopic {
class Scene;
} // namespace photopic

namespace photopic::cli {

class RunOutputs;

class SceneCommand final : public Command {
public:
    explicit SceneCommand(CLI::App& parent);
    int run() override;

private:
    void addSceneFileOptions();
    /// --list: each built-in scene and what it shows.
    static int list();
    /// The scene named, its file flags and its share of --set applied; the post settings from the rest.
    std::unique_ptr<Scene> makeNamedScene(Settings& settings) const;
    /// The scene's file flags (--canvas, --model, ...) as the --set overrides they stand for, then --set's.
    std::vector<std::string> sceneOverrides(const Scene& scene) const;
    /// `--truth KIND`: the testbed's ray-traced references for frames [start, start + frames).
    int renderTruth(Scene& scene, const std::filesystem::path& outDir, RunOutputs& outputs) const;
    /// The frames and telemetry.csv, streamed as `photopic image`'s are.
    void stream(Scene& scene, const Settings& settings, const std::filesystem::path& outDir,
                RunOutputs& outputs) const;

    SceneOptions mOptions;
    bool mList = false;
};

} // namespace photopic::cli
