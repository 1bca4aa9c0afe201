#pragma once
// `photopic scene testbed`: an analytic 3D scene (TestbedGeometry.h) rasterised by TestbedRenderer, handing
// the pipeline colour, depth, normals, motion and the camera, with a CPU ray tracer (TestbedRaytracer.h) of
// the same geometry for ground truth.

#include "scenes/Scene.h"
#include "scenes/testbed/TestbedGeometry.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedRenderer.h"

#include <memory>

namespace photopic {

struct TestbedSceneSettings {
    float cameraStart = 0.0f;
    float cameraSpeed = 1.0f;
    float objectStart = 0.0f;
    float objectSpeed = 1.0f;
    float fNumber = 2.8f;
    float focusDistance = 0.0f;
    float shutterAngle = 180.0f;
    int samples = 16;
    float aoRadius = 1.0f;
    int aoSamples = 16;
    float sunMaxDistance = 0.0f;
    int sunSamples = 1;
    bool fixedCamera = false;
    glm::vec3 eye{0.0f, 1.2f, 6.0f};
    glm::vec3 target{0.0f, 0.8f, -1.0f};
    float sensorHeight = 24.0f;

    template <class V>
    void visit(V& v) {
        v.field("cameraStart", cameraStart, Range{0, 1000}, "s: the camera path's time at frame 0");
        v.field("cameraSpeed", cameraSpeed, Range{0, 100},
                "path seconds per second (0 holds the camera still)");
        v.field("objectStart", objectStart, Range{0, 1000}, "s: the objects' time at frame 0");
        v.field("objectSpeed", objectSpeed, Range{0, 100}, "object seconds per second (0 holds them still)");
        v.field("fNumber", fNumber, Range{0.5, 256}, "the lens (thin-lens truth, the camera's lens)");
        v.field("focusDistance", focusDistance, Range{0, 1000}, "m: the camera path's focus");
        v.field("shutterAngle", shutterAngle, Range{0, 360},
                "degrees: the shutter (shutter truth, the camera's lens)");
        v.field("samples", samples, Range{1, 64}, "colour truths take samples x samples per pixel");
        v.field("aoRadius", aoRadius, Range{0.01, 100}, "m: the ao truth's occluder distance");
        v.field("aoSamples", aoSamples, Range{1, 64}, "aoSamples x aoSamples rays per pixel");
        v.field("sunMaxDistance", sunMaxDistance, Range{0, 1000},
                "m (0: unlimited): the sun truth's occluder distance");
        v.field("sunSamples", sunSamples, Range{1, 32},
                "1: one ray to the sun's centre; n: n x n over its disc");
        v.field("fixedCamera", fixedCamera,
                "false: the camera path's framing; true: a still camera at `eye` looking at `target` (focus "
                "at the target's distance unless focusDistance is set)");
        v.field("eye", eye, Range{-1000, 1000}, "m: the fixed camera's position");
        v.field("target", target, Range{-1000, 1000}, "m: the point the fixed camera looks at");
        v.field(
            "sensorHeight", sensorHeight, Range{1, 1000},
            "mm (24: full frame): the lens's sensor height; with the fixed 45-degree field of view the focal "
            "length follows it, so a larger sensor gives a longer lens and shallower depth of field");
        v.require(!fixedCamera || eye != target, "target", "must differ from eye");
    }
};

/// Its camera follows the scripted path; as an InteractiveCamera (photopic-view's drag and wheel) the first
/// move holds the path's current view as a still camera (fixedCamera, eye, target) and then orbits that.
class TestbedScene final : public Scene, private InteractiveCamera {
public:
    /// Needs a current GL 4.5 context (compiles the scene's shaders).
    TestbedScene();

    [[nodiscard]] std::string_view name() const override { return "testbed"; }
    [[nodiscard]] Settings defaultSettings() const override;
    std::vector<SettingsIssue> applyOverride(std::string_view assignment) override;
    [[nodiscard]] std::string settingsJson() const override;
    void resize(Extent extent) override;
    /// shot, cut: the camera path's shot and whether this frame starts it.
    [[nodiscard]] std::vector<std::string> telemetryColumns() const override;
    /// Asks the pipeline for the frame's jitter (beginFrame), rasterises, runs its lighting stage and, when
    /// that hands back ambient occlusion or sun visibility, shades again with them.
    FrameInputs render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) override;

    [[nodiscard]] InteractiveCamera* interactiveCamera() override { return this; }

    [[nodiscard]] const TestbedSceneSettings& settings() const { return mSettings; }
    /// The camera's and objects' times of frame `time` under the settings.
    [[nodiscard]] testbed::FrameTimes frameTimes(const FrameTime& time) const;
    /// The truth options matching frame `time` at this scene's size and settings.
    [[nodiscard]] testbed::TruthOptions truthOptions(const FrameTime& time) const;
    /// The Lens the settings describe (focal length and focus come from the camera path).
    [[nodiscard]] Lens lens() const;

private:
    /// The still camera the next move starts from: the fixed one, else the path's view of the last frame.
    [[nodiscard]] OrbitView currentView() const override;
    void holdView(const OrbitView& view) override;

    TestbedSceneSettings mSettings;
    double mLastCameraTime = -1.0; ///< path time of the last rendered frame; < 0 before the first
    testbed::TestbedRenderer mRenderer;
    Camera mCamera;
    Extent mExtent;
};

std::unique_ptr<Scene> makeTestbedScene();

} // namespace photopic
