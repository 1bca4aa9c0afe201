#include "scenes/testbed/TestbedScene.h"

#include "scenes/SceneSettings.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace photopic {

TestbedScene::TestbedScene() = default;

Settings TestbedScene::defaultSettings() const {
    Settings s;
    // A sunlit exterior: the eye adapts to the whole frame, the sun's disc blooms.
    s.tonemapping.mode = ToneMapper::AcesFitted;
    s.autoExposure.enabled = true;
    s.bloom.enabled = true;
    return s;
}

std::vector<SettingsIssue> TestbedScene::applyOverride(std::string_view assignment) {
    return applySceneOverride(mSettings, name(), assignment);
}

std::string TestbedScene::settingsJson() const {
    return sceneSettingsJson(mSettings);
}

void TestbedScene::resize(Extent extent) {
    mExtent = extent;
    mRenderer.resize(extent);
}

std::vector<std::string> TestbedScene::telemetryColumns() const {
    return {"shot", "cut"};
}

Lens TestbedScene::lens() const {
    Lens l;
    l.fNumber = mSettings.fNumber;
    l.shutterAngleDeg = mSettings.shutterAngle;
    l.sensorHeightMm = mSettings.sensorHeight;
    return l;
}

testbed::FrameTimes TestbedScene::frameTimes(const FrameTime& time) const {
    return testbed::frameTimes(time.frameIndex, double(time.dt),
                               {double(mSettings.cameraStart), double(mSettings.cameraSpeed)},
                               {double(mSettings.objectStart), double(mSettings.objectSpeed)});
}

testbed::TruthOptions TestbedScene::truthOptions(const FrameTime& time) const {
    testbed::TruthOptions o;
    o.width = mExtent.width;
    o.height = mExtent.height;
    o.times = frameTimes(time);
    o.dt = double(time.dt);
    o.lens = lens();
    o.focusDistance = mSettings.focusDistance;
    o.samples = mSettings.samples;
    o.aoRadius = mSettings.aoRadius;
    o.aoSamples = mSettings.aoSamples;
    o.sunMaxDistance = mSettings.sunMaxDistance;
    o.sunSamples = mSettings.sunSamples;
    if (mSettings.fixedCamera) {
        o.fixedView = testbed::FixedView{mSettings.eye, mSettings.target};
    }
    return o;
}

FrameInputs TestbedScene::render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) {
    const testbed::FrameTimes t = frameTimes(time);
    mCamera = testbed::truthCamera(truthOptions(time));
    mLastCameraTime = t.camera;
    const std::vector<testbed::Primitive> prims = testbed::primitivesAt(t.objects, t.prevObjects);

    const glm::vec2 jitter = pipeline.beginFrame(time, &mCamera);
    testbed::TestbedRenderer::DrawInfo draw{.camera = &mCamera, .jitter = jitter, .primitives = &prims};
    mRenderer.draw(draw);
    FrameInputs inputs{.color = &mRenderer.color(),
                       .depth = &mRenderer.depth(),
                       .depthKind = DepthKind::Standard,
                       .normals = &mRenderer.normals(),
                       .normalEncoding = NormalEncoding::ViewXyz,
                       .motion = &mRenderer.motion(),
                       .camera = &mCamera,
                       .sunDirection = testbed::environment().sunDirection,
                       .objectId = &mRenderer.objectId(),
                       .material = &mRenderer.material()};
    const LightingOutputs& lighting = pipeline.renderLighting(inputs, time);
    draw.ambientOcclusion = lighting.ambientOcclusion;
    draw.ambientOcclusionPower = lighting.ambientOcclusionPower;
    draw.sunVisibility = lighting.contactShadows;
    if (lighting.ambientOcclusion != nullptr || lighting.contactShadows != nullptr) {
        mRenderer.draw(draw);
    }
    // Supersampling: each further sub-frame with its own jitter (and the lighting stage's textures), folded
    // into the pipeline's mean in linear light; depth, normals and motion are the last sub-frame's.
    inputs.color = &pipeline.supersample(mRenderer.color(), [&](glm::vec2 subframeJitter) {
        draw.jitter = subframeJitter;
        mRenderer.draw(draw);
    });
    telemetry = {double(testbed::cameraPoseAt(t.camera).shot), mCamera.cut ? 1.0 : 0.0};
    return inputs;
}

OrbitView TestbedScene::currentView() const {
    OrbitView view;
    if (mSettings.fixedCamera || mLastCameraTime < 0.0) {
        view.eye = mSettings.eye;
        view.target = mSettings.target;
        return view;
    }
    // The path's camera of the last frame, looking at the point it focuses on.
    const glm::mat4 cameraToWorld = glm::inverse(mCamera.view);
    view.eye = glm::vec3(cameraToWorld[3]);
    const glm::vec3 forward = -glm::normalize(glm::vec3(cameraToWorld[2]));
    view.target = view.eye + forward * testbed::cameraPoseAt(mLastCameraTime).focusDistance;
    return view;
}

void TestbedScene::holdView(const OrbitView& view) {
    // Within the settings' range, so the held view saves and loads back as it is.
    mSettings.fixedCamera = true;
    mSettings.eye = glm::clamp(view.eye, glm::vec3(-1000.0f), glm::vec3(1000.0f));
    mSettings.target = glm::clamp(view.target, glm::vec3(-1000.0f), glm::vec3(1000.0f));
}

std::unique_ptr<Scene> makeTestbedScene() {
    return std::make_unique<TestbedScene>();
}

} // namespace photopic
