#pragma once
// IEEE 754 binary16 ("half") to and from float, for whole runs of values: the EXR decoder widens a frame's
// half channels to float, and the CLI's upload narrows them back for a half-float texture. The runs use the
// F16C instructions where the CPU has them (chosen at run time: the build targets plain x86-64), else work
// on the bits; either way the results are the same bits.
//
// Reference: F. Giesen, "Half to float done quic" and "float->half variants" (2016), for the bit-level
// conversions with correct rounding, denormals and non-finite values.

#include <cstddef>
#include <cstdint>

namespace photopic {

/// The float a half's bits stand for. Exact for every input: zeros and denormals keep their sign and value,
/// infinities stay infinite and a NaN keeps its payload (not made quiet), as OpenEXR's Imath converts.
[[nodiscard]] float halfToFloat(std::uint16_t bits) noexcept;

/// halfToFloat over `count` values, eight at a time (F16C when the CPU has it, else SSE2 where the build has
/// it), the same bits as one at a time.
void halfToFloat(const std::uint16_t* in, float* out, std::size_t count) noexcept;

/// The half nearest to `value`, ties to even (IEEE's default rounding, which F16C, Imath and Mesa's texture
/// store use); beyond the largest half (65504, from 65520 on) infinity; NaN a quiet NaN of the same sign. A
/// float that is a half exactly comes back as that half's bits (a NaN's payload aside).
[[nodiscard]] std::uint16_t floatToHalf(float value) noexcept;

/// floatToHalf over `count` values: eight at a time with F16C when the CPU has it, else one at a time.
/// `out` is only written, front to back (it may be write-combined memory).
void floatToHalf(const float* in, std::uint16_t* out, std::size_t count) noexcept;

/// Whether the runs above use F16C here.
[[nodiscard]] bool hasF16c() noexcept;

namespace detail {
/// The runs as a CPU without F16C converts them (SSE2 or one value at a time): the tests hold them to the
/// same bits on a CPU that has it.
void halfToFloatPortable(const std::uint16_t* in, float* out, std::size_t count) noexcept;
void floatToHalfPortable(const float* in, std::uint16_t* out, std::size_t count) noexcept;
} // namespace detail

} // namespace photopic
