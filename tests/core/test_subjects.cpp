// Subjects: selection rule, the outdoors mask's V-flip contract, probe throttling in frame time,
// multi-tap probe, luma deadband, outdoors coupling, contexts, and no allocation per frame.

#include "core/ExposureController.h"
#include "core/Subjects.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

// Counts heap allocations while gAllocCounting is set (the allocation-free test); otherwise plain malloc.
namespace {
std::atomic<bool> gAllocCounting{false};
std::atomic<int> gAllocCount{0};
} // namespace

void* operator new(std::size_t size) {
    if (gAllocCounting.load()) {
        gAllocCount.fetch_add(1);
    }
    if (void* p = std::malloc(size ? size : 1)) {
        return p;
    }
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

namespace photopic {
namespace {

Subject subject(std::uint32_t id, bool controlled = false, bool own = false) {
    Subject s;
    s.id = id;
    s.controlled = controlled;
    s.ownCharacter = own;
    return s;
}

// ---- selection rule
// -------------------------------------------------------------------------------------------

TEST(Subjects, SelectsFirstControlledThenOwnCharacterThenFallback) {
    std::vector<Subject> s = {subject(1), subject(2, false, true), subject(3, true), subject(4, true)};
    auto sel = selectSubject(s, SubjectFallback::None);
    EXPECT_EQ(sel.source, SubjectSource::Controlled);
    EXPECT_EQ(sel.index, 2u); // the first controlled one, even after an own character

    s[2].controlled = s[3].controlled = false;
    sel = selectSubject(s, SubjectFallback::Center);
    EXPECT_EQ(sel.source, SubjectSource::OwnCharacter);
    EXPECT_EQ(sel.index, 1u);

    s[1].ownCharacter = false;
    EXPECT_EQ(selectSubject(s, SubjectFallback::None).source, SubjectSource::None);
    EXPECT_EQ(selectSubject(s, SubjectFallback::Center).source, SubjectSource::Center);
    EXPECT_EQ(selectSubject({}, SubjectFallback::None).source, SubjectSource::None);
}

TEST(Subjects, TrackerFollowsTheRuleAndTheCentreFallback) {
    SubjectSettings settings;
    SubjectTracker tracker(settings);
    tracker.beginFrame(1.0f / 30.0f);
    tracker.addSubject(subject(7));
    tracker.addSubject(subject(8, false, true));
    tracker.scheduleProbes();
    ASSERT_NE(tracker.subjectContext(), nullptr);
    EXPECT_EQ(tracker.subjectContext()->id, 8u);

    tracker.beginFrame(1.0f / 30.0f);
    tracker.addSubject(subject(7));
    tracker.scheduleProbes();
    EXPECT_EQ(tracker.subjectContext(), nullptr); // fallback none: no subject, exposure holds

    settings.fallback = SubjectFallback::Center;
    tracker.setSettings(settings);
    tracker.beginFrame(1.0f / 30.0f, {123.0f, 45.0f});
    tracker.addSubject(subject(7));
    const auto requests = tracker.scheduleProbes();
    const SubjectContext* c = tracker.subjectContext();
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->id, kCenterSubjectId);
    EXPECT_EQ(c->screenUv, glm::vec2(0.5f));
    EXPECT_EQ(c->world, glm::vec2(123.0f, 45.0f));
    EXPECT_EQ(requests.size(), 2u); // both never probed: probed at once
}

// ---- outdoors mask: its coordinate contract
// ------------------------------------------------------------

TEST(OutdoorsMask, WorldToUvFlipsV) {
    const SceneRect rect{100.0f, 50.0f, 400.0f, 200.0f};
    EXPECT_EQ(worldToMaskUv(rect, {100.0f, 50.0f}), glm::vec2(0.0f, 1.0f));  // top-left of the map: v = 1
    EXPECT_EQ(worldToMaskUv(rect, {500.0f, 250.0f}), glm::vec2(1.0f, 0.0f)); // bottom-right: v = 0
    EXPECT_EQ(worldToMaskUv(rect, {300.0f, 100.0f}), glm::vec2(0.5f, 0.75f));
}

TEST(OutdoorsMask, RowZeroIsTheBottomOfTheMap) {
    // 2x2 mask: row 0 (v = 0, the bottom of the map, large world y) open sky, row 1 (the top) roofed.
    const OutdoorsMask mask(2, 2, {255, 255, 0, 0}, {0.0f, 0.0f, 100.0f, 100.0f});
    EXPECT_FLOAT_EQ(mask.atWorld(10.0f, 90.0f), 1.0f); // bottom of the map: outdoors
    EXPECT_FLOAT_EQ(mask.atWorld(10.0f, 10.0f), 0.0f); // top: under the roof
    EXPECT_FLOAT_EQ(mask.atWorld(50.0f, 50.0f), 0.5f); // halfway between texel centres: bilinear
    EXPECT_FLOAT_EQ(mask.atWorld(50.0f, 37.5f), 0.25f);
    EXPECT_FLOAT_EQ(mask.atWorld(-1000.0f, 1e6f), 1.0f); // clamped to the edge texels
}

TEST(OutdoorsMask, BilinearBetweenTexelCentresHorizontally) {
    const OutdoorsMask mask(4, 1, {0, 0, 255, 255}, {0.0f, 0.0f, 4.0f, 1.0f});
    EXPECT_FLOAT_EQ(mask.sampleUv({0.5f, 0.5f}), 0.5f);
    EXPECT_FLOAT_EQ(mask.sampleUv({0.375f, 0.5f}), 0.0f);   // texel 1 centre
    EXPECT_FLOAT_EQ(mask.sampleUv({0.4375f, 0.5f}), 0.25f); // a quarter towards texel 2
    EXPECT_FLOAT_EQ(mask.sampleUv({0.625f, 0.5f}), 1.0f);
    EXPECT_THROW(OutdoorsMask(3, 2, {0, 0}, {}), std::invalid_argument);
}

TEST(OutdoorsMask, TrackerReadsMaskWhenSubjectBringsNoValue) {
    const OutdoorsMask mask(2, 2, {255, 255, 0, 0}, {0.0f, 0.0f, 100.0f, 100.0f});
    SubjectTracker tracker;
    tracker.setOutdoorsMask(&mask);
    tracker.beginFrame(0.1f);
    Subject a = subject(1, true);
    a.world = {10.0f, 95.0f};
    Subject b = subject(2);
    b.world = {10.0f, 95.0f};
    b.outdoors = 0.25f; // the host's own value wins
    tracker.addSubject(a);
    tracker.addSubject(b);
    tracker.scheduleProbes();
    EXPECT_FLOAT_EQ(tracker.contextForSubject(1)->outdoors, 1.0f);
    EXPECT_FLOAT_EQ(tracker.contextForSubject(2)->outdoors, 0.25f);
    EXPECT_FLOAT_EQ(tracker.outdoorsAtWorld(10.0f, 5.0f), 0.0f);
    tracker.setOutdoorsMask(nullptr);
    EXPECT_FLOAT_EQ(tracker.outdoorsAtWorld(10.0f, 95.0f), 0.0f);
}

// ---- probe schedule
// -------------------------------------------------------------------------------------------

std::vector<int> dueFrames(ProbeScheduler& s, const std::vector<float>& dts) {
    std::vector<int> frames;
    for (std::size_t i = 0; i < dts.size(); ++i) {
        if (s.advance(dts[i])) {
            frames.push_back(int(i));
        }
    }
    return frames;
}

TEST(ProbeSchedule, FiveHertzAtThirtyFpsIsEverySixthFrame) {
    ProbeScheduler s(5.0f);
    const auto frames = dueFrames(s, std::vector<float>(3000, 1.0f / 30.0f));
    ASSERT_EQ(frames.size(), 500u);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        EXPECT_EQ(frames[i], int(6 * i)) << i;
    }
}

TEST(ProbeSchedule, TenHertzAtSixtyAndFifteenFps) {
    ProbeScheduler a(10.0f);
    EXPECT_EQ(dueFrames(a, std::vector<float>(60, 1.0f / 60.0f)),
              (std::vector<int>{0, 6, 12, 18, 24, 30, 36, 42, 48, 54}));
    // Frames longer than the period: 10 probes per second of frame time still, at most one per frame.
    ProbeScheduler b(10.0f);
    EXPECT_EQ(dueFrames(b, std::vector<float>(7, 1.0f / 15.0f)), (std::vector<int>{0, 2, 3, 5, 6}));
}

TEST(ProbeSchedule, VariableFrameTimeCountsFrameTimeNotFrames) {
    // 5 Hz: due when 0.2 s of frame time has accumulated since the last due frame; the remainder carries.
    ProbeScheduler s(5.0f);
    const std::vector<float> dts = {0.0f,  0.05f, 0.1f, 0.06f, 0.01f, 0.15f,
                                    0.02f, 0.0f,  0.3f, 0.01f, 1.0f,  0.2f};
    // accumulated:             start  .05   .15   .21*(->.01) .02 .17  .19  .19 .49*(->.29->0, no burst) .01
    //                          1.01*(->0.81->0) .2*
    EXPECT_EQ(dueFrames(s, dts), (std::vector<int>{0, 3, 8, 10, 11}));
}

TEST(ProbeSchedule, NegativeAndNaNFrameTimeCountAsZero) {
    ProbeScheduler s(5.0f);
    EXPECT_TRUE(s.advance(0.0f));
    EXPECT_FALSE(s.advance(-1.0f));
    EXPECT_FALSE(s.advance(std::nanf("")));
    EXPECT_TRUE(s.advance(0.2f));
    s.reset();
    EXPECT_TRUE(s.advance(0.0f));
}

TEST(ProbeSchedule, TrackerProbesEverySixFramesAndFreezesWhileMoving) {
    SubjectSettings settings;
    settings.probe.hz = 5.0f;
    settings.probe.freezeWhileMoving = true;
    settings.probe.moveThreshold = 10.0f; // world units / s
    SubjectTracker tracker(settings);
    const float dt = 1.0f / 30.0f;
    std::vector<int> probed;
    for (int f = 0; f < 60; ++f) {
        Subject s = subject(1, true);
        // Walks 2 units per frame (60 units/s) over frames 10..29, still otherwise.
        s.world = {2.0f * float(std::clamp(f, 10, 30)), 0.0f};
        tracker.beginFrame(dt);
        tracker.addSubject(s);
        const auto requests = tracker.scheduleProbes();
        if (!requests.empty()) {
            probed.push_back(f);
        }
        for (const ProbeRequest& r : requests) {
            tracker.recordProbe(r.id, 0.1f, tracker.time());
        }
        EXPECT_EQ(tracker.subjectContext()->moving, f > 10 && f <= 30) << f;
    }
    // 0, 6: still; 12, 18, 24, 30 frozen (moving); 31: forced when it stops; 36, 42, 48, 54 on schedule.
    EXPECT_EQ(probed, (std::vector<int>{0, 6, 31, 36, 42, 48, 54}));
}

// ---- multi-tap probe
// ------------------------------------------------------------------------------------------

ImageF greyImage(int w, int h, float v) {
    ImageF image(w, h, v);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 1.0f;
    }
    return image;
}

void setGrey(ImageF& image, int x, int y, float v) {
    float* p = image.at(x, y);
    p[0] = p[1] = p[2] = v;
}

TEST(Probe, ProbeTapsAreTheFirstNineSpotTapsAndClampThere) {
    const AutoExposureSettings::SpotMetering disc{.u = 0.3f, .v = 0.6f, .radius = 0.25f, .taps = 13};
    for (int tap = 0; tap < kProbeTapCount; ++tap) {
        const TexelCoord probe = probeTapTexel({0.3f, 0.6f}, tap, 0.25f, 64, 48);
        const TexelCoord spot = spotTapTexel(disc, tap, 64, 48);
        EXPECT_EQ(probe.x, spot.x) << tap;
        EXPECT_EQ(probe.y, spot.y) << tap;
    }
    // The probe shader's table has nine entries: tap 12 (a spot rim tap) must read tap 8, not the rim.
    const TexelCoord beyond = probeTapTexel({0.3f, 0.6f}, 12, 0.25f, 64, 48);
    const TexelCoord last = spotTapTexel(disc, 8, 64, 48);
    EXPECT_EQ(beyond.x, last.x);
    EXPECT_EQ(beyond.y, last.y);
}

TEST(Probe, TapTexelsFollowTheRadiusInImageHeights) {
    // 100x50 image, radius 0.2 image heights = 10 px; tap 1 is +0.5 radius = +5 px right.
    const TexelCoord c = probeTapTexel({0.5f, 0.5f}, 0, 0.2f, 100, 50);
    EXPECT_EQ(c.x, 50);
    EXPECT_EQ(c.y, 25);
    const TexelCoord right = probeTapTexel({0.5f, 0.5f}, 1, 0.2f, 100, 50);
    EXPECT_EQ(right.x, 55);
    EXPECT_EQ(right.y, 25);
    const TexelCoord downRight = probeTapTexel({0.5f, 0.5f}, 5, 0.2f, 100, 50);
    EXPECT_EQ(downRight.x, 55);
    EXPECT_EQ(downRight.y, 30);
    const TexelCoord clamped = probeTapTexel({1.0f, 0.0f}, 7, 0.2f, 100, 50); // (+0.5, -0.5): off the corner
    EXPECT_EQ(clamped.x, 99);
    EXPECT_EQ(clamped.y, 0);
}

TEST(Probe, AveragesLuminanceArithmeticallyOverTheTaps) {
    ImageF image = greyImage(100, 50, 1.0f);
    setGrey(image, 50, 25, 10.0f); // a torch highlight right at the centre
    EXPECT_FLOAT_EQ(probeImage(image, {0.5f, 0.5f}, 1, 0.2f), 10.0f);
    EXPECT_FLOAT_EQ(probeImage(image, {0.5f, 0.5f}, 5, 0.2f), (10.0f + 4.0f) / 5.0f);
    EXPECT_FLOAT_EQ(probeImage(image, {0.5f, 0.5f}, 9, 0.2f), (10.0f + 8.0f) / 9.0f);
    setGrey(image, 55, 30, 0.0f); // tap 5 (+0.5, +0.5)
    EXPECT_FLOAT_EQ(probeImage(image, {0.5f, 0.5f}, 9, 0.2f), (10.0f + 7.0f) / 9.0f);
    setGrey(image, 45, 25, std::nanf("")); // tap 2: not finite counts as 0
    EXPECT_FLOAT_EQ(probeImage(image, {0.5f, 0.5f}, 5, 0.2f), (10.0f + 3.0f) / 5.0f);
    EXPECT_EQ(probeImage(ImageF{}, {0.5f, 0.5f}, 5, 0.2f), 0.0f);
    EXPECT_EQ(probeImage(image, {std::nanf(""), 0.5f}, 5, 0.2f), 0.0f);
}

TEST(Probe, UsesRec709Luma) {
    ImageF image = greyImage(4, 4, 0.0f);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            image.at(x, y)[1] = 1.0f; // pure green
        }
    }
    EXPECT_NEAR(probeImage(image, {0.5f, 0.5f}, 9, 0.1f), 0.7152f, 1e-6f);
}

// ---- deadband
// -------------------------------------------------------------------------------------------------

TEST(Hysteresis, SmallLumaChangesAreIgnored) {
    EXPECT_EQ(applyLumaDeadband(0.0f, 0.5f, 0.05f), 0.5f);  // first reading is taken
    EXPECT_EQ(applyLumaDeadband(1.0f, 1.03f, 0.05f), 1.0f); // 0.043 EV: inside the deadband
    EXPECT_EQ(applyLumaDeadband(1.0f, 0.97f, 0.05f), 1.0f);
    EXPECT_EQ(applyLumaDeadband(1.0f, 1.04f, 0.05f), 1.04f); // 0.057 EV: taken
    EXPECT_EQ(applyLumaDeadband(1.0f, 0.5f, 0.05f), 0.5f);
    EXPECT_EQ(applyLumaDeadband(1.0f, std::nanf(""), 0.05f), 1.0f);
    EXPECT_EQ(applyLumaDeadband(1.0f, 0.0f, 0.05f), 1.0f);
    EXPECT_EQ(applyLumaDeadband(1.0f, 1.0001f, 0.0f), 1.0001f); // no deadband: every change
}

TEST(Hysteresis, JitterDoesNotMoveTheContextOrMakeExposureHunt) {
    SubjectSettings settings;
    settings.probe.hz = 240.0f; // every frame
    SubjectTracker tracker(settings);
    AutoExposureSettings ae;
    ae.enabled = true;
    ExposureController controller(ae);
    float firstTarget = 0.0f;
    for (int f = 0; f < 200; ++f) {
        tracker.beginFrame(1.0f / 60.0f);
        tracker.addSubject(subject(1, true));
        for (const ProbeRequest& r : tracker.scheduleProbes()) {
            // +-2% flicker around 0.1: inside a 0.05 EV deadband.
            tracker.recordProbe(r.id, 0.1f * (1.0f + 0.02f * std::sin(float(f))), tracker.time());
        }
        const SubjectContext* c = tracker.subjectContext();
        controller.update(c->measuredLuma, 1.0f / 60.0f);
        tracker.updateExposure(ae, controller.state().appliedLog2);
        if (f == 0) {
            firstTarget = c->targetLog2;
        }
        EXPECT_EQ(c->targetLog2, firstTarget) << f;
        EXPECT_EQ(controller.state().appliedLog2, firstTarget) << f;
    }
}

// ---- outdoors coupling
// ----------------------------------------------------------------------------------------

TEST(OutdoorsCoupling, OffByDefaultAndBlendedByOutdoors) {
    AutoExposureSettings base;
    base.minEV = -2.0f;
    base.maxEV = 2.0f;
    SubjectSettings::OutdoorsCoupling c;
    EXPECT_FALSE(c.enabled);
    AutoExposureSettings s = outdoorsCoupledSettings(base, c, 1.0f);
    EXPECT_EQ(s.maxEV, 2.0f);
    EXPECT_EQ(s.tauDarken, base.tauDarken);

    c.enabled = true;
    c.maxEV = 1.0f;
    c.speedScale = 2.0f;
    s = outdoorsCoupledSettings(base, c, 0.0f); // indoors: unchanged
    EXPECT_EQ(s.maxEV, 2.0f);
    EXPECT_EQ(s.tauBrighten, base.tauBrighten);
    s = outdoorsCoupledSettings(base, c, 1.0f); // outdoors: tighter and twice as fast
    EXPECT_FLOAT_EQ(s.maxEV, 1.0f);
    EXPECT_FLOAT_EQ(s.minEV, -2.0f);
    EXPECT_FLOAT_EQ(s.tauBrighten, base.tauBrighten / 2.0f);
    EXPECT_FLOAT_EQ(s.tauDarken, base.tauDarken / 2.0f);
    EXPECT_FLOAT_EQ(s.speedUp, base.speedUp * 2.0f);
    s = outdoorsCoupledSettings(base, c, 0.5f);
    EXPECT_FLOAT_EQ(s.maxEV, 1.5f);
    EXPECT_FLOAT_EQ(s.tauDarken, base.tauDarken / 1.5f);
    c.maxEV = 5.0f; // never looser than the base
    EXPECT_FLOAT_EQ(outdoorsCoupledSettings(base, c, 1.0f).maxEV, 2.0f);
    c.maxEV = -4.0f; // below minEV: minEV follows so the range stays valid
    s = outdoorsCoupledSettings(base, c, 1.0f);
    EXPECT_FLOAT_EQ(s.maxEV, -4.0f);
    EXPECT_FLOAT_EQ(s.minEV, -4.0f);
    EXPECT_EQ(outdoorsCoupledSettings(base, c, std::nanf("")).maxEV, 2.0f); // NaN counts as indoors
}

TEST(OutdoorsCoupling, TrackerTargetsMatchCoupledSettings) {
    SubjectSettings settings;
    settings.outdoorsCoupling.enabled = true;
    settings.outdoorsCoupling.maxEV = 0.5f;
    SubjectTracker tracker(settings);
    AutoExposureSettings ae;
    tracker.beginFrame(0.1f);
    for (std::uint32_t id = 1; id <= 3; ++id) {
        Subject s = subject(id, id == 1);
        s.outdoors = 0.5f * float(id - 1);
        tracker.addSubject(s);
    }
    for (const ProbeRequest& r : tracker.scheduleProbes()) {
        tracker.recordProbe(r.id, 0.02f, 0.0f); // dark: target 3.17 EV before clamping
    }
    tracker.updateExposure(ae, 0.7f);
    for (const SubjectContext& c : tracker.contexts()) {
        const float expected =
            exposureTargetLog2(outdoorsCoupledSettings(ae, settings.outdoorsCoupling, c.outdoors), 0.02f);
        EXPECT_FLOAT_EQ(c.targetLog2, expected) << c.id;
        EXPECT_EQ(c.appliedLog2, 0.7f);
    }
    EXPECT_FLOAT_EQ(tracker.contextForSubject(1)->targetLog2, 2.0f);
    EXPECT_FLOAT_EQ(tracker.contextForSubject(3)->targetLog2, 0.5f);
}

// ---- contexts
// -------------------------------------------------------------------------------------------------

TEST(SubjectContexts, HoldContextFieldsAndKeepProbeHistoryById) {
    SubjectSettings settings;
    settings.probe.hz = 5.0f;
    SubjectTracker tracker(settings);
    AutoExposureSettings ae;
    const float dt = 1.0f / 30.0f;
    for (int f = 0; f < 8; ++f) {
        tracker.beginFrame(dt);
        Subject a = subject(10);
        a.world = {float(f), 2.0f};
        a.screenUv = {0.25f, 0.75f};
        Subject b = subject(20, true);
        b.outdoors = 1.0f;
        if (f != 3) { // subject 10 is missing for one frame: its context disappears, then starts afresh
            tracker.addSubject(a);
        }
        tracker.addSubject(b);
        for (const ProbeRequest& r : tracker.scheduleProbes()) {
            tracker.recordProbe(r.id, r.id == 10 ? 0.09f : 1.44f, tracker.time());
        }
        tracker.updateExposure(ae, -1.0f);
        if (f == 3) {
            EXPECT_EQ(tracker.contextForSubject(10), nullptr);
        }
    }
    const SubjectContext* a = tracker.contextForSubject(10);
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->world, glm::vec2(7.0f, 2.0f));
    EXPECT_EQ(a->screenUv, glm::vec2(0.25f, 0.75f));
    EXPECT_FLOAT_EQ(a->measuredLuma, 0.09f);
    EXPECT_FLOAT_EQ(a->targetLog2, 1.0f); // log2(0.18 / 0.09)
    EXPECT_FLOAT_EQ(a->appliedLog2, -1.0f);
    EXPECT_NEAR(a->lastProbeAt, 7.0f * dt, 1e-6f); // re-registered at frame 4 (probed at once), then frame 6
    const SubjectContext* b = tracker.subjectContext();
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->id, 20u);
    EXPECT_FLOAT_EQ(b->targetLog2, -2.0f);         // log2(0.18 / 1.44) = -3, clamped to minEV
    EXPECT_NEAR(b->lastProbeAt, 7.0f * dt, 1e-6f); // probed on frames 0 and 6 of frame time 1..8 dt
    EXPECT_EQ(tracker.contextForSubject(99), nullptr);
}

TEST(SubjectContexts, IgnoresDuplicatesAndOverflow) {
    SubjectSettings settings;
    settings.maxSubjects = 3;
    SubjectTracker tracker(settings);
    EXPECT_EQ(tracker.capacity(), 4u); // + the centre slot
    tracker.beginFrame(0.1f);
    EXPECT_TRUE(tracker.addSubject(subject(1)));
    EXPECT_FALSE(tracker.addSubject(subject(1)));
    EXPECT_FALSE(tracker.addSubject(subject(kCenterSubjectId)));
    EXPECT_TRUE(tracker.addSubject(subject(2)));
    EXPECT_TRUE(tracker.addSubject(subject(3)));
    EXPECT_FALSE(tracker.addSubject(subject(4)));
    EXPECT_EQ(tracker.contexts().size(), 3u);
}

TEST(SubjectContexts, PerFrameCallsDoNotAllocate) {
    SubjectSettings settings;
    settings.maxSubjects = 16;
    settings.fallback = SubjectFallback::Center;
    settings.probe.freezeWhileMoving = true;
    const OutdoorsMask mask(2, 2, {255, 255, 0, 0}, {0.0f, 0.0f, 100.0f, 100.0f});
    SubjectTracker tracker(settings);
    tracker.setOutdoorsMask(&mask);
    AutoExposureSettings ae;
    // One overflowing frame first: its warning is logged once, through the allocating log.
    tracker.beginFrame(1.0f / 60.0f);
    for (std::uint32_t i = 1; i <= 20; ++i) {
        tracker.addSubject(subject(i));
    }
    const SubjectContext* storage = tracker.contexts().data();
    const std::size_t capacity = tracker.capacity();
    gAllocCount = 0;
    gAllocCounting = true;
    for (int f = 0; f < 300; ++f) {
        tracker.beginFrame(1.0f / 60.0f, {50.0f, 50.0f});
        const int n = f % 20; // 0..19 subjects: empty frames (centre fallback) and overflow both happen
        for (int i = 0; i < n; ++i) {
            Subject s = subject(std::uint32_t(i + 1), i == 5);
            s.world = {float((f * i) % 100), float(i)};
            tracker.addSubject(s);
        }
        for (const ProbeRequest& r : tracker.scheduleProbes()) {
            tracker.recordProbe(r.id, 0.1f + 0.01f * float(r.id % 7), tracker.time());
        }
        tracker.updateExposure(ae, 0.0f);
        (void)tracker.subjectContext();
        (void)tracker.contextForSubject(3);
        (void)tracker.outdoorsAtWorld(1.0f, 2.0f);
    }
    gAllocCounting = false;
    EXPECT_EQ(gAllocCount.load(), 0);
    EXPECT_EQ(tracker.contexts().data(), storage);
    EXPECT_EQ(tracker.capacity(), capacity);
}

} // namespace
} // namespace photopic
