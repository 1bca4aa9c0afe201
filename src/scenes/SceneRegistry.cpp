#include "scenes/Scene.h"

#include "scenes/canvas/CanvasScene.h"
#include "scenes/gradient/GradientScene.h"
#include "scenes/tabletop/TabletopScene.h"

#include <stdexcept>

namespace photopic {

const std::vector<SceneInfo>& builtInScenes() {
    // Scenes are listed here explicitly: self-registration from static objects is dropped by static linking.
    static const std::vector<SceneInfo> kScenes = {
        {"gradient", "a drifting HDR gradient with a bright sun disc (smoke test of the scene runner)",
         makeGradientScene},
        {"canvas", "seed 003: a painted canvas lit by the device's tilt, glitter sparkle, tile-based shading",
         makeCanvasScene},
        {"tabletop",
         "a battle map: a player token walks from a torch-lit building into the sun and back (seed 000)",
         makeTabletopScene},
    };
    return kScenes;
}

std::unique_ptr<Scene> makeScene(std::string_view name) {
    std::string known;
    for (const auto& scene : builtInScenes()) {
        if (scene.name == name) {
            return scene.make();
        }
        known += (known.empty() ? "" : ", ") + scene.name;
    }
    throw std::invalid_argument("unknown scene '" + std::string(name) + "' (known scenes: " + known + ")");
}

} // namespace photopic
