#include "core/Subjects.h"

#include "core/ExposureController.h"
#include "core/Log.h"

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

constexpr std::size_t kNotFound = static_cast<std::size_t>(-1);
/// A period counts as elapsed within this fraction of it: float frame times that sum to the period (six
/// dt = 1/30 for 5 Hz) land a few ulps either side of it.
constexpr double kPeriodTolerance = 1e-4;

float clamp01OrZero(float x) noexcept {
    return x >= 0.0f ? std::min(x, 1.0f) : 0.0f; // NaN and negatives -> 0
}

} // namespace

SubjectSelection selectSubject(std::span<const Subject> subjects, SubjectFallback fallback) noexcept {
    for (std::size_t i = 0; i < subjects.size(); ++i) {
        if (subjects[i].controlled) {
            return {SubjectSource::Controlled, i};
        }
    }
    for (std::size_t i = 0; i < subjects.size(); ++i) {
        if (subjects[i].ownCharacter) {
            return {SubjectSource::OwnCharacter, i};
        }
    }
    if (fallback == SubjectFallback::Center) {
        return {SubjectSource::Center, 0};
    }
    return {};
}

TexelCoord probeTapTexel(glm::vec2 uv, int tap, float radius, int width, int height) noexcept {
    const AutoExposureSettings::SpotMetering disc{
        .u = uv.x, .v = uv.y, .radius = radius, .taps = kProbeTapCount};
    return spotTapTexel(disc, std::clamp(tap, 0, kProbeTapCount - 1), width, height);
}

float probeImage(const ImageF& image, glm::vec2 uv, int taps, float radius) noexcept {
    if (image.empty() || std::isnan(uv.x) || std::isnan(uv.y)) {
        return 0.0f;
    }
    const int n = std::clamp(taps, 1, kProbeTapCount);
    double sum = 0.0;
    for (int t = 0; t < n; ++t) {
        const TexelCoord c = probeTapTexel(uv, t, radius, image.width, image.height);
        const float l = pixelLuminance(image, c.x, c.y);
        sum += (l >= 0.0f && l <= kMaxMeterableLuminance) ? double(l) : 0.0;
    }
    return float(sum / double(n));
}

void ProbeScheduler::setRate(float hz) noexcept {
    mPeriod = hz > 0.0f ? 1.0 / double(hz) : 0.0;
}

bool ProbeScheduler::advance(float dt) noexcept {
    if (!mStarted) {
        mStarted = true;
        mSince = 0.0;
        return true;
    }
    mSince += dt > 0.0f ? double(dt) : 0.0;
    if (mSince < mPeriod * (1.0 - kPeriodTolerance)) {
        return false;
    }
    mSince = std::max(mSince - mPeriod, 0.0);
    if (mSince >= mPeriod) {
        mSince = 0.0;
    }
    return true;
}

void ProbeScheduler::reset() noexcept {
    mStarted = false;
    mSince = 0.0;
}

float applyLumaDeadband(float kept, float measured, float deadbandEV) noexcept {
    if (!isMeterableLuminance(measured)) {
        return kept;
    }
    if (!isMeterableLuminance(kept)) {
        return measured;
    }
    return std::abs(std::log2(measured) - std::log2(kept)) > deadbandEV ? measured : kept;
}

AutoExposureSettings outdoorsCoupledSettings(const AutoExposureSettings& base,
                                             const SubjectSettings::OutdoorsCoupling& coupling,
                                             float outdoors) {
    AutoExposureSettings s = base;
    if (!coupling.enabled) {
        return s;
    }
    const float t = clamp01OrZero(outdoors);
    const float tightMax = std::min(base.maxEV, coupling.maxEV);
    s.maxEV = base.maxEV + (tightMax - base.maxEV) * t;
    s.minEV = std::min(base.minEV, s.maxEV);
    const float f = 1.0f + (std::max(coupling.speedScale, 1.0f) - 1.0f) * t;
    s.tauBrighten = base.tauBrighten / f;
    s.tauDarken = base.tauDarken / f;
    s.speedUp = base.speedUp * f;
    s.speedDown = base.speedDown * f;
    return s;
}

SubjectTracker::SubjectTracker(const SubjectSettings& settings) {
    setSettings(settings);
}

void SubjectTracker::setSettings(const SubjectSettings& settings) {
    const std::size_t capacity = std::size_t(std::max(settings.maxSubjects, 1)) + 1; // + the centre subject
    mSettings = settings;
    mScheduler.setRate(settings.probe.hz);
    if (capacity != mContexts.size()) {
        mSubjects.assign(capacity, Subject{});
        mContexts.assign(capacity, SubjectContext{});
        mTracks.assign(capacity, Track{});
        mPrevContexts.assign(capacity, SubjectContext{});
        mPrevTracks.assign(capacity, Track{});
        mRequests.assign(capacity, ProbeRequest{});
        mCount = mPrevCount = mRequestCount = 0;
        mSelection = {};
    }
}

void SubjectTracker::beginFrame(float dt, glm::vec2 viewCentreWorld) noexcept {
    std::copy_n(mContexts.begin(), mCount, mPrevContexts.begin());
    std::copy_n(mTracks.begin(), mCount, mPrevTracks.begin());
    mPrevCount = mCount;
    mCount = 0;
    mRequestCount = 0;
    mSelection = {};
    mDt = dt > 0.0f ? dt : 0.0f;
    mTime += double(mDt);
    mViewCentre = viewCentreWorld;
}

std::size_t SubjectTracker::findCurrent(std::uint32_t id) const noexcept {
    for (std::size_t i = 0; i < mCount; ++i) {
        if (mContexts[i].id == id) {
            return i;
        }
    }
    return kNotFound;
}

void SubjectTracker::addEntry(const Subject& subject) noexcept {
    const std::size_t slot = mCount++;
    mSubjects[slot] = subject;
    SubjectContext& c = mContexts[slot];
    Track& track = mTracks[slot];
    c = SubjectContext{};
    track = Track{};
    glm::vec2 previousWorld = subject.world;
    bool seen = false;
    for (std::size_t i = 0; i < mPrevCount; ++i) {
        if (mPrevContexts[i].id == subject.id) {
            c = mPrevContexts[i]; // probe history: measured luma, target, last probe time
            track = mPrevTracks[i];
            previousWorld = mPrevContexts[i].world;
            seen = true;
            break;
        }
    }
    c.id = subject.id;
    c.world = subject.world;
    c.screenUv = subject.screenUv;
    c.outdoors = subject.outdoors ? clamp01OrZero(*subject.outdoors)
                                  : (mMask ? mMask->atWorld(subject.world.x, subject.world.y) : 0.0f);
    const float distance = std::hypot(subject.world.x - previousWorld.x, subject.world.y - previousWorld.y);
    c.moving = seen && mDt > 0.0f && distance > mSettings.probe.moveThreshold * mDt;
    track.forceProbe = track.wasMoving && !c.moving;
    track.wasMoving = c.moving;
}

bool SubjectTracker::addSubject(const Subject& subject) noexcept {
    if (subject.id == kCenterSubjectId || findCurrent(subject.id) != kNotFound) {
        return false;
    }
    if (mCount + 1 >= mContexts.size()) { // the last slot is kept for the centre subject
        if (!mWarnedFull) {
            mWarnedFull = true;
            try {
                warnOnce("subjects.full",
                         "subjects: more than subjects.maxSubjects registered in a frame; the "
                         "extra ones are ignored");
            } catch (...) {
                // Logging is best effort on the per-frame path.
            }
        }
        return false;
    }
    addEntry(subject);
    return true;
}

std::span<const ProbeRequest> SubjectTracker::scheduleProbes() noexcept {
    mSelection = selectSubject({mSubjects.data(), mCount}, mSettings.fallback);
    if (mSelection.source == SubjectSource::Center) {
        Subject centre;
        centre.id = kCenterSubjectId;
        centre.world = mViewCentre;
        centre.screenUv = glm::vec2(0.5f);
        addEntry(centre);
        mSelectedSlot = mCount - 1;
    } else {
        mSelectedSlot = mSelection.index;
    }
    const bool due = mScheduler.advance(mDt);
    mRequestCount = 0;
    for (std::size_t i = 0; i < mCount; ++i) {
        const SubjectContext& c = mContexts[i];
        const bool frozen = mSettings.probe.freezeWhileMoving && c.moving;
        if ((due && !frozen) || (mSettings.probe.freezeWhileMoving && mTracks[i].forceProbe) ||
            c.lastProbeAt < 0.0f) {
            mRequests[mRequestCount++] = {c.id, c.screenUv};
        }
    }
    return {mRequests.data(), mRequestCount};
}

void SubjectTracker::recordProbe(std::uint32_t id, float luma, float atSeconds) noexcept {
    const std::size_t i = findCurrent(id);
    if (i == kNotFound || !isMeterableLuminance(luma)) {
        return;
    }
    SubjectContext& c = mContexts[i];
    c.measuredLuma = applyLumaDeadband(c.measuredLuma, luma, mSettings.probe.deadbandEV);
    c.lastProbeAt = atSeconds;
}

void SubjectTracker::updateExposure(const AutoExposureSettings& autoExposure,
                                    float viewAppliedLog2) noexcept {
    const auto& coupling = mSettings.outdoorsCoupling;
    for (std::size_t i = 0; i < mCount; ++i) {
        SubjectContext& c = mContexts[i];
        c.appliedLog2 = viewAppliedLog2;
        if (!isMeterableLuminance(c.measuredLuma)) {
            continue;
        }
        // The base target, then the coupled (never looser) bounds: the same numbers as
        // exposureTargetLog2(outdoorsCoupledSettings(...)) without copying the settings per subject.
        float target = exposureTargetLog2(autoExposure, c.measuredLuma);
        if (coupling.enabled) {
            const float t = clamp01OrZero(c.outdoors);
            const float maxEV =
                autoExposure.maxEV + (std::min(autoExposure.maxEV, coupling.maxEV) - autoExposure.maxEV) * t;
            target = std::min(target, maxEV);
        }
        c.targetLog2 = target;
    }
}

const SubjectContext* SubjectTracker::contextForSubject(std::uint32_t id) const noexcept {
    const std::size_t i = findCurrent(id);
    return i == kNotFound ? nullptr : &mContexts[i];
}

const SubjectContext* SubjectTracker::subjectContext() const noexcept {
    if (mSelection.source == SubjectSource::None || mSelectedSlot >= mCount) {
        return nullptr;
    }
    return &mContexts[mSelectedSlot];
}

float SubjectTracker::outdoorsAtWorld(float x, float y) const noexcept {
    return mMask ? mMask->atWorld(x, y) : 0.0f;
}

} // namespace photopic
