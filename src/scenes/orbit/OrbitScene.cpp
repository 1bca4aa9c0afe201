#include "scenes/orbit/OrbitScene.h"

#include "scenes/SceneSettings.h"
#include "scenes/orbit/OrbitShip.h"
#include "scenes/orbit/OrbitWorld.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

/// The built-in ship's bounding radius; a glTF model is scaled to the same size.
constexpr float kShipRadius = 14.0f;

} // namespace

OrbitScene::OrbitScene() = default;

Settings OrbitScene::defaultSettings() const {
    Settings s;
    s.tonemapping.mode = ToneMapper::Neutral;
    // Thin rods, panel seams and foil alias: SMAA on the display image by default (aa.mode=ssaa for stills).
    s.aa.mode = AntiAliasing::Smaa;
    if (mSettings.post == OrbitPost::Raw) {
        s.autoExposure.enabled = false;
        s.tonemapping.exposure = std::log2(mSettings.exp);
        s.bloom.enabled = false;
        s.lensFlare.enabled = false;
    } else {
        s.autoExposure.enabled = true;
        s.autoExposure.compensationEV = std::log2(mSettings.exp);
        // Space is mostly black: meter a spot on the ship, which the camera keeps at the image centre, not
        // the frame, whose empty sky would drag exposure up by several stops.
        s.autoExposure.metering = MeteringMode::Spot;
        s.autoExposure.spot.radius = 0.04f;
        s.autoExposure.spot.taps = 13;
        s.autoExposure.minEV = -6.0f;
        s.autoExposure.maxEV = 4.0f;
        // Bloom of what is well past white only (the sun's disc, glints), as a glow of light in the HDR
        // domain: the energy-conserving mix would spread the sun's disc, 2000x white, over the frame.
        s.bloom = BloomSettings::stills();
        s.bloom.threshold = 4.0f;
        s.bloom.intensity = 0.1f;
    }
    return s;
}

std::vector<SettingsIssue> OrbitScene::applyOverride(std::string_view assignment) {
    return applySceneOverride(mSettings, name(), assignment);
}

std::string OrbitScene::settingsJson() const {
    return sceneSettingsJson(mSettings);
}

void OrbitScene::loadModel() {
    orbit::Model model;
    if (mSettings.model.empty()) {
        model = orbit::buildShip();
    } else {
        try {
            model = orbit::loadModel(mSettings.model);
        } catch (const orbit::ModelError& e) {
            throw SceneInputError(std::string("--model: ") + e.what());
        }
    }
    // Centre the model on the origin and scale it to the ship's size, so the camera path frames it.
    const glm::vec3 centre = 0.5f * (model.bounds.min + model.bounds.max);
    const float radius = 0.5f * glm::length(model.bounds.max - model.bounds.min);
    const float scale = mSettings.model.empty() || radius <= 0.0f ? 1.0f : kShipRadius / radius;
    mShipRadius = mSettings.model.empty() ? radius : kShipRadius;
    const glm::mat4 placement =
        glm::scale(glm::mat4(1.0f), glm::vec3(scale)) *
        glm::translate(glm::mat4(1.0f), mSettings.model.empty() ? glm::vec3(0.0f) : -centre);
    mRenderer.setModel(model, placement);
    mLoadedModel = mSettings.model;
}

void OrbitScene::loadEnvironment() {
    mLoadedEnv = mSettings.env;
    mLoadedIblSize = mSettings.iblSize;
    // A missing or unreadable file logs one warning and falls back to a procedural sky (OrbitIbl.h).
    const std::filesystem::path path =
        mSettings.env.empty() ? orbit::Ibl::defaultEnvironmentPath() : std::filesystem::path(mSettings.env);
    orbit::IblOptions options;
    options.faceSize = mSettings.iblSize;
    options.specularLevels = std::min(options.specularLevels, int(std::log2(double(mSettings.iblSize))) + 1);
    mRenderer.setEnvironment(orbit::Ibl::loadEnvironmentOrFallback(path), options);
}

void OrbitScene::resize(Extent extent) {
    mExtent = extent;
    mRenderer.resize(extent);
    if (mLoadedModel != mSettings.model) {
        loadModel();
    }
    if (mLoadedEnv != mSettings.env || mLoadedIblSize != mSettings.iblSize) {
        loadEnvironment();
    }
}

std::vector<std::string> OrbitScene::telemetryColumns() const {
    return {"script_s", "sun_visibility"};
}

double OrbitScene::scriptTime(const FrameTime& time) const {
    return double(mSettings.start) + double(mSettings.speed) * double(time.frameIndex) * double(time.dt);
}

orbit::OrbitLights OrbitScene::lightsAt(double seconds) const {
    const bool raw = mSettings.post == OrbitPost::Raw;
    orbit::OrbitLights l;
    l.sunDirection = orbit::sunDirectionAt(seconds);
    l.sun = mSettings.sun;
    l.ambient = mSettings.amb;
    l.hemi = mSettings.hemi;
    l.ibl = mSettings.ibl;
    l.atmosphere = raw ? 0.0f : mSettings.atmosphere;
    l.glow = raw ? 0.0f : mSettings.glow;
    l.nebula = mSettings.nebula;
    l.time = seconds;
    return l;
}

FrameInputs OrbitScene::render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) {
    if (mLoadedModel != mSettings.model || mLoadedEnv != mSettings.env ||
        mLoadedIblSize != mSettings.iblSize) {
        resize(mExtent); // settings changed since the last resize (an interactive host)
    }
    const double t = scriptTime(time);
    const double dtScript = double(mSettings.speed) * double(time.dt);
    const double prev = time.frameIndex == 0 ? t : t - dtScript;
    mCamera = mSettings.fixedCamera
                  ? orbit::orbitCameraFrom(mSettings.eye, mSettings.eye, mExtent.width, mExtent.height)
                  : orbit::orbitCamera(t, prev, mShipRadius, mExtent.width, mExtent.height);
    mCamera.cut = time.frameIndex == 0;
    mLastScriptTime = t;

    const glm::vec2 jitter = pipeline.beginFrame(time, &mCamera);
    orbit::OrbitRenderer::DrawInfo draw{.camera = &mCamera,
                                        .jitter = jitter,
                                        .shipTransform = orbit::shipTransform(t),
                                        .prevShipTransform = orbit::shipTransform(prev),
                                        .lights = lightsAt(t),
                                        .shadow = &mSettings.shadow};
    mRenderer.draw(draw);
    FrameInputs inputs{.color = &mRenderer.color(),
                       .depth = &mRenderer.depth(),
                       .depthKind = DepthKind::Standard,
                       .normals = &mRenderer.normals(),
                       .normalEncoding = NormalEncoding::ViewXyz,
                       .motion = &mRenderer.motion(),
                       .camera = &mCamera,
                       .sunDirection = draw.lights.sunDirection,
                       .objectId = &mRenderer.objectId(),
                       .material = &mRenderer.material()};
    // The ship's shadow map goes to the pipeline too: volumetric light's shadow-map mode marches it (off by
    // default: there is no medium in orbit to scatter in; a user turns it on for the look). The sun's light
    // reaching the ship is what the medium would scatter, the planet's eclipse included.
    if (const orbit::ShadowMap* map = mRenderer.sunShadowMap()) {
        const float visible = orbit::sunVisibility(orbit::kEarth, glm::vec3(0.0f), draw.lights.sunDirection);
        inputs.sunShadow.depth = &map->depth();
        inputs.sunShadow.worldToClip = map->projection().viewProjection;
        inputs.sunShadow.illuminance = glm::vec3(draw.lights.sun * visible);
    }
    const LightingOutputs& lighting = pipeline.renderLighting(inputs, time);
    draw.ambientOcclusion = lighting.ambientOcclusion;
    draw.ambientOcclusionPower = lighting.ambientOcclusionPower;
    draw.contactShadows = lighting.contactShadows;
    if (lighting.ambientOcclusion != nullptr || lighting.contactShadows != nullptr) {
        mRenderer.draw(draw);
    }
    // Supersampling: each further sub-frame with its own jitter (and the lighting stage's textures), folded
    // into the pipeline's mean in linear light; depth, normals and motion are the last sub-frame's.
    inputs.color = &pipeline.supersample(mRenderer.color(), [&](glm::vec2 subframeJitter) {
        draw.jitter = subframeJitter;
        mRenderer.draw(draw);
    });
    telemetry = {t, double(orbit::sunVisibility(orbit::kEarth, glm::vec3(0.0f), draw.lights.sunDirection))};
    return inputs;
}

OrbitView OrbitScene::currentView() const {
    OrbitView view;
    view.eye = mSettings.fixedCamera ? mSettings.eye : orbit::cameraEyeAt(mLastScriptTime, mShipRadius);
    view.target = glm::vec3(0.0f);
    view.minDistance = 0.5f * mShipRadius;
    view.maxDistance = 600.0f;
    return view;
}

void OrbitScene::holdView(const OrbitView& view) {
    // Within the settings' range, so the held view saves and loads back as it is.
    mSettings.fixedCamera = true;
    mSettings.eye = glm::clamp(view.eye, glm::vec3(-1000.0f), glm::vec3(1000.0f));
}

std::unique_ptr<Scene> makeOrbitScene() {
    return std::make_unique<OrbitScene>();
}

} // namespace photopic
