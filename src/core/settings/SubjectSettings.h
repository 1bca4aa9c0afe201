#pragma once
// Subjects (exposure that follows the light a token or character stands in): the host registers subjects each
// frame, a selection rule picks the subject of the view, probes measure the light under every subject at
// `probe.hz`, and the subject of the view can drive `subject` metering. The logic is in core/Subjects.h.
//
// Defaults: probeHz 10 (walking pace needs no more), a multi-tap probe (steadier than one texel) with a small
// deadband on the measured luma (against flicker), outdoors coupling present but off until tuned.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

/// What the view follows when no subject is controlled and the user has no character (no subject, or
/// the centre of the screen).
enum class SubjectFallback {
    None,   ///< no subject: subject metering gives no reading and exposure holds
    Center, ///< the screen centre, probed like a subject (id kCenterSubjectId)
};

inline std::span<const std::string_view> subjectFallbackNames() {
    static constexpr std::array<std::string_view, 2> kNames{"none", "center"};
    return kNames;
}

struct SubjectSettings {
    /// The light probe under each subject.
    struct Probe {
        float hz = 10.0f;
        int taps = 5;
        float radius = 0.02f;
        bool freezeWhileMoving = false;
        float moveThreshold = 20.0f;
        float deadbandEV = 0.05f;

        template <class V>
        void visit(V& v) {
            v.field("hz", hz, Range{0.1, 240}, "1/s: probes per second of frame time");
            v.field("taps", taps, Range{1, 9},
                    "1, 5 or 9: the first taps of kSpotTaps (centre, plus, 3x3), averaged");
            v.field("radius", radius, Range{0, 0.5}, "image heights: distance of the outer taps");
            v.field("freezeWhileMoving", freezeWhileMoving,
                    "skip probes while the subject moves, force one when it stops (a walking token over "
                    "torch pools does not pump)");
            v.field("moveThreshold", moveThreshold, Range{0, 1e6},
                    "world units/s: \"moving\" above this speed");
            v.field("deadbandEV", deadbandEV, Range{0, 4},
                    "EV: a probe closer than this (in log2 luma) to the kept luma is ignored, so tiny "
                    "changes do not make exposure hunt");
            v.require(taps == 1 || taps == 5 || taps == 9, "taps", "must be 1, 5 or 9");
        }
    };

    /// Outdoors coupling (outdoors, exposure may clamp tighter and adapt faster): blended by the
    /// subject's outdoors value, 0 = indoors (settings unchanged) .. 1 = fully outdoors.
    struct OutdoorsCoupling {
        bool enabled = false;
        float maxEV = 1.0f;
        float speedScale = 2.0f;

        template <class V>
        void visit(V& v) {
            v.field("enabled", enabled,
                    "couples adaptation to how far outdoors the subject is (off until tuned for a scene)");
            v.field("maxEV", maxEV, Range{-20, 20}, "EV: highest auto exposure when fully outdoors");
            v.field("speedScale", speedScale, Range{1, 10},
                    "x: adaptation runs this much faster fully outdoors");
        }
    };

    SubjectFallback fallback = SubjectFallback::None;
    int maxSubjects = 32;
    Probe probe;
    OutdoorsCoupling outdoorsCoupling;

    template <class V>
    void visit(V& v) {
        v.field("fallback", fallback, subjectFallbackNames(), "what the view follows without a subject");
        v.field("maxSubjects", maxSubjects, Range{1, 1024},
                "count: storage fixed at set-up; extra subjects dropped");
        v.object("probe", probe);
        v.object("outdoorsCoupling", outdoorsCoupling);
    }
};

} // namespace photopic
