#pragma once

#include "scenes/Scene.h"
#include "scenes/canvas/CanvasRenderer.h"

#include <string>

namespace photopic {

/// A painted canvas lit by the device's tilt: a lamp over the user's shoulder whose direction
/// follows pitch and roll, Blinn-Phong highlights from a material map, glitter that sparkles, shading only on
/// tiles with material. `photopic scene canvas`.
struct CanvasSceneSettings {
    std::string color;    ///< path, default "" (procedural painting): the painting's colour (EXR, HDR, PNG)
    std::string material; ///< path, default "" (procedural): material PNG (RGBA, see CanvasMaterial.h)
    std::string motion;   ///< path, default "" (scripted tilt): CSV "time_s,pitch,roll,yaw" in radians
    CanvasShading shading = CanvasShading::Tiled; ///< tiled | fullscreen, default tiled
    int tileSize = 256;                           ///< px, [16, 1024], multiple of 16, default 256
    float occupancy = 0.5f; ///< [0, 1], default 0.5: fraction of tiles given material (procedural material)
    int seed = 3;           ///< [0, 1000000], default 3: the painting's strokes, glitter facets and tiles
    float lightIntensity = 1.0f;  ///< scene-linear, [0, 1000], default 1: the lamp
    float ambient = 0.25f;        ///< [0, 10], default 0.25: fill light, a fraction of the lamp
    float specular = 0.6f;        ///< [0, 100], default 0.6: Blinn-Phong strength ks
    float sparkleExposure = 4.0f; ///< [0, 1000], default 4: exposure on the sparkle (>1 at the peak)
    float viewDistance = 1.5f; ///< image heights, [0.1, 100], default 1.5: eye in front of the canvas centre
    float sweepPeriod = 6.0f;  ///< s, [0.1, 600], default 6: scripted tilt's roll period (pitch: 1.5x)
    float sweepRoll = 0.35f;   ///< rad, [0, 1.5], default 0.35: scripted roll amplitude
    float sweepPitch = 0.25f;  ///< rad, [0, 1.5], default 0.25: scripted pitch amplitude

    template <class V>
    void visit(V& v) {
        v.field("colour", color);
        v.field("material", material);
        v.field("motion", motion);
        v.field("shading", shading, canvasShadingNames());
        v.field("tileSize", tileSize, Range{16, 1024});
        v.require(tileSize % 16 == 0, "tileSize", "must be a multiple of 16 (the shading workgroup's side)");
        v.field("occupancy", occupancy, Range{0, 1});
        v.field("seed", seed, Range{0, 1000000});
        v.field("lightIntensity", lightIntensity, Range{0, 1000});
        v.field("ambient", ambient, Range{0, 10});
        v.field("specular", specular, Range{0, 100});
        v.field("sparkleExposure", sparkleExposure, Range{0, 1000});
        v.field("viewDistance", viewDistance, Range{0.1, 100});
        v.field("sweepPeriod", sweepPeriod, Range{0.1, 600});
        v.field("sweepRoll", sweepRoll, Range{0, 1.5});
        v.field("sweepPitch", sweepPitch, Range{0, 1.5});
    }
};

std::unique_ptr<Scene> makeCanvasScene();

} // namespace photopic
