#pragma once

#include "scenes/Scene.h"

namespace photopic {

/// A sky-to-ground HDR gradient with a sun disc that rises out of the frame and sets back over `period`
/// seconds: the smallest scene that exercises metering, adaptation, bloom and the scene runner. Deterministic
/// per frame.
struct GradientSceneSettings {
    float period = 8.0f;          ///< s, [0.1, 600], default 8: one rise-and-set of the sun
    float sunLuminance = 2000.0f; ///< scene-linear, [0, 65000], default 2000: the disc's luminance
    float skyLuminance = 1.0f;    ///< scene-linear, [0, 1000], default 1: the zenith's luminance

    template <class V>
    void visit(V& v) {
        v.field("period", period, Range{0.1, 600});
        v.field("sunLuminance", sunLuminance, Range{0, 65000});
        v.field("skyLuminance", skyLuminance, Range{0, 1000});
    }
};

std::unique_ptr<Scene> makeGradientScene();

} // namespace photopic
