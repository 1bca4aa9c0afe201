#pragma once
// Outlines from depth and normal discontinuities, drawn into the HDR image before TAA so that TAA smooths
// them like any other edge.

#include "core/settings/Reflect.h"

#include <glm/vec3.hpp>

namespace photopic {

struct OutlineSettings {
    bool enabled = false;
    float depthThreshold = 0.01f;
    float normalThreshold = 0.3f;
    float intensity = 1.0f;
    int width = 1;
    glm::vec3 color{0.0f};

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns outlines (depth and normal edges) on");
        v.field("depthThreshold", depthThreshold, Range{0, 1},
                "the relative depth jump that makes an edge. Measured in 1/z, which is affine on any plane, "
                "so a tilted plane gives no edge at any angle: (2/z0 - 1/zl - 1/zr) z0 across the pixel, a "
                "jump from z0 to z1 behind it giving (z1 - z0) / z1 on the near side. Scale-invariant (no "
                "scene units); only the nearer side of a jump is drawn");
        v.field("normalThreshold", normalThreshold, Range{0, 2},
                "1 - cos of the angle between the normals on either side of the pixel that makes an edge "
                "(0.3: about 46 degrees); 2 turns normal edges off");
        v.field("intensity", intensity, Range{0, 1}, "how much of the outline colour replaces the image");
        v.field("width", width, Range{1, 8}, "pixels: how far from the edge a pixel is outlined");
        v.field("color", color, Range{0, 65504}, "linear scene-referred RGB");
    }
};

} // namespace photopic
