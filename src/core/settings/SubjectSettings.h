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
        float hz = 10.0f; ///< 1/s, [0.1, 240], default 10: probes per second of frame time
        int taps = 5;     ///< 1, 5 or 9, default 5: the first taps of kSpotTaps (centre, plus, 3x3), averaged
        float radius = 0.02f;           ///< image heights, [0, 0.5], default 0.02: distance of the outer taps
        bool freezeWhileMoving = false; ///< default off: skip probes while the subject moves, force one when
                                        ///< it stops (a walking token over torch pools does not pump)
        float moveThreshold = 20.0f;    ///< world units/s, [0, 1e6], default 20: "moving" above this speed
        float deadbandEV = 0.05f; ///< EV, [0, 4], default 0.05: a probe closer than this (in log2 luma) to
                                  ///< the kept luma is ignored, so tiny changes do not make exposure hunt

        template <class V>
        void visit(V& v) {
            v.field("hz", hz, Range{0.1, 240});
            v.field("taps", taps, Range{1, 9});
            v.field("radius", radius, Range{0, 0.5});
            v.field("freezeWhileMoving", freezeWhileMoving);
            v.field("moveThreshold", moveThreshold, Range{0, 1e6});
            v.field("deadbandEV", deadbandEV, Range{0, 4});
            v.require(taps == 1 || taps == 5 || taps == 9, "taps", "must be 1, 5 or 9");
        }
    };

    /// Outdoors coupling (outdoors, exposure may clamp tighter and adapt faster): blended by the
    /// subject's outdoors value, 0 = indoors (settings unchanged) .. 1 = fully outdoors.
    struct OutdoorsCoupling {
        bool enabled = false;    ///< default off until tuned for a scene
        float maxEV = 1.0f;      ///< EV, [-20, 20], default 1: highest auto exposure when fully outdoors
        float speedScale = 2.0f; ///< x, [1, 10], default 2: adaptation runs this much faster fully outdoors

        template <class V>
        void visit(V& v) {
            v.field("enabled", enabled);
            v.field("maxEV", maxEV, Range{-20, 20});
            v.field("speedScale", speedScale, Range{1, 10});
        }
    };

    SubjectFallback fallback = SubjectFallback::None; ///< default none: what the view follows without subject
    int maxSubjects = 32; ///< count, [1, 1024], default 32: storage fixed at set-up; extra subjects dropped
    Probe probe;
    OutdoorsCoupling outdoorsCoupling;

    template <class V>
    void visit(V& v) {
        v.field("fallback", fallback, subjectFallbackNames());
        v.field("maxSubjects", maxSubjects, Range{1, 1024});
        v.object("probe", probe);
        v.object("outdoorsCoupling", outdoorsCoupling);
    }
};

} // namespace photopic
