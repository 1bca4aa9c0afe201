#include "scenes/Scene.h"

#include "core/settings/SettingsJson.h"

#include "scenes/SceneSettings.h"

#include "scenes/canvas/CanvasScene.h"
#include "scenes/gradient/GradientScene.h"
#include "scenes/orbit/OrbitScene.h"
#include "scenes/tabletop/TabletopScene.h"
#include "scenes/testbed/TestbedScene.h"

#include <stdexcept>

namespace photopic {

const std::vector<SceneInfo>& builtInScenes() {
    // Scenes are listed here explicitly: self-registration from static objects is dropped by static linking.
    static const std::vector<SceneInfo> kScenes = {
        {"gradient", "a drifting HDR gradient with a bright sun disc (smoke test of the scene runner)",
         makeGradientScene, describeSceneSettings<GradientSceneSettings>},
        {"canvas", "a painted canvas lit by the device's tilt, glitter sparkle, tile-based shading",
         makeCanvasScene, describeSceneSettings<CanvasSceneSettings>},
        {"tabletop", "a battle map: a player token walks from a torch-lit building into the sun and back",
         makeTabletopScene, describeSceneSettings<TabletopSceneSettings>},
        {"testbed",
         "an analytic 3D scene (spheres, boxes, poles, a wire fence, a checker wall, a metal strip, a "
         "spinning "
         "and a moving object; a pan, a dolly and a cut) with depth, normals, motion and the camera; --truth "
         "KIND writes its CPU ray-traced references",
         makeTestbedScene, describeSceneSettings<TestbedSceneSettings>},
        {"orbit",
         "a spacecraft in orbit (PBR, image-based light, procedural planets and stars): the camera circles "
         "the ship as it passes through the planet's shadow and back into the sun; --model FILE draws a "
         "glTF model instead",
         makeOrbitScene, describeSceneSettings<OrbitSceneSettings>},
    };
    return kScenes;
}

std::string builtInSceneNames() {
    std::string names;
    for (const SceneInfo& scene : builtInScenes()) {
        names += (names.empty() ? "" : ", ") + scene.name;
    }
    return names;
}

std::unique_ptr<Scene> makeScene(std::string_view name) {
    for (const auto& scene : builtInScenes()) {
        if (scene.name == name) {
            return scene.make();
        }
    }
    throw std::invalid_argument("unknown scene '" + std::string(name) +
                                "' (known scenes: " + builtInSceneNames() + ")");
}

SplitOverrides splitSceneOverrides(std::string_view sceneName, std::span<const std::string> overrides) {
    const std::string prefix = std::string(sceneName) + ".";
    SplitOverrides split;
    for (const std::string& o : overrides) {
        if (o.rfind(prefix, 0) == 0) {
            split.scene.push_back(o.substr(prefix.size()));
        } else {
            split.post.push_back(o);
        }
    }
    return split;
}

void applySceneOverrides(Scene& scene, std::span<const std::string> sceneOverrides) {
    std::vector<SettingsIssue> issues;
    for (const std::string& o : sceneOverrides) {
        auto found = scene.applyOverride(o);
        issues.insert(issues.end(), found.begin(), found.end());
    }
    if (!issues.empty()) {
        throw SettingsError("--set", std::move(issues));
    }
}

} // namespace photopic
