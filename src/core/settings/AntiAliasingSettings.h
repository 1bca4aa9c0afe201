#pragma once
// Anti-aliasing: one mode for the frame, and each method's own settings. FXAA and SMAA work on the
// display-referred image after tone mapping; TAA resolves in the HDR domain before metering; SSAA renders
// several jittered sub-frames through the host and accumulates them in HDR.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class AntiAliasing {
    None,
    Fxaa,    ///< FXAA 3.11 on display-referred values
    Smaa,    ///< SMAA 1x on display-referred values
    Taa,     ///< temporal resolve with motion vectors (needs jitter from the host and motion or depth)
    Ssaa,    ///< jittered sub-frames accumulated in HDR (built-in scenes and two-stage hosts)
    TaaSmaa, ///< SMAA's edges, then TAA's temporal gather
};

inline std::span<const std::string_view> antiAliasingNames() {
    static constexpr std::array<std::string_view, 6> kNames{"none", "fxaa", "smaa",
                                                            "taa",  "ssaa", "taa+smaa"};
    return kNames;
}

enum class SsaaFilter {
    Box,            ///< every sub-frame alike
    BlackmanHarris, ///< sub-frames near the pixel centre count more
};

inline std::span<const std::string_view> ssaaFilterNames() {
    static constexpr std::array<std::string_view, 2> kNames{"box", "blackman-harris"};
    return kNames;
}

struct AntiAliasingSettings {
    AntiAliasing mode = AntiAliasing::None;
    int level = 2;
    SsaaFilter ssaaFilter = SsaaFilter::Box;

    template <class V>
    void visit(V& v) {
        v.field("mode", mode, antiAliasingNames(),
                "the anti-aliasing method. The older switches `fxaa.enabled` and `taa.enabled` still select "
                "FXAA and TAA when this is none");
        v.field("level", level, Range{1, 4}, "SSAA: 2^level sub-frames per frame");
        v.field("ssaaFilter", ssaaFilter, ssaaFilterNames(),
                "SSAA reconstruction: box weighs every sub-frame alike, blackman-harris weighs those near "
                "the pixel centre more");
    }
};

enum class SmaaQuality { Low, Medium, High, Ultra };

inline std::span<const std::string_view> smaaQualityNames() {
    static constexpr std::array<std::string_view, 4> kNames{"low", "medium", "high", "ultra"};
    return kNames;
}

/// SMAA 1x (Jimenez et al. 2012) on the display-referred image.
struct SmaaSettings {
    SmaaQuality quality = SmaaQuality::High;
    float subpixel = 0.33f;

    template <class V>
    void visit(V& v) {
        v.field(
            "quality", quality, smaaQualityNames(),
            "sMAA preset. The reference presets: luma threshold 0.15 / 0.1 / 0.1 / 0.05, orthogonal search "
            "steps 4 / 8 / 16 / 32, diagonal steps - / - / 8 / 16, corner rounding - / - / 25% / 25%");
        v.field(
            "subpixel", subpixel, Range{0, 1},
            "a pixel the patterns leave alone that is a ridge one pixel wide (edges on both sides, darker "
            "or brighter than both) moves this far towards its sides' mean in linear light: a line thinner "
            "than a pixel is drawn fainter, as its coverage would have it. 0 is the reference SMAA 1x. Not "
            "under taa+smaa, where TAA's jittered frames resolve thin lines");
    }
};

enum class HistoryFilter {
    CatmullRom, ///< sharp: a bicubic fetch keeps a moving image from softening frame after frame
    Bilinear,   ///< cheaper, but every reprojection at a fractional position blurs the history a little
};

inline std::span<const std::string_view> historyFilterNames() {
    static constexpr std::array<std::string_view, 2> kNames{"catmull-rom", "bilinear"};
    return kNames;
}

/// Temporal anti-aliasing (Karis 2014; Salvi 2016 variance clipping; Playdead's adaptive feedback).
struct TaaSettings {
    bool enabled = false;
    float blendFactor = 0.9f;
    float varianceGamma = 1.0f;
    bool adaptiveFeedback = false;
    float feedbackMin = 0.88f;
    float feedbackMax = 0.97f;
    HistoryFilter historyFilter = HistoryFilter::CatmullRom;

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "turns TAA on; selects TAA when aa.mode is none");
        v.field("blendFactor", blendFactor, Range{0, 0.99}, "the history's weight in the blend");
        v.field("varianceGamma", varianceGamma, Range{0.5, 2},
                "the clip box is mean +- gamma * sigma (YCoCg)");
        v.field("adaptiveFeedback", adaptiveFeedback,
                "the history weight rises from feedbackMin to feedbackMax where the history agrees with the "
                "current frame (less blur on moving edges, longer accumulation where it is stable)");
        v.field("feedbackMin", feedbackMin, Range{0, 0.99},
                "adaptive feedback: the history weight where the history disagrees");
        v.field("feedbackMax", feedbackMax, Range{0, 0.99},
                "adaptive feedback: the history weight where the history agrees");
        v.field("historyFilter", historyFilter, historyFilterNames(),
                "how the history is fetched: catmull-rom keeps a moving image sharp, bilinear is cheaper but "
                "blurs a little at every reprojection");
        v.require(feedbackMin <= feedbackMax, "feedbackMin", "must not exceed feedbackMax");
    }
};

} // namespace photopic
