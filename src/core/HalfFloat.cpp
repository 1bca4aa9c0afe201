#include "core/HalfFloat.h"

#include <bit>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#include <immintrin.h>
#define PHOTOPIC_X86 1
#endif

namespace photopic {

namespace {

constexpr std::uint32_t kHalfExponentBias = 127 - 15; ///< float exponent minus half exponent
constexpr std::uint32_t kHalfMaxFinite = 0x7bff;      ///< expmant bits of 65504
constexpr std::uint32_t kHalfMinNormal = 0x0400;      ///< expmant bits of 2^-14

float bitsToFloat(std::uint32_t bits) noexcept {
    return std::bit_cast<float>(bits);
}
std::uint32_t floatToBits(float value) noexcept {
    return std::bit_cast<std::uint32_t>(value);
}

#if defined(__SSE2__)
/// Four halves (in the low 16 bits of each lane) to floats: the exponent rebiased by adding to the shifted
/// bits, once more for infinity and NaN (float exponent 255), and denormals made normal floats by adding one
/// to the exponent and subtracting 2^-14 (exact, and no denormal float ever enters the arithmetic).
__m128 halfToFloat4(__m128i halves) noexcept {
    const __m128i expmant = _mm_and_si128(halves, _mm_set1_epi32(0x7fff));
    const __m128i sign = _mm_slli_epi32(_mm_xor_si128(halves, expmant), 16);
    const __m128i rebias = _mm_set1_epi32(int(kHalfExponentBias << 23));
    __m128i bits = _mm_add_epi32(_mm_slli_epi32(expmant, 13), rebias);
    const __m128i infNan = _mm_cmpgt_epi32(expmant, _mm_set1_epi32(int(kHalfMaxFinite)));
    bits = _mm_add_epi32(bits, _mm_and_si128(infNan, rebias));
    const __m128i denormal = _mm_cmplt_epi32(expmant, _mm_set1_epi32(int(kHalfMinNormal)));
    const __m128 renormalised = _mm_sub_ps(_mm_castsi128_ps(_mm_add_epi32(bits, _mm_set1_epi32(1 << 23))),
                                           _mm_castsi128_ps(_mm_set1_epi32(int(113u << 23))));
    bits = _mm_or_si128(_mm_and_si128(denormal, _mm_castps_si128(renormalised)),
                        _mm_andnot_si128(denormal, bits));
    return _mm_castsi128_ps(_mm_or_si128(bits, sign));
}
#endif

#if defined(PHOTOPIC_X86)
__attribute__((target("avx,f16c"))) void floatToHalfF16c(const float* in, std::uint16_t* out,
                                                         std::size_t count) noexcept {
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        const __m128i halves =
            _mm256_cvtps_ph(_mm256_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), halves);
    }
    for (; i < count; ++i) {
        out[i] = std::uint16_t(_mm_cvtsi128_si32(
            _mm_cvtps_ph(_mm_set_ss(in[i]), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)));
    }
}

/// halfToFloat eight at a time with F16C, whose conversion is exact except that it makes a signalling NaN
/// quiet: a block holding one (exponent all ones, quiet bit clear, payload not zero) goes the bit way.
__attribute__((target("avx,f16c"))) void halfToFloatF16c(const std::uint16_t* in, float* out,
                                                         std::size_t count) noexcept {
    const __m128i exponentAndQuiet = _mm_set1_epi16(0x7e00);
    const __m128i signallingExponent = _mm_set1_epi16(0x7c00);
    const __m128i payload = _mm_set1_epi16(0x01ff);
    const __m128i zero = _mm_setzero_si128();
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        const __m128i halves = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i));
        const __m128i signalling =
            _mm_andnot_si128(_mm_cmpeq_epi16(_mm_and_si128(halves, payload), zero),
                             _mm_cmpeq_epi16(_mm_and_si128(halves, exponentAndQuiet), signallingExponent));
        if (_mm_movemask_epi8(signalling) != 0) {
            for (std::size_t k = i; k < i + 8; ++k)
                out[k] = halfToFloat(in[k]);
            continue;
        }
        _mm256_storeu_ps(out + i, _mm256_cvtph_ps(halves));
    }
    for (; i < count; ++i)
        out[i] = halfToFloat(in[i]);
}

/// AVX usable (the CPU has it and the OS saves its registers: __builtin_cpu_supports checks both) and F16C,
/// read from CPUID leaf 1 (ECX bit 29) directly: Clang before 16 knows no "f16c" for __builtin_cpu_supports.
bool detectF16c() noexcept {
    __builtin_cpu_init();
    unsigned eax = 0;
    unsigned ebx = 0;
    unsigned ecx = 0;
    unsigned edx = 0;
    return __builtin_cpu_supports("avx") && __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 &&
           (ecx & bit_F16C) != 0;
}
#endif

} // namespace

float halfToFloat(std::uint16_t half) noexcept {
    const std::uint32_t expmant = half & 0x7fffu;
    const std::uint32_t sign = std::uint32_t(half & 0x8000u) << 16;
    std::uint32_t bits = (expmant << 13) + (kHalfExponentBias << 23);
    if (expmant > kHalfMaxFinite)
        bits += kHalfExponentBias << 23;
    if (expmant < kHalfMinNormal)
        bits = floatToBits(bitsToFloat(bits + (1u << 23)) - bitsToFloat(113u << 23));
    return bitsToFloat(bits | sign);
}

void halfToFloat(const std::uint16_t* in, float* out, std::size_t count) noexcept {
#if defined(PHOTOPIC_X86)
    if (hasF16c()) {
        halfToFloatF16c(in, out, count);
        return;
    }
#endif
    detail::halfToFloatPortable(in, out, count);
}

void detail::halfToFloatPortable(const std::uint16_t* in, float* out, std::size_t count) noexcept {
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    for (; i + 8 <= count; i += 8) {
        const __m128i halves = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i));
        _mm_storeu_ps(out + i, halfToFloat4(_mm_unpacklo_epi16(halves, zero)));
        _mm_storeu_ps(out + i + 4, halfToFloat4(_mm_unpackhi_epi16(halves, zero)));
    }
#endif
    for (; i < count; ++i)
        out[i] = halfToFloat(in[i]);
}

std::uint16_t floatToHalf(float value) noexcept {
    std::uint32_t bits = floatToBits(value);
    const std::uint32_t sign = bits & 0x80000000u;
    bits ^= sign;
    std::uint32_t half = 0;
    if (bits >= (127u + 16u) << 23) {
        // 2^16 and above (and the rounding below takes 65520..65536 to infinity too); NaN stays NaN.
        half = bits > (255u << 23) ? 0x7e00u : 0x7c00u;
    } else if (bits < 113u << 23) {
        // Below the smallest normal half: adding 0.5 aligns the denormal's last bit with float's, so the
        // FPU's own round-to-nearest-even does the rounding.
        const float denormalMagic = bitsToFloat(((127u - 15u) + (23u - 10u) + 1u) << 23);
        half = floatToBits(bitsToFloat(bits) + denormalMagic) - floatToBits(denormalMagic);
    } else {
        const std::uint32_t mantissaOdd = (bits >> 13) & 1u;
        bits += ((15u - 127u) << 23) + 0xfffu; // rebias, and round half-way cases up ...
        bits += mantissaOdd;                   // ... to even
        half = bits >> 13;
    }
    return std::uint16_t(half | (sign >> 16));
}

void floatToHalf(const float* in, std::uint16_t* out, std::size_t count) noexcept {
#if defined(PHOTOPIC_X86)
    if (hasF16c()) {
        floatToHalfF16c(in, out, count);
        return;
    }
#endif
    detail::floatToHalfPortable(in, out, count);
}

void detail::floatToHalfPortable(const float* in, std::uint16_t* out, std::size_t count) noexcept {
    for (std::size_t i = 0; i < count; ++i)
        out[i] = floatToHalf(in[i]);
}

bool hasF16c() noexcept {
#if defined(PHOTOPIC_X86)
    static const bool has = detectF16c();
    return has;
#else
    return false;
#endif
}

} // namespace photopic
