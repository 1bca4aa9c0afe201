#include "scenes/canvas/CanvasScene.h"

#include "core/Motion.h"
#include "io/ImageIO.h"
#include "scenes/SceneSettings.h"

#include <optional>
#include <tuple>

namespace photopic {

namespace {

class CanvasScene final : public Scene {
public:
    [[nodiscard]] std::string_view name() const override { return "canvas"; }

    [[nodiscard]] Settings defaultSettings() const override {
        Settings s;
        // The canvas wants ACES's look. aces-fitted (Hill's fit) keeps ACES's AP1 matrices, so the glitter's
        // and the highlights' HDR peaks desaturate towards white as the RRT+ODT does, at a few ALU per pixel;
        // the Narkowicz fit is per channel and keeps them saturated, the full CTL transform costs far more.
        // Bloom makes the highlights read as physically bright: only what is above 1.0 (the highlights and
        // the sparkles) blooms, added on top; the quality tier decides the chain (ultra/high multi-pass,
        // legacy none).
        s.tonemapping.mode = ToneMapper::AcesFitted;
        s.tonemapping.exposure = 0.5f; // the lit canvas sits around 0.5 linear; +0.5 EV puts it mid-display
        s.bloom.enabled = true;
        s.bloom.mode = BloomMode::Threshold;
        s.bloom.threshold = 1.0f;
        s.bloom.intensity = 0.6f;
        return s;
    }

    std::vector<SettingsIssue> applyOverride(std::string_view assignment) override {
        return applySceneOverride(mSettings, name(), assignment);
    }
    [[nodiscard]] std::string settingsJson() const override { return sceneSettingsJson(mSettings); }

    void resize(Extent extent) override {
        mExtent = extent;
        prepare();
    }

    [[nodiscard]] std::vector<std::string> telemetryColumns() const override {
        return {"pitch", "roll", "yaw", "light_x", "light_y", "light_z", "tiles_shaded", "tiles_total"};
    }

    FrameInputs render(const FrameTime& time, Pipeline&, std::vector<double>& telemetry) override {
        prepare();
        // Time is frameIndex * dt, never a clock: frame N is identical on every run.
        const double t = double(time.frameIndex) * double(time.dt);
        const Attitude a = mMotion ? mMotion->at(t)
                                   : ScriptedTilt{.period = mSettings.sweepPeriod,
                                                  .rollAmplitude = mSettings.sweepRoll,
                                                  .pitchAmplitude = mSettings.sweepPitch}
                                         .at(t);
        const glm::vec3 seedLight = seedLightVector(a.pitch, a.roll);
        const CanvasLighting lighting{.light = canvasLightDirection(a.pitch, a.roll),
                                      .lightColor = glm::vec3(mSettings.lightIntensity),
                                      .ambient = mSettings.ambient,
                                      .specular = mSettings.specular,
                                      .sparkleExposure = mSettings.sparkleExposure,
                                      .viewDistance = mSettings.viewDistance};
        const Texture& out = mRenderer->execute(lighting, mSettings.shading);
        telemetry = {a.pitch,
                     a.roll,
                     a.yaw,
                     double(seedLight.x),
                     double(seedLight.y),
                     double(seedLight.z),
                     double(mRenderer->tilesShaded(mSettings.shading)),
                     double(mRenderer->grid().count())};
        return {.color = &out};
    }

private:
    /// Builds (or rebuilds, when a setting it depends on changed) the canvas and loads the motion file. Bad
    /// files become SceneInputError naming them.
    void prepare() {
        if (!mRenderer) {
            mRenderer.emplace();
        }
        const auto canvasKey =
            std::make_tuple(mExtent.width, mExtent.height, mSettings.color, mSettings.material,
                            mSettings.tileSize, mSettings.occupancy, mSettings.seed);
        try {
            if (mMotionPath != mSettings.motion || (!mMotion && !mSettings.motion.empty())) {
                mMotion.reset();
                if (!mSettings.motion.empty()) {
                    mMotion = loadMotionCsv(mSettings.motion);
                }
                mMotionPath = mSettings.motion;
            }
            if (canvasKey != mCanvasKey) {
                CanvasImages images = makeProceduralCanvas({.width = mExtent.width,
                                                            .height = mExtent.height,
                                                            .tileSize = mSettings.tileSize,
                                                            .occupancy = mSettings.occupancy,
                                                            .seed = std::uint32_t(mSettings.seed)});
                if (!mSettings.color.empty()) {
                    images.color = loadCanvasColor(mSettings.color, mExtent.width, mExtent.height);
                }
                if (!mSettings.material.empty()) {
                    images.material = loadCanvasMaterial(mSettings.material, mExtent.width, mExtent.height);
                }
                mRenderer->setCanvas(images, mSettings.tileSize);
                mCanvasKey = canvasKey;
            }
        } catch (const MotionError& e) {
            throw SceneInputError(e.what());
        } catch (const IoError& e) {
            throw SceneInputError(e.what());
        }
    }

    CanvasSceneSettings mSettings;
    Extent mExtent{640, 360};
    std::optional<CanvasRenderer> mRenderer;
    std::optional<MotionTrack> mMotion;
    std::string mMotionPath;
    std::tuple<int, int, std::string, std::string, int, float, int> mCanvasKey{-1, -1, "", "", 0, 0.0f, 0};
};

} // namespace

std::unique_ptr<Scene> makeCanvasScene() {
    return std::make_unique<CanvasScene>();
}

} // namespace photopic
