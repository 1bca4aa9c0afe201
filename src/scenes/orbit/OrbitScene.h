#pragma once
// `photopic scene orbit`: a spacecraft between an Earth-like and a Mars-like planet, rendered HDR with a
// metallic-roughness material model (OrbitRenderer), lit by a sun the planet eclipses, amb and hemi fills
// and an image-based light, over a procedural starfield. A scripted camera orbits the ship while the ship
// passes into the planet's shadow and out into the sun again (OrbitWorld.h), so exposure adapts in 3D.
// `--set orbit.model=FILE` (the CLI's --model) draws a glTF model in the ship's place.

#include "scenes/InteractiveCamera.h"
#include "scenes/Scene.h"
#include "scenes/orbit/OrbitRenderer.h"
#include "scenes/orbit/OrbitShadowMap.h"

#include <array>
#include <memory>
#include <string>
#include <string_view>

namespace photopic {

/// orbit.post: the post look the scene asks for.
enum class OrbitPost {
    Full, ///< bloom, the planets' atmosphere and limb glow (the scene's look)
    Raw,  ///< calibration: no bloom, lens flare, glow or atmosphere; manual exposure `exp`
};
inline std::span<const std::string_view> orbitPostNames() {
    static constexpr std::array<std::string_view, 2> kNames = {"full", "raw"};
    return kNames;
}

struct OrbitSceneSettings {
    /// full (default) or raw: raw turns bloom, lens flare, the limb glow and the atmosphere off and exposes
    /// manually at `exp`, so that what the lights do can be measured (--set bloom.enabled=true still wins)
    OrbitPost post = OrbitPost::Full;
    /// [1/64, 64], default 1: exposure multiplier. raw: the manual exposure (tonemapping.exposure =
    /// log2 exp); full: added to auto exposure's compensation (log2 exp EV)
    float exp = 1.0f;
    float sun = 3.0f;  ///< scene-linear illuminance, [0, 1000], default 3: the sun at normal incidence
    float amb = 0.02f; ///< irradiance, [0, 100], default 0.02: uniform fill (multiplies diffuse / pi)
    /// irradiance, [0, 100], default 0.05: hemisphere fill, bluish earthshine from the planet's side
    float hemi = 0.05f;
    /// [0, 100], default 0.25: image-based-light intensity; every material's stored baseline times this
    float ibl = 0.25f;
    float atmosphere = 1.0f; ///< [0, 4], default 1: the planets' rim on their discs (1: its bounded maximum)
    float glow = 1.0f;       ///< [0, 4], default 1: the planets' limb glow outside their discs
    float nebula = 1.0f;     ///< [0, 100], default 1: the background nebula's brightness (not the IBL)
    float start = 0.0f;      ///< s, [0, 1000], default 0: script time of frame 0 (eclipse ~4..8 s)
    float speed = 1.0f;      ///< [0, 100], default 1: script seconds per second (0: a still frame)
    std::string model;       ///< glTF 2.0 file (.gltf or .glb) drawn in place of the built-in ship
    /// equirectangular HDR image (.exr, .hdr) for the image-based light; empty (default): the data
    /// folder's blender_sunrise.exr. Missing or unreadable: a procedural sky, with one warning
    std::string env;
    /// texels, a power of two in [16, 2048], default 128: the environment cube's face (the image-based
    /// light's detail and build time, about 0.5 s at 128 on a 2-core software renderer)
    int iblSize = 128;
    /// the ship's sun shadow map (OrbitShadowMap.h): on by default, 2048 texels, biases and PCF in texels
    orbit::ShadowSettings shadow;
    /// default false: the scripted camera; true: a still camera at `eye` looking at the ship (the viewer's
    /// drag and wheel set both)
    bool fixedCamera = false;
    glm::vec3 eye{0.0f, 8.0f, 30.0f}; ///< m, each in [-1000, 1000], not 0: the still camera's position

    template <class V>
    void visit(V& v) {
        v.field("post", post, orbitPostNames(),
                "full: the scene's look; raw: calibration (no bloom, lens flare, glow or atmosphere; manual "
                "exposure exp)");
        v.field("exp", exp, Range{1.0 / 64.0, 64},
                "exposure multiplier: raw, the manual exposure; full, log2(exp) EV of compensation");
        v.field("sun", sun, Range{0, 1000}, "scene-linear illuminance of the sun at normal incidence");
        v.field("amb", amb, Range{0, 100}, "irradiance of the uniform fill (diffuse / pi)");
        v.field("hemi", hemi, Range{0, 100},
                "irradiance of the hemisphere fill: earthshine from the planet's side");
        v.field("ibl", ibl, Range{0, 100},
                "image-based-light intensity (every material's stored baseline times it)");
        v.field("atmosphere", atmosphere, Range{0, 4},
                "the planets' rim on their discs (1: its bounded maximum)");
        v.field("glow", glow, Range{0, 4},
                "the planets' limb glow outside their discs (1: its bounded maximum)");
        v.field("nebula", nebula, Range{0, 100}, "the background nebula's brightness (never the IBL)");
        v.field("start", start, Range{0, 1000}, "s: script time of frame 0 (the eclipse is ~4.3 to 8.4 s)");
        v.field("speed", speed, Range{0, 100}, "script seconds per second (0: a still frame)");
        v.field("model", model, "glTF 2.0 file (.gltf, .glb) drawn in place of the built-in ship (--model)");
        v.field(
            "env", env,
            "equirectangular HDR image for the image-based light (--env); empty: data/blender_sunrise.exr");
        v.field("iblSize", iblSize, Range{16, 2048}, "texels, a power of two: the environment cube's face");
        v.require((iblSize & (iblSize - 1)) == 0, "iblSize", "must be a power of two");
        v.object("shadow", shadow);
        v.field("fixedCamera", fixedCamera,
                "true: a still camera at eye looking at the ship; false: the script's");
        v.field("eye", eye, Range{-1000, 1000}, "m: the still camera's position");
        v.require(glm::length(eye) > 0.0f, "eye", "must not be the ship's centre");
    }
};

/// Its camera follows the script; as an InteractiveCamera (photopic-view's drag and wheel) the first move
/// holds the script's current eye as a still camera (fixedCamera, eye) and then orbits the ship from there.
class OrbitScene final : public Scene, private InteractiveCamera {
public:
    /// Needs a current GL 4.5 context (compiles the scene's shaders).
    OrbitScene();

    [[nodiscard]] std::string_view name() const override { return "orbit"; }
    /// Auto exposure, PBR Neutral tone mapping, bloom; post=raw: manual exposure, no bloom or flare.
    [[nodiscard]] Settings defaultSettings() const override;
    std::vector<SettingsIssue> applyOverride(std::string_view assignment) override;
    [[nodiscard]] std::string settingsJson() const override;
    /// Loads the model and the environment when they changed; throws SceneInputError naming the file and
    /// the problem for a model that cannot be drawn.
    void resize(Extent extent) override;
    /// script_s (script time), sun_visibility (the planet's occlusion of the sun at the ship, 0..1).
    [[nodiscard]] std::vector<std::string> telemetryColumns() const override;
    FrameInputs render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) override;
    [[nodiscard]] InteractiveCamera* interactiveCamera() override { return this; }

    [[nodiscard]] const OrbitSceneSettings& settings() const { return mSettings; }
    [[nodiscard]] const orbit::OrbitRenderer& renderer() const { return mRenderer; }
    /// Script time of frame `time` under the settings.
    [[nodiscard]] double scriptTime(const FrameTime& time) const;

private:
    void loadModel();
    void loadEnvironment();
    [[nodiscard]] orbit::OrbitLights lightsAt(double seconds) const;
    /// The eye the camera has now: the still one, or the script's at the last rendered frame.
    [[nodiscard]] OrbitView currentView() const override;
    void holdView(const OrbitView& view) override;

    OrbitSceneSettings mSettings;
    orbit::OrbitRenderer mRenderer;
    Camera mCamera;
    Extent mExtent;
    std::string mLoadedModel = "\x01"; ///< the model setting the renderer holds (never a real path at first)
    std::string mLoadedEnv = "\x01";
    int mLoadedIblSize = 0;
    float mShipRadius = 1.0f;
    double mLastScriptTime = 0.0;
};

std::unique_ptr<Scene> makeOrbitScene();

} // namespace photopic
