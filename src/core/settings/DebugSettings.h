#pragma once
// Debug views (scene values before tone mapping, overlays last; docs/architecture.md): what the pipeline
// shows instead of, or over, the image.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class DebugView {
    None,      ///< the normal image
    Exposure,  ///< false colour of exposed scene values (a band per stop)
    Luma,      ///< exposed Rec.709 luma as grey
    Ev,        ///< stops around middle grey, log2(Y exposure / 0.18), one colour per stop -6..+6
    Metering,  ///< the weight each pixel gets in the metering mode
    Histogram, ///< overlay over the normal image: 256 bins, percentile window, average, target, current
    Bloom,     ///< the bloom texture alone (black when the pipeline has no bloom)
    Depth, ///< linear view depth as grey, logarithmic from near (white) to far (black); needs depth + camera
    Normals, ///< view-space normals as colour, 0.5 + 0.5 n; needs normals
    Motion,  ///< motion vectors: hue is the direction, brightness the length (8 px saturates); needs motion
    TaaHistoryWeight, ///< TAA's history weight per pixel as grey (black: no history used); needs TAA on
    Disocclusion, ///< white where TAA found the history disoccluded (or off screen: see weight); needs TAA
    /// The lighting stage's sun visibility (contact shadows) as grey: raw values in an EXR; needs
    /// contactShadows.enabled and a host that runs the lighting stage
    ContactShadows,
    /// The contact-shadow ray march's steps taken per pixel over its step count (0: none marched)
    ContactShadowSteps,
    /// Depth of field's signed circle of confusion over dof.maxCocRadius: red the near field's radius, blue
    /// the far field's, black in focus (raw values in an EXR); needs dof.enabled, depth and a camera
    Coc,
    /// Screen-space reflections: the reflected radiance (RGB) and its confidence (alpha), raw values in an
    /// EXR; needs ssr.enabled, depth, a camera
    Ssr,
    /// Motion blur's velocity tiles: per pixel, its tile's neighbourhood maximum velocity in pixels of blur
    /// radius (R x right, G y up, B length); raw values in an EXR; needs motionBlur.enabled and motion
    VelocityTiles,
    /// Volumetric light: the light it adds (RGB), raw values in an EXR; needs volumetricLight.enabled,
    /// depth, a camera and the sun's direction
    VolumetricLight,
    /// Ambient occlusion's visibility (GTAO, after its denoise, before ssao.power) as grey: raw values in an
    /// EXR; needs ssao.enabled, depth, normals and a camera
    Gtao,
};

inline std::span<const std::string_view> debugViewNames() {
    static constexpr std::array<std::string_view, 19> kNames{"none",
                                                             "exposure",
                                                             "luma",
                                                             "ev",
                                                             "metering",
                                                             "histogram",
                                                             "bloom",
                                                             "depth",
                                                             "normals",
                                                             "motion",
                                                             "taa-history-weight",
                                                             "disocclusion",
                                                             "contact-shadows",
                                                             "contact-shadows-steps",
                                                             "coc",
                                                             "ssr",
                                                             "velocity-tiles",
                                                             "volumetric-light",
                                                             "ao"};
    return kNames;
}

struct DebugSettings {
    DebugView view = DebugView::None;

    template <class V>
    void visit(V& v) {
        v.field("view", view, debugViewNames(), "scene-value views replace the image before tone mapping");
    }
};

} // namespace photopic
