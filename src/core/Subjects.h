#pragma once
// Subjects: what the eye follows (a token or character whose light drives exposure). GL-free: the selection
// rule, the probe schedule, the multi-tap probe on the CPU (the reference the GPU probe copies), the deadband
// on the measured luma, outdoors coupling and the per-subject context that game logic and UI read.
//
// Per frame, allocation-free once constructed (storage is sized by SubjectSettings::maxSubjects):
//   tracker.beginFrame(dt, viewCentreWorld);
//   tracker.addSubject({...});                       // every subject, in the host's order
//   for (const ProbeRequest& r : tracker.scheduleProbes())
//       tracker.recordProbe(r.id, probe(r.screenUv), tracker.time());  // CPU: probeImage; GPU: one dispatch
//   tracker.updateExposure(autoExposureSettings, viewAppliedLog2);
//   tracker.subjectContext(), contextForSubject(id), outdoorsAtWorld(x, y)
//
// Screen UV is image UV as in core/Metering.h: u right, v DOWN, (0, 0) = top-left. A host that projects to GL
// NDC (where v = ndc.y * 0.5 + 0.5 runs up) hands the library v = 0.5 - 0.5 * ndc.y.

#include "core/Image.h"
#include "core/Metering.h"
#include "core/OutdoorsMask.h"
#include "core/settings/AutoExposureSettings.h"
#include "core/settings/SubjectSettings.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace photopic {

/// Id of the synthetic screen-centre subject (SubjectFallback::Center). Hosts must not use it.
inline constexpr std::uint32_t kCenterSubjectId = 0xFFFFFFFFu;

/// One subject as the host registers it each frame.
struct Subject {
    std::uint32_t id = 0;          ///< the host's id (Foundry: token id), stable across frames
    glm::vec2 world{0.0f};         ///< world position (map units, y down; core/OutdoorsMask.h)
    glm::vec2 screenUv{0.5f};      ///< image UV the host projected (u right, v down)
    std::optional<float> outdoors; ///< 0..1 when the host knows it; else read from the outdoors mask
    bool controlled = false;       ///< the user controls it (Foundry: canvas.tokens.controlled)
    bool ownCharacter = false;     ///< the user's own character (Foundry: game.user.character's token)
};

/// Where the subject of the view came from (the selection rule's cases, in order).
enum class SubjectSource { None, Controlled, OwnCharacter, Center };

struct SubjectSelection {
    SubjectSource source = SubjectSource::None;
    std::size_t index = 0; ///< into the subjects, for Controlled and OwnCharacter
};

/// The eye is the user's: the first controlled subject, else the first that is the user's own character, else
/// the screen centre when `fallback` is center, else none.
[[nodiscard]] SubjectSelection selectSubject(std::span<const Subject> subjects,
                                             SubjectFallback fallback) noexcept;

// ---------------------------------------------------------------------------------------------------------------
// The probe: the light under a subject.

/// Probe taps: the first nine spot-metering taps (kSpotTaps, in units of probe.radius, image heights on both
/// axes, x right and y down), so a probe and a spot meter read the same disc; `taps = n` uses the first n:
/// 1 = centre, 5 = plus at 0.5, 9 = 3x3 grid of spacing 0.5. Equal weights.
inline constexpr int kProbeTapCount = 9;
static_assert(kProbeTapCount <= int(kSpotTaps.size()));

/// Texel of probe tap `tap` (nearest, clamped to the image), as spotTapTexel:
///   rp = radius * H;  px = uv.x * W + kSpotTaps[tap].x * rp;  py = uv.y * H + kSpotTaps[tap].y * rp
///   x = clamp(int(floor(px)), 0, W - 1);  y = clamp(int(floor(py)), 0, H - 1)
[[nodiscard]] TexelCoord probeTapTexel(glm::vec2 uv, int tap, float radius, int width, int height) noexcept;

/// The CPU reference probe: the ARITHMETIC mean of the Rec.709 luma at the first `taps` taps (1, 5 or 9;
/// other counts are clamped to 1..9). Averaging linear light keeps it a luminance. A tap whose luma is not
/// finite or is negative counts as 0 (the pipeline sanitises its input, so this only guards the CPU path). 0
/// for an empty image or a NaN UV.
[[nodiscard]] float probeImage(const ImageF& image, glm::vec2 uv, int taps, float radius) noexcept;

/// Probes due this frame (ProbeScheduler) for `probe.hz`, counted in frame time: the caller's dt, never a
/// clock, so replays are deterministic. The first advance() is due; then one is due each time the frame
/// time accumulated since the last due one reaches 1 / hz (within 1e-4 of a period, so float dt that sums
/// to the period counts: hz = 5 at dt = 1/30 is due every 6th frame exactly). The remainder carries over;
/// after a long frame at most one probe is due (no bursts to catch up).
class ProbeScheduler {
public:
    explicit ProbeScheduler(float hz = 10.0f) noexcept { setRate(hz); }
    /// hz <= 0 or NaN: probes every frame.
    void setRate(float hz) noexcept;
    /// One frame of dt seconds (negative or NaN counts as 0); true when a probe is due.
    bool advance(float dt) noexcept;
    /// The next advance() is due.
    void reset() noexcept;

private:
    double mPeriod = 0.1;
    double mSince = 0.0;
    bool mStarted = false;
};

/// Deadband (hysteresis) on the measured luma: `measured` replaces `kept` only when their log2 differ by more
/// than deadbandEV, or when `kept` is not meterable (no reading yet). Returns the luma to keep; a measured
/// value that is not meterable keeps `kept`.
[[nodiscard]] float applyLumaDeadband(float kept, float measured, float deadbandEV) noexcept;

// ---------------------------------------------------------------------------------------------------------------
// Outdoors coupling (optional, default off).

/// Exposure bounds and adaptation speed for an outdoors value t = clamp(outdoors, 0, 1) (NaN -> 0):
///   maxEV' = base.maxEV + (min(base.maxEV, c.maxEV) - base.maxEV) * t      (tighter outdoors, never looser)
///   minEV' = min(base.minEV, maxEV')
///   speed factor f = 1 + (c.speedScale - 1) * t:  tau' = tau / f, speed' = speed * f  (faster outdoors)
/// Disabled coupling returns `base` unchanged.
[[nodiscard]] AutoExposureSettings outdoorsCoupledSettings(const AutoExposureSettings& base,
                                                           const SubjectSettings::OutdoorsCoupling& coupling,
                                                           float outdoors);

// ---------------------------------------------------------------------------------------------------------------
// Per-subject context: what game logic and UI read about each subject.

struct SubjectContext {
    std::uint32_t id = 0;
    glm::vec2 world{0.0f};     ///< world position this frame
    float outdoors = 0.0f;     ///< 0..1: the subject's own value, else the mask at `world`, else 0
    float measuredLuma = 0.0f; ///< scene-linear luma kept after the deadband; 0 before the first probe
    float targetLog2 = 0.0f;   ///< EV, target exposure for measuredLuma (exposure multiplier = 2^targetLog2)
    float appliedLog2 = 0.0f;  ///< EV, the view's adapted exposure (one eye per view: several
                               ///< exposures on one screen would conflict)
    glm::vec2 screenUv{0.5f};  ///< image UV this frame (u right, v down)
    float lastProbeAt = -1.0f; ///< s of frame time (SubjectTracker::time()) of the last kept probe; -1: never
    bool moving = false;       ///< faster than probe.moveThreshold this frame
};

/// One probe to take this frame: the subject and where to sample.
struct ProbeRequest {
    std::uint32_t id = 0;
    glm::vec2 screenUv{0.5f};
};

/// The subjects of one view across frames: registration, selection, probe schedule and contexts. Storage is
/// allocated in the constructor and setSettings(); the per-frame calls never allocate and never throw.
class SubjectTracker {
public:
    explicit SubjectTracker(const SubjectSettings& settings = {});

    /// Set-up time: reallocates storage when maxSubjects changes (contexts then start afresh).
    void setSettings(const SubjectSettings& settings);
    [[nodiscard]] const SubjectSettings& settings() const { return mSettings; }
    /// Outdoors values for subjects that bring none. Not owned; must outlive its use; nullptr clears it.
    void setOutdoorsMask(const OutdoorsMask* mask) noexcept { mMask = mask; }

    /// Starts a frame of dt seconds: forgets last frame's list (keeping each subject's probe history by id).
    /// viewCentreWorld is the world position under the screen centre (the centre fallback's position).
    void beginFrame(float dt, glm::vec2 viewCentreWorld = glm::vec2(0.0f)) noexcept;
    /// Registers one subject for this frame. False when storage is full (warned once) or the id is already
    /// registered this frame or is kCenterSubjectId.
    bool addSubject(const Subject& subject) noexcept;
    /// Selects the subject of the view, adds the centre subject when the fallback applies, and returns the
    /// probes due this frame: every subject when the schedule is due (except those frozen while moving), a
    /// subject that just stopped moving or has never been probed at once. Call once per frame.
    std::span<const ProbeRequest> scheduleProbes() noexcept;
    /// A probe result (probeImage, or the GPU readback), taken at `atSeconds` of frame time. Unknown ids and
    /// luma that is not meterable are ignored.
    void recordProbe(std::uint32_t id, float luma, float atSeconds) noexcept;
    /// Fills targetLog2 (from each subject's measured luma, with its outdoors coupling) and appliedLog2 (the
    /// view's) for every subject.
    void updateExposure(const AutoExposureSettings& autoExposure, float viewAppliedLog2) noexcept;

    /// This frame's context, nullptr when the id is not registered.
    [[nodiscard]] const SubjectContext* contextForSubject(std::uint32_t id) const noexcept;
    /// The subject of the view, nullptr when there is none.
    [[nodiscard]] const SubjectContext* subjectContext() const noexcept;
    /// The mask at a world position, 0 without a mask.
    [[nodiscard]] float outdoorsAtWorld(float x, float y) const noexcept;

    [[nodiscard]] SubjectSelection selection() const { return mSelection; }
    /// This frame's contexts in registration order (the centre subject last, when selected).
    [[nodiscard]] std::span<const SubjectContext> contexts() const { return {mContexts.data(), mCount}; }
    /// Subjects this tracker can hold per frame (maxSubjects, plus one slot for the centre subject).
    [[nodiscard]] std::size_t capacity() const { return mContexts.size(); }
    /// Frame time in seconds: the sum of every beginFrame dt.
    [[nodiscard]] float time() const { return float(mTime); }

private:
    /// Per-subject state that is not part of the public context.
    struct Track {
        bool wasMoving = false;
        bool forceProbe = false;
    };

    std::size_t findCurrent(std::uint32_t id) const noexcept;
    void addEntry(const Subject& subject) noexcept;

    SubjectSettings mSettings;
    const OutdoorsMask* mMask = nullptr;
    ProbeScheduler mScheduler;

    // This frame (mCount used) and the previous one (mPrevCount used), same fixed capacity.
    std::vector<Subject> mSubjects;
    std::vector<SubjectContext> mContexts;
    std::vector<Track> mTracks;
    std::vector<SubjectContext> mPrevContexts;
    std::vector<Track> mPrevTracks;
    std::vector<ProbeRequest> mRequests;
    std::size_t mCount = 0;
    std::size_t mPrevCount = 0;
    std::size_t mRequestCount = 0;

    SubjectSelection mSelection;
    std::size_t mSelectedSlot = 0; ///< slot of the selected subject when mSelection.source != None
    float mDt = 0.0f;
    double mTime = 0.0;
    glm::vec2 mViewCentre{0.0f};
    bool mWarnedFull = false;
};

} // namespace photopic
