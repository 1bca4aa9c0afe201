#include "common/SequencePattern.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace photopic {
namespace {

FramePattern parsed(std::string_view name) {
    const std::optional<FramePattern> p = parseFramePattern(name);
    EXPECT_TRUE(p.has_value()) << name;
    return p.value_or(FramePattern{});
}

TEST(SequencePattern, PrintfZeroPadded) {
    const FramePattern p = parsed("f%04d.exr");
    EXPECT_EQ(p.prefix, "f");
    EXPECT_EQ(p.suffix, ".exr");
    EXPECT_EQ(p.width, 4);
    EXPECT_EQ(p.name(7), "f0007.exr");
    EXPECT_EQ(p.name(12345), "f12345.exr"); // wider than the padding, as printf writes it
}

TEST(SequencePattern, HashesAreDigitsAndAtIsUnpadded) {
    EXPECT_EQ(parsed("f.####.exr").name(42), "f.0042.exr");
    EXPECT_EQ(parsed("f.#.exr").name(42), "f.42.exr");
    EXPECT_EQ(parsed("f@.png").name(42), "f42.png");
    EXPECT_EQ(parsed("f@@@.png").name(7), "f007.png");
    EXPECT_EQ(parsed("f%d.png").name(9), "f9.png");
}

TEST(SequencePattern, PercentPercentIsLiteral) {
    const FramePattern p = parsed("100%%_%03d.png");
    EXPECT_EQ(p.name(5), "100%_005.png");
    EXPECT_FALSE(parseFramePattern("100%%.png").has_value());
}

TEST(SequencePattern, NoTokenIsNoPattern) {
    EXPECT_FALSE(parseFramePattern("frame_0001.exr").has_value());
}

TEST(SequencePattern, BadTokensAreRefused) {
    EXPECT_THROW((void)parseFramePattern("f%04d_%d.exr"), std::invalid_argument); // two numbers
    EXPECT_THROW((void)parseFramePattern("f####@.exr"), std::invalid_argument);
    EXPECT_THROW((void)parseFramePattern("f%s.exr"), std::invalid_argument);
    EXPECT_THROW((void)parseFramePattern("f%4d.exr"), std::invalid_argument); // space padded: not a name
    EXPECT_THROW((void)parseFramePattern("f%019d.exr"), std::invalid_argument);
}

TEST(SequencePattern, MatchesOnlyTheNamesItWrites) {
    const FramePattern padded = parsed("f%04d.exr");
    EXPECT_EQ(padded.match("f0012.exr"), 12);
    EXPECT_EQ(padded.match("f12345.exr"), 12345);
    EXPECT_FALSE(padded.match("f12.exr").has_value());
    EXPECT_FALSE(padded.match("f00012.exr").has_value());
    EXPECT_FALSE(padded.match("f0012.png").has_value());
    EXPECT_FALSE(padded.match("f.exr").has_value());
    EXPECT_FALSE(padded.match("f00a2.exr").has_value());
    const FramePattern unpadded = parsed("f@.exr");
    EXPECT_EQ(unpadded.match("f9.exr"), 9);
    EXPECT_EQ(unpadded.match("f0.exr"), 0);
    EXPECT_FALSE(unpadded.match("f09.exr").has_value());
}

TEST(SequencePattern, FrameRanges) {
    const FrameRange r = parseFrameRange("1001-1100");
    EXPECT_EQ(r.first, 1001);
    EXPECT_EQ(r.last, 1100);
    EXPECT_EQ(parseFrameRange("7").first, 7);
    EXPECT_EQ(parseFrameRange("7").last, 7);
    for (const char* bad : {"", "-", "5-", "-5", "a-b", "10-9", "1-2-3", "1 - 2"}) {
        EXPECT_THROW((void)parseFrameRange(bad), std::invalid_argument) << bad;
    }
}

const std::vector<std::string> kFolder = {"f1000.exr", "f0999.exr", "f1002.exr", "f1001.exr",
                                          "f0012.png", "f12.exr",   "notes.txt"};

std::vector<std::int64_t> frames(const std::vector<SequenceFrame>& sequence) {
    std::vector<std::int64_t> out;
    for (const SequenceFrame& f : sequence) {
        out.push_back(f.frame);
    }
    return out;
}

TEST(SequencePattern, ExpandsInFrameOrderFromTheLowest) {
    const auto seq = expandSequence("shots/f%04d.exr", kFolder);
    EXPECT_EQ(frames(seq), (std::vector<std::int64_t>{999, 1000, 1001, 1002}));
    EXPECT_EQ(seq.front().path, std::filesystem::path("shots/f0999.exr"));
}

TEST(SequencePattern, StartNumber) {
    EXPECT_EQ(frames(expandSequence("f####.exr", kFolder, {.startFrom = 1001})),
              (std::vector<std::int64_t>{1001, 1002}));
    EXPECT_THROW((void)expandSequence("f####.exr", kFolder, {.startFrom = 2000}), std::invalid_argument);
}

TEST(SequencePattern, RangeNeedsEveryFrame) {
    EXPECT_EQ(frames(expandSequence("f%04d.exr", kFolder, {.range = FrameRange{1000, 1001}})),
              (std::vector<std::int64_t>{1000, 1001}));
    try {
        (void)expandSequence("f%04d.exr", kFolder, {.range = FrameRange{1001, 1003}});
        FAIL() << "frame 1003 is missing";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("f1003.exr"), std::string::npos) << e.what();
    }
}

TEST(SequencePattern, NoMatchNamesThePattern) {
    try {
        (void)expandSequence("out/g%04d.exr", kFolder);
        FAIL() << "nothing matches";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("out/g%04d.exr"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace photopic
