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
    float cameraStart = 0.0f;    ///< s, [0, 1000], default 0: the camera path's time at frame 0
    float cameraSpeed = 1.0f;    ///< [0, 100], default 1: path seconds per second (0 holds the camera still)
    float objectStart = 0.0f;    ///< s, [0, 1000], default 0: the objects' time at frame 0
    float objectSpeed = 1.0f;    ///< [0, 100], default 1: object seconds per second (0 holds them still)
    float fNumber = 2.8f;        ///< [0.5, 256], default 2.8: the lens (thin-lens truth, the camera's lens)
    float focusDistance = 0.0f;  ///< m, [0, 1000], default 0: the camera path's focus
    float shutterAngle = 180.0f; ///< degrees, [0, 360], default 180 (shutter truth, the camera's lens)
    int samples = 16;            ///< [1, 64], default 16: colour truths take samples x samples per pixel
    float aoRadius = 1.0f;       ///< m, [0.01, 100], default 1: the ao truth's occluder distance
    int aoSamples = 16;          ///< [1, 64], default 16: aoSamples x aoSamples rays per pixel
    float sunMaxDistance = 0.0f; ///< m, [0, 1000], default 0 (unlimited): the sun truth's occluder distance
    int sunSamples = 1;          ///< [1, 32], default 1: one ray to the sun's centre; n: n x n over its disc
    /// Default false: the camera path's framing; true: a still camera at `eye` looking at `target` (a test
    /// holds a chosen framing; focus at the target's distance unless focusDistance is set).
    bool fixedCamera = false;
    glm::vec3 eye{0.0f, 1.2f, 6.0f};     ///< m, each in [-1000, 1000]: the fixed camera's position
    glm::vec3 target{0.0f, 0.8f, -1.0f}; ///< m, each in [-1000, 1000]: the point the fixed camera looks at
    /// mm, [1, 1000], default 24 (full frame): the lens's sensor height; with the fixed 45-degree field of
    /// view the focal length follows it, so a larger sensor gives a longer lens and shallower depth of field
    float sensorHeight = 24.0f;

    template <class V>
    void visit(V& v) {
        v.field("cameraStart", cameraStart, Range{0, 1000});
        v.field("cameraSpeed", cameraSpeed, Range{0, 100});
        v.field("objectStart", objectStart, Range{0, 1000});
        v.field("objectSpeed", objectSpeed, Range{0, 100});
        v.field("fNumber", fNumber, Range{0.5, 256});
        v.field("focusDistance", focusDistance, Range{0, 1000});
        v.field("shutterAngle", shutterAngle, Range{0, 360});
        v.field("samples", samples, Range{1, 64});
        v.field("aoRadius", aoRadius, Range{0.01, 100});
        v.field("aoSamples", aoSamples, Range{1, 64});
        v.field("sunMaxDistance", sunMaxDistance, Range{0, 1000});
        v.field("sunSamples", sunSamples, Range{1, 32});
        v.field("fixedCamera", fixedCamera);
        v.field("eye", eye, Range{-1000, 1000});
        v.field("target", target, Range{-1000, 1000});
        v.field("sensorHeight", sensorHeight, Range{1, 1000});
        v.require(!fixedCamera || eye != target, "target", "must differ from eye");
    }
};

class TestbedScene final : public Scene {
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

    [[nodiscard]] const TestbedSceneSettings& settings() const { return mSettings; }
    /// The camera's and objects' times of frame `time` under the settings.
    [[nodiscard]] testbed::FrameTimes frameTimes(const FrameTime& time) const;
    /// The truth options matching frame `time` at this scene's size and settings.
    [[nodiscard]] testbed::TruthOptions truthOptions(const FrameTime& time) const;
    /// The Lens the settings describe (focal length and focus come from the camera path).
    [[nodiscard]] Lens lens() const;

private:
    TestbedSceneSettings mSettings;
    testbed::TestbedRenderer mRenderer;
    Camera mCamera;
    Extent mExtent;
};

std::unique_ptr<Scene> makeTestbedScene();

} // namespace photopic
