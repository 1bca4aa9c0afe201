#include "core/ExposurePlan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace photopic {
namespace {

constexpr float kDt = 1.0f / 24.0f;

AutoExposureSettings enabled() {
    AutoExposureSettings s;
    s.enabled = true;
    s.minEV = -10.0f;
    s.maxEV = 10.0f;
    return s;
}

/// A dark stretch, then a bright one: exposure adapts across the step.
std::vector<MeterRecord> stepRecords(std::int64_t first, int frames) {
    std::vector<MeterRecord> records;
    for (int i = 0; i < frames; ++i) {
        records.push_back({.frame = first + i, .reading = i < frames / 2 ? 0.02f : 2.0f});
    }
    return records;
}

TEST(ExposurePlan, IsTheControllerRunOverTheFramesInOrder) {
    const AutoExposureSettings s = enabled();
    const std::vector<MeterRecord> records = stepRecords(1001, 40);
    const std::vector<PlannedExposure> plan = planExposure(s, records, kDt, 0.5f, {});
    ASSERT_EQ(plan.size(), records.size());
    ExposureController controller(s);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const ExposureState& want = controller.update(records[i].reading, kDt, 0.5f);
        EXPECT_EQ(plan[i].frame, records[i].frame);
        EXPECT_EQ(plan[i].state.appliedLog2, want.appliedLog2) << "frame " << plan[i].frame;
        EXPECT_EQ(plan[i].state.exposure, want.exposure);
        EXPECT_EQ(plan[i].cut, i == 0);
    }
    // It adapted: 20 frames after the step the exposure is past half way from the dark target to the bright
    // one, not at it (the eye's lag).
    const float dark = exposureTargetLog2(s, 0.02f);
    const float bright = exposureTargetLog2(s, 2.0f);
    EXPECT_LT(plan.back().state.appliedLog2, 0.5f * (dark + bright));
    EXPECT_GT(plan.back().state.appliedLog2, bright + 0.05f);
    EXPECT_GT(plan[21].state.appliedLog2, plan.back().state.appliedLog2);
}

TEST(ExposurePlan, SnapsAtACut) {
    const AutoExposureSettings s = enabled();
    const std::vector<MeterRecord> records = stepRecords(0, 40);
    const std::int64_t cut = 20; // the first bright frame
    const std::vector<PlannedExposure> plan = planExposure(s, records, kDt, 0.0f, std::vector{cut});
    EXPECT_TRUE(plan[20].cut);
    EXPECT_FLOAT_EQ(plan[20].state.appliedLog2, exposureTargetLog2(s, 2.0f));
    const std::vector<PlannedExposure> smooth = planExposure(s, records, kDt, 0.0f, {});
    EXPECT_GT(smooth[20].state.appliedLog2, plan[20].state.appliedLog2 + 1.0f) << "without the cut it lags";
}

TEST(ExposurePlan, AFrameWithoutAReadingHoldsExposure) {
    const AutoExposureSettings s = enabled();
    std::vector<MeterRecord> records = stepRecords(0, 40);
    records[25].reading = 0.0f;
    const std::vector<PlannedExposure> plan = planExposure(s, records, kDt, 0.0f, {});
    EXPECT_EQ(plan[25].state.appliedLog2, plan[24].state.appliedLog2);
    EXPECT_EQ(plan[25].reading, 0.0f);
}

TEST(ExposurePlan, HistogramMeteringUsesTheBinsWithThePlansPercentiles) {
    AutoExposureSettings s = enabled();
    s.metering = MeteringMode::Histogram;
    MeterRecord r{.frame = 0, .reading = 123.0f}; // the reading at metering's percentiles is not used
    Histogram h;
    h.bins[100] = 50;
    h.bins[200] = 50;
    r.histogram = h;
    s.lowPercent = 0.0f;
    s.highPercent = 40.0f; // the darker half only
    EXPECT_FLOAT_EQ(planReading(s, r), std::exp2(histogramBinCentreLog2(100, s.histogramLog2Min,
                                                                        s.histogramLog2Max)));
    s.lowPercent = 60.0f;
    s.highPercent = 100.0f; // the brighter half only
    EXPECT_FLOAT_EQ(planReading(s, r), std::exp2(histogramBinCentreLog2(200, s.histogramLog2Min,
                                                                        s.histogramLog2Max)));
    r.histogram = Histogram{};
    EXPECT_EQ(planReading(s, r), 0.0f) << "an empty histogram is no reading";
}

TEST(ExposurePlan, PhysicalModeAdaptsAroundTheCamerasExposure) {
    const AutoExposureSettings s = enabled();
    std::vector<MeterRecord> records = stepRecords(0, 4);
    for (MeterRecord& r : records) {
        r.reading = 0.18f;
        r.cameraLog2 = -3.0f;
    }
    const std::vector<PlannedExposure> plan = planExposure(s, records, kDt, 0.0f, {});
    // The camera-exposed scene meters 0.18 * 2^-3: the correction is +3 EV, the total exposure 2^0.
    EXPECT_FLOAT_EQ(plan[0].state.appliedLog2, 3.0f);
    EXPECT_FLOAT_EQ(plan[0].state.exposure, 1.0f);
}

TEST(ExposurePlan, MeteringDescriptionsTellModesAndParametersApart) {
    AutoExposureSettings a;
    AutoExposureSettings b;
    EXPECT_EQ(meteringDescription(a), meteringDescription(b));
    b.metering = MeteringMode::Spot;
    EXPECT_NE(meteringDescription(a), meteringDescription(b));
    AutoExposureSettings c = b;
    c.spot.radius = 0.2f;
    EXPECT_NE(meteringDescription(b), meteringDescription(c));
    a.keyValue = 0.5f; // an adaptation parameter, not metering's
    EXPECT_EQ(meteringDescription(a), meteringDescription(AutoExposureSettings{}));
}

} // namespace
} // namespace photopic
