#pragma once

#include "scenes/Scene.h"

namespace photopic {

/// A sky-to-ground HDR gradient with a sun disc that rises out of the frame and sets back over `period`
/// seconds: the smallest scene that exercises metering, adaptation, bloom and the scene runner. Deterministic
/// per frame.
struct GradientSceneSettings {
    float period = 8.0f;
    float sunLuminance = 2000.0f;
    float skyLuminance = 1.0f;

    template <class V>
    void visit(V& v) {
        v.field("period", period, Range{0.1, 600}, "s: one rise-and-set of the sun");
        v.field("sunLuminance", sunLuminance, Range{0, 65000}, "scene-linear: the disc's luminance");
        v.field("skyLuminance", skyLuminance, Range{0, 1000}, "scene-linear: the zenith's luminance");
    }
};

std::unique_ptr<Scene> makeGradientScene();

} // namespace photopic
