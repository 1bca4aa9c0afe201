// Inputs that once escaped the core's parsers (found by fuzzing): settings JSON, --set text, motion tracks.

#include "core/Motion.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool finite(const Attitude& a) {
    return std::isfinite(a.pitch) && std::isfinite(a.roll) && std::isfinite(a.yaw);
}

TEST(SettingsReliability, NumberBeyondDoubleRangeIsAParseIssue) {
    Settings settings;
    const auto issues =
        readSettingsJson(R"({"version": 1, "postEffects": {"bloom": {"intensity": 1e400}}})", settings);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::ParseError);
    EXPECT_NE(issues[0].message.find("1e400"), std::string::npos) << issues[0].message;
}

TEST(SettingsReliability, OverrideThatIsNotUtf8IsReportedAsSuch) {
    Settings settings;
    try {
        applySettingsOverride(settings, "tonemapping.exposure=\xbe");
        FAIL() << "no SettingsError";
    } catch (const SettingsError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].code, SettingsIssueCode::InvalidUtf8);
        // The message names the text, with the bad byte escaped so the message itself is valid text.
        EXPECT_NE(std::string(e.what()).find("--set tonemapping.exposure=\\xbe"), std::string::npos)
            << e.what();
    }
}

TEST(SettingsReliability, Utf8Validation) {
    EXPECT_EQ(invalidUtf8Offset("plain ascii"), std::nullopt);
    EXPECT_EQ(invalidUtf8Offset("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"), std::nullopt);
    EXPECT_EQ(invalidUtf8Offset("a\xbe"), 1u);            // lone continuation byte
    EXPECT_EQ(invalidUtf8Offset("\xc0\xaf"), 0u);         // overlong '/'
    EXPECT_EQ(invalidUtf8Offset("ab\xed\xa0\x80"), 2u);   // surrogate U+D800
    EXPECT_EQ(invalidUtf8Offset("\xf4\x90\x80\x80"), 0u); // above U+10FFFF
    EXPECT_EQ(invalidUtf8Offset("\xe2\x82"), 0u);         // cut short
}

TEST(MotionReliability, AtIsDefinedForEveryTime) {
    const MotionTrack track(std::vector<MotionSample>{{.time = 0, .attitude = {.pitch = 0.1}},
                                                      {.time = 1, .attitude = {.pitch = 0.3}}});
    EXPECT_EQ(track.at(kNaN).pitch, 0.1); // NaN: the first sample (it once read past the end)
    EXPECT_EQ(track.at(-kInf).pitch, 0.1);
    EXPECT_EQ(track.at(kInf).pitch, 0.3);
    EXPECT_DOUBLE_EQ(track.at(0.5).pitch, 0.2);
}

TEST(MotionReliability, HugeFiniteValuesInterpolateWithoutOverflow) {
    const MotionTrack track = parseMotionCsv("time_s,pitch,roll,yaw\n"
                                             "0,0,0,-1.7976931348623157e308\n"
                                             "1,0,0,1.7976931348623157e308\n",
                                             "huge.csv");
    for (double t : {0.25, 0.5, 0.75}) {
        EXPECT_TRUE(finite(track.at(t))) << t;
    }
    EXPECT_NEAR(track.at(0.5).yaw, 0.0, 1e293);
}

TEST(MotionReliability, HugeFiniteTimesInterpolateWithoutOverflow) {
    const MotionTrack track = parseMotionCsv("time_s,pitch,roll,yaw\n"
                                             "-1.7e308,0,0,0\n"
                                             "1.7e308,1,2,3\n",
                                             "times.csv");
    const Attitude mid = track.at(0.0);
    EXPECT_TRUE(finite(mid));
    EXPECT_NEAR(mid.pitch, 0.5, 1e-9);
}

TEST(MotionReliability, TrackRejectsNonFiniteOrUnorderedSamples) {
    using Samples = std::vector<MotionSample>;
    EXPECT_THROW(MotionTrack(Samples{{.time = kNaN}}), std::invalid_argument);
    EXPECT_THROW(MotionTrack(Samples{{.time = 0, .attitude = {.roll = kInf}}}), std::invalid_argument);
    EXPECT_THROW(MotionTrack(Samples{{.time = 1}, {.time = 1}}), std::invalid_argument);
    EXPECT_THROW((void)parseMotionCsv("time_s,pitch,roll,yaw\n0,nan,0,0\n", "nan.csv"), MotionError);
    EXPECT_THROW((void)parseMotionCsv("time_s,pitch,roll,yaw\n1e400,0,0,0\n", "big.csv"), MotionError);
}

} // namespace
} // namespace photopic
