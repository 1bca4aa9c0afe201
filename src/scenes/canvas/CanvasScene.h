#pragma once

#include "scenes/Scene.h"
#include "scenes/canvas/CanvasRenderer.h"

#include <string>

namespace photopic {

/// A painted canvas lit by the device's tilt: a lamp over the user's shoulder whose direction
/// follows pitch and roll, Blinn-Phong highlights from a material map, glitter that sparkles, shading only on
/// tiles with material. `photopic scene canvas`.
struct CanvasSceneSettings {
    std::string color;
    std::string material;
    std::string motion;
    CanvasShading shading = CanvasShading::Auto;
    int tileSize = 256;
    float occupancy = 0.5f;
    int seed = 3;
    float lightIntensity = 1.0f;
    float ambient = 0.25f;
    float specular = 0.6f;
    float sparkleExposure = 4.0f;
    float viewDistance = 1.5f;
    float sweepPeriod = 6.0f;
    float sweepRoll = 0.35f;
    float sweepPitch = 0.25f;

    template <class V>
    void visit(V& v) {
        v.field("colour", color,
                "path (empty: a procedural painting): the painting's colour (EXR, HDR, PNG)");
        v.field("material", material, "path (empty: procedural): material PNG (RGBA)");
        v.field("motion", motion, "path (empty: a scripted tilt): CSV \"time_s,pitch,roll,yaw\" in radians");
        v.field("shading", shading, canvasShadingNames(),
                "tiled: specular and sparkle only on tiles with material; fullscreen: one dispatch over "
                "every pixel; auto: whichever the first frames measure faster on this device (the same "
                "image either way)");
        v.field("tileSize", tileSize, Range{16, 1024}, "px, a multiple of 16: the shading tiles' size");
        v.require(tileSize % 16 == 0, "tileSize", "must be a multiple of 16 (the shading workgroup's side)");
        v.field("occupancy", occupancy, Range{0, 1},
                "fraction of tiles given material (procedural material)");
        v.field("seed", seed, Range{0, 1000000}, "the painting's strokes, glitter facets and tiles");
        v.field("lightIntensity", lightIntensity, Range{0, 1000}, "scene-linear: the lamp");
        v.field("ambient", ambient, Range{0, 10}, "fill light, a fraction of the lamp");
        v.field("specular", specular, Range{0, 100}, "Blinn-Phong strength ks");
        v.field("sparkleExposure", sparkleExposure, Range{0, 1000},
                "exposure on the sparkle (>1 at the peak)");
        v.field("viewDistance", viewDistance, Range{0.1, 100},
                "image heights: eye in front of the canvas centre");
        v.field("sweepPeriod", sweepPeriod, Range{0.1, 600}, "s: scripted tilt's roll period (pitch: 1.5x)");
        v.field("sweepRoll", sweepRoll, Range{0, 1.5}, "rad: scripted roll amplitude");
        v.field("sweepPitch", sweepPitch, Range{0, 1.5}, "rad: scripted pitch amplitude");
    }
};

std::unique_ptr<Scene> makeCanvasScene();

} // namespace photopic
