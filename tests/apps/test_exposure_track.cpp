#include "common/ExposureTrack.h"

#include "common/TempFolder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace photopic {
namespace {

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no error)";
}

MeterRecord record(std::int64_t frame, float reading, bool histogram) {
    MeterRecord r{.frame = frame, .reading = reading, .cameraLog2 = -0.25f, .minLuminance = 1e-3f,
                  .maxLuminance = 40.0f};
    if (histogram) {
        Histogram h;
        h.bins[7] = std::uint32_t(frame) + 1;
        h.bins[255] = 3;
        r.histogram = h;
    }
    return r;
}

TEST(ExposureTrack, MeterFilesRoundTripEveryValue) {
    const test::TempFolder tmp;
    for (const bool histogram : {false, true}) {
        const auto path = tmp.path() / (histogram ? "h.csv" : "a.csv");
        std::string text = meterCsvHeader("histogram histogramLog2Min=-12", histogram);
        const MeterRecord a = record(1001, 0.123456789f, histogram);
        const MeterRecord b = record(1002, 3.0e-7f, histogram);
        text += meterCsvRow(a, 1, 2, 3) + meterCsvRow(b, 1, 2, 3);
        writeText(path, text);
        const MeterFile file = readMeterCsv(path);
        EXPECT_EQ(file.metering, "histogram histogramLog2Min=-12");
        ASSERT_EQ(file.records.size(), 2u);
        EXPECT_EQ(file.records[0].frame, 1001);
        EXPECT_EQ(file.records[0].reading, a.reading) << "floats written so they read back exactly";
        EXPECT_EQ(file.records[1].reading, b.reading);
        EXPECT_EQ(file.records[0].cameraLog2, -0.25f);
        EXPECT_EQ(file.records[1].histogram.has_value(), histogram);
        if (histogram) {
            EXPECT_EQ(file.records[1].histogram->bins, b.histogram->bins);
        }
    }
}

TEST(ExposureTrack, MergedChunksAreOneSequenceInFrameOrder) {
    const std::vector<MeterFile> files = {
        {.metering = "average", .records = {record(12, 1, false), record(13, 2, false)}},
        {.metering = "average",
         .records = {record(10, 3, false), record(11, 4, false), record(12, 1, false)}}};
    const MeterFile merged = mergeMeterFiles({"b.csv", "a.csv"}, files);
    ASSERT_EQ(merged.records.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(merged.records[i].frame, 10 + std::int64_t(i));
    }
    std::vector<MeterFile> clash = files;
    clash[1].records[2].reading = 1.5f;
    EXPECT_NE(errorOf([&] { (void)mergeMeterFiles({"b.csv", "a.csv"}, clash); })
                  .find("frame 12 is in b.csv and in a.csv with different readings"),
              std::string::npos);
    std::vector<MeterFile> modes = files;
    modes[1].metering = "spot u=0.5";
    EXPECT_NE(errorOf([&] { (void)mergeMeterFiles({"b.csv", "a.csv"}, modes); }).find("same settings"),
              std::string::npos);
}

TEST(ExposureTrack, TracksRoundTripAndFindTheirFrames) {
    const test::TempFolder tmp;
    std::vector<PlannedExposure> plan(3);
    for (int i = 0; i < 3; ++i) {
        plan[std::size_t(i)].frame = 100 + i * 2;
        plan[std::size_t(i)].cut = i == 0;
        plan[std::size_t(i)].state.appliedLog2 = -0.1f * float(i) - 1.0f / 3.0f;
    }
    const auto path = tmp.path() / "t.csv";
    writeText(path, exposureTrackCsv(plan, 23.976f, "average"));
    const ExposureTrack track = readExposureTrack(path);
    EXPECT_FLOAT_EQ(track.fps, 23.976f);
    EXPECT_EQ(track.metering, "average");
    ASSERT_NE(track.find(102), nullptr);
    EXPECT_EQ(track.find(102)->appliedLog2, plan[1].state.appliedLog2);
    EXPECT_TRUE(track.find(100)->cut);
    EXPECT_FALSE(track.find(104)->cut);
    EXPECT_EQ(track.find(101), nullptr);
    EXPECT_EQ(track.find(99), nullptr);
}

TEST(ExposureTrack, BadFilesNameTheFileLineAndColumn) {
    const test::TempFolder tmp;
    const auto path = tmp.path() / "bad.csv";
    const std::string header = meterCsvHeader("average", false);
    writeText(path, header + "7,0.5,0,0,1,0,0,0,0\n8,abc,0,0,1,0,0,0,0\n");
    EXPECT_NE(errorOf([&] { (void)readMeterCsv(path); }).find("bad.csv:4: column reading: \"abc\" is not a number"),
              std::string::npos);
    writeText(path, header + "7,0.5,0,0,1,0,0,0\n");
    EXPECT_NE(errorOf([&] { (void)readMeterCsv(path); }).find("bad.csv:3: 8 fields where the header has 9"),
              std::string::npos);
    writeText(path, header + "7,0.5,0,0,1,0,0,0,0\n7,0.5,0,0,1,0,0,0,0\n");
    EXPECT_NE(errorOf([&] { (void)readMeterCsv(path); }).find("frames must increase"), std::string::npos);
    writeText(path, header + "7,inf,0,0,1,0,0,0,0\n");
    EXPECT_NE(errorOf([&] { (void)readMeterCsv(path); }).find("not finite"), std::string::npos);
    writeText(path, "frame,reading\n");
    EXPECT_NE(errorOf([&] { (void)readMeterCsv(path); }).find("not a file of this kind"), std::string::npos);
    EXPECT_NE(errorOf([&] { (void)readExposureTrack(tmp.path() / "none.csv"); }).find("cannot be read"),
              std::string::npos);
    writeText(path, exposureTrackCsv({}, 24.0f, "average"));
    EXPECT_NE(errorOf([&] { (void)readExposureTrack(path); }).find("holds no frame"), std::string::npos);
}

} // namespace
} // namespace photopic
