// core/HalfFloat.h against OpenEXR's Imath::half, the conversion EXR files are read and written with: every
// half's float to the bit (NaN payloads too), floats back to halves rounded the same way, and the runs (F16C
// or SSE2 where the CPU has them) the same as one value at a time, over lengths that leave a tail.

#include "core/HalfFloat.h"

#include <gtest/gtest.h>

#include <Imath/half.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace photopic {
namespace {

std::uint32_t bits(float value) {
    return std::bit_cast<std::uint32_t>(value);
}

std::vector<std::uint16_t> everyHalf() {
    std::vector<std::uint16_t> halves(1u << 16);
    for (std::size_t i = 0; i < halves.size(); ++i)
        halves[i] = std::uint16_t(i);
    return halves;
}

TEST(HalfFloat, EveryHalfWidensToImathsFloat) {
    const std::vector<std::uint16_t> halves = everyHalf();
    std::vector<float> run(halves.size());
    halfToFloat(halves.data(), run.data(), halves.size());
    std::vector<float> portable(halves.size());
    detail::halfToFloatPortable(halves.data(), portable.data(), halves.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < halves.size(); ++i) {
        Imath::half h;
        h.setBits(halves[i]);
        const std::uint32_t expected = bits(float(h));
        mismatches += bits(halfToFloat(halves[i])) != expected;
        mismatches += bits(run[i]) != expected;
        mismatches += bits(portable[i]) != expected;
    }
    EXPECT_EQ(mismatches, 0);
    // A signalling NaN stays signalling (F16C alone would make it quiet).
    EXPECT_EQ(bits(halfToFloat(std::uint16_t(0x7c01))), 0x7f802000u);
    std::vector<std::uint16_t> block{0x3c00, 0x7c01, 0x0001, 0x8000, 0xfc00, 0x7bff, 0x0400, 0xfd55, 0x3555};
    std::vector<float> widened(block.size());
    halfToFloat(block.data(), widened.data(), block.size());
    EXPECT_EQ(bits(widened[1]), 0x7f802000u);
    EXPECT_EQ(widened[0], 1.0f);
    EXPECT_EQ(widened[2], std::ldexp(1.0f, -24));
}

TEST(HalfFloat, EveryHalfNarrowsBackToItself) {
    const std::vector<std::uint16_t> halves = everyHalf();
    std::vector<float> floats(halves.size());
    halfToFloat(halves.data(), floats.data(), floats.size());
    std::vector<std::uint16_t> run(halves.size());
    floatToHalf(floats.data(), run.data(), floats.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < halves.size(); ++i) {
        const bool nan = (halves[i] & 0x7c00u) == 0x7c00u && (halves[i] & 0x03ffu) != 0;
        if (nan) { // NaN stays NaN of the same sign; its payload may be made quiet
            mismatches += (floatToHalf(floats[i]) & 0xfe00u) != ((halves[i] & 0x8000u) | 0x7e00u);
            mismatches += (run[i] & 0x7c00u) != 0x7c00u || (run[i] & 0x03ffu) == 0;
            continue;
        }
        mismatches += floatToHalf(floats[i]) != halves[i];
        mismatches += run[i] != halves[i];
    }
    EXPECT_EQ(mismatches, 0);
}

TEST(HalfFloat, FloatsRoundToNearestEvenAsImathRounds) {
    std::vector<float> values{
        1.0f + std::ldexp(1.0f, -11),        // half-way between 1 and its neighbour: to even, 1
        1.0f + 3.0f * std::ldexp(1.0f, -11), // half-way: to even, up
        65504.0f,
        65519.99f, // still the largest half
        65520.0f,  // infinity
        -1e9f,
        std::ldexp(1.0f, -25),          // half the smallest denormal: to even, zero
        std::ldexp(1.5f, -25),          // above it: the smallest denormal
        std::ldexp(3.0f, -25),          // half-way between the first two denormals: to even, two
        std::ldexp(1.0f, -14) * 0.999f, // the largest denormal's neighbourhood
        std::numeric_limits<float>::denorm_min(),
        -0.0f,
        std::numeric_limits<float>::infinity(),
    };
    std::mt19937 random(5);
    std::uniform_real_distribution<float> exponent(-30.0f, 17.0f);
    for (int i = 0; i < 200000; ++i)
        values.push_back(std::exp2(exponent(random)) * ((random() & 1u) != 0 ? -1.0f : 1.0f));
    // Every float between two neighbouring halves, around 1 and in the denormals.
    for (std::uint32_t b = bits(1.0f); b <= bits(1.0f) + (1u << 14); ++b)
        values.push_back(std::bit_cast<float>(b));
    for (std::uint32_t b = bits(std::ldexp(1.0f, -24)) - (1u << 12);
         b <= bits(std::ldexp(1.0f, -24)) + (1u << 12); ++b)
        values.push_back(std::bit_cast<float>(b));
    // Odd lengths leave a tail after the eight-value steps.
    for (const std::size_t count : {values.size(), values.size() - 3, std::size_t(7), std::size_t(1)}) {
        std::vector<std::uint16_t> run(count);
        floatToHalf(values.data(), run.data(), count);
        std::vector<std::uint16_t> portable(count);
        detail::floatToHalfPortable(values.data(), portable.data(), count);
        int mismatches = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint16_t expected = Imath::half(values[i]).bits();
            mismatches += floatToHalf(values[i]) != expected;
            mismatches += run[i] != expected;
            mismatches += portable[i] != expected;
        }
        EXPECT_EQ(mismatches, 0) << count << " values";
    }
    EXPECT_EQ(floatToHalf(std::numeric_limits<float>::quiet_NaN()) & 0x7e00u, 0x7e00u);
    EXPECT_EQ(floatToHalf(-std::numeric_limits<float>::quiet_NaN()), 0xfe00u);
}

} // namespace
} // namespace photopic
