#pragma once
// TAA's settings, selected by aa.mode = taa or taa+smaa.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

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
