#pragma once
// Outlines from depth and normal discontinuities, drawn into the HDR image before TAA so that TAA smooths
// them like any other edge.

#include "core/settings/Reflect.h"

#include <glm/vec3.hpp>

namespace photopic {

struct OutlineSettings {
    bool enabled = false; ///< default off
    /// [0, 1], default 0.01: the relative depth jump that makes an edge. Measured in 1/z, which is affine on
    /// any plane, so a tilted plane gives no edge at any angle: (2/z0 - 1/zl - 1/zr) z0 across the pixel,
    /// a jump from z0 to z1 behind it giving (z1 - z0) / z1 on the near side. Scale-invariant (no scene
    /// units); only the nearer side of a jump is drawn.
    float depthThreshold = 0.01f;
    /// [0, 2], default 0.3: 1 - cos of the angle between the normals on either side of the pixel that makes
    /// an edge (0.3: about 46 degrees); 2 turns normal edges off.
    float normalThreshold = 0.3f;
    float intensity = 1.0f; ///< [0, 1], default 1: how much of the outline colour replaces the image
    int width = 1;          ///< pixels, [1, 8], default 1: how far from the edge a pixel is outlined
    glm::vec3 color{0.0f};  ///< linear scene-referred RGB, [0, 65504], default black

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled);
        v.field("depthThreshold", depthThreshold, Range{0, 1});
        v.field("normalThreshold", normalThreshold, Range{0, 2});
        v.field("intensity", intensity, Range{0, 1});
        v.field("width", width, Range{1, 8});
        v.field("color", color, Range{0, 65504});
    }
};

} // namespace photopic
