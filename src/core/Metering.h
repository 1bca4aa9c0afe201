#pragma once
// CPU reference metering: the luminance that drives auto exposure, measured on the sanitised HDR image before
// exposure is applied (so exposure never feeds back into its own measurement). The GPU metering passes mirror
// these functions; the GL tests compare the two on small images.
//
// Conventions a shader must copy exactly:
//  - Luminance: Rec.709 luma of linear RGB (ITU-R BT.709-6), 0.2126 r + 0.7152 g + 0.0722 b (core/Color.h).
//  - L is meterable when `L >= FLT_MIN && L <= FLT_MAX`: positive, normal, finite. The comparisons reject NaN
//    too (GLSL's isnan may be optimised away), and FLT_MIN keeps denormals out (GPUs flush them to zero).
//    Nothing else enters a mean.
//  - Image UV: u right, v down, (0, 0) = top-left corner of the image (row 0 of ImageF). Pixel (x, y) has its
//    centre at uv = ((x + 0.5) / W, (y + 0.5) / H); a texture uploaded from ImageF row 0 first agrees.
//  - Every mode but `histogram` is a weighted geometric mean, exp2(sum(w log2 L) / sum(w)) over meterable L
//    with w > 0, and 0 ("no reading": the controller keeps its state) when there is none.
//  - Per-pixel values are float32 as in GLSL; the CPU sums them in double because it sums serially (a GPU
//    tree reduction in float lands close to the exact sum; a serial float sum over 10^6 pixels does not).
//
// Histogram: A. Tardif, "Automatic Exposure Using a Luminance Histogram" (2019).
// 256 bins. Bin 0 holds L below 2^log2Min and every non-positive L; it counts (those are the
// darkest pixels of the percentile window). Otherwise bin = int(1 + 254 * saturate((log2 L - log2Min) /
// (log2Max - log2Min))): bins 1..254 split the range evenly and bin 255 holds L >= 2^log2Max. Non-finite L
// is in no bin. Bin b's centre is log2Min + (b - 0.5) * (log2Max - log2Min) / 254 for every b (bin 0 half a
// bin below the range, bin 255 half a bin above). The percentile window (Unreal, Bevy: 10 / 90) weighs the
// bins at its edges by the fraction inside, so the mean is continuous.

#include "core/Image.h"
#include "core/settings/AutoExposureSettings.h"

#include <array>
#include <cstdint>

namespace photopic {

inline constexpr int kHistogramBins = 256;
/// Bins 1..254 split [log2Min, log2Max] evenly (Tardif's 1 + 254 * t); bin 0 is underflow, bin 255 overflow.
inline constexpr float kHistogramRangeBins = 254.0f;
/// Smallest meterable luminance: FLT_MIN, the smallest normal float (denormals are flushed to zero on GPUs).
inline constexpr float kMinMeterableLuminance = 1.17549435e-38f;
/// Largest meterable luminance: FLT_MAX (+inf is not meterable).
inline constexpr float kMaxMeterableLuminance = 3.40282347e+38f;

/// Centre-weighted metering: w = exp(-kCenterFalloff * d^2), d = distance from the image centre in image
/// heights. 8 = 1 / (2 sigma^2), sigma = 0.25 image heights: w = 0.135 at the top and bottom edges, 0.0003
/// in a 16:9 corner, never 0 (a frame with a black centre still meters).
inline constexpr float kCenterFalloff = 8.0f;

/// Spot taps in units of the spot radius, x right and y down (image heights on both axes). `taps = n` uses
/// the first n: 1 = centre; 5 = plus at 0.5; 9 = 3x3 grid of spacing 0.5; 13 = the 9 plus the four axis
/// points on the rim (a diamond). Equal weights.
/// GLSL: `const vec2 kSpotTaps[13] = vec2[](vec2(0, 0), vec2(0.5, 0), vec2(-0.5, 0), ...);`
inline constexpr std::array<std::array<float, 2>, 13> kSpotTaps{{
    {0.0f, 0.0f},
    {0.5f, 0.0f},
    {-0.5f, 0.0f},
    {0.0f, 0.5f},
    {0.0f, -0.5f},
    {0.5f, 0.5f},
    {-0.5f, 0.5f},
    {0.5f, -0.5f},
    {-0.5f, -0.5f},
    {1.0f, 0.0f},
    {-1.0f, 0.0f},
    {0.0f, 1.0f},
    {0.0f, -1.0f},
}};

/// Positive, normal, finite: `L >= FLT_MIN && L <= FLT_MAX` (false for NaN, +-inf, 0, negatives, denormals).
[[nodiscard]] constexpr bool isMeterableLuminance(float luminance) noexcept {
    return luminance >= kMinMeterableLuminance && luminance <= kMaxMeterableLuminance;
}

/// Rec.709 luma of pixel (x, y).
[[nodiscard]] float pixelLuminance(const ImageF& image, int x, int y) noexcept;

/// Geometric mean of the meterable pixel luminances; 0 when there is none.
[[nodiscard]] float meterAverage(const ImageF& image) noexcept;

struct Histogram {
    std::array<std::uint32_t, kHistogramBins> bins{}; ///< pixel counts; bin 0 underflow, 255 overflow
    float log2Min = -12.0f;                           ///< low edge of bin 1
    float log2Max = 16.0f;                            ///< high edge of bin 254
};

/// Bin of a luminance: -1 for non-finite (counted nowhere); 0 for L < 2^log2Min, L <= 0 or denormal; else
/// int(1 + 254 * saturate((log2 L - log2Min) / (log2Max - log2Min))). Needs log2Min < log2Max.
[[nodiscard]] int histogramBin(float luminance, float log2Min, float log2Max) noexcept;
/// log2Min + (bin - 0.5) * (log2Max - log2Min) / 254, for every bin 0..255.
[[nodiscard]] float histogramBinCentreLog2(int bin, float log2Min, float log2Max) noexcept;
/// Histogram of the image's luma, starting from empty bins.
[[nodiscard]] Histogram buildHistogram(const ImageF& image, float log2Min, float log2Max);

struct HistogramStats {
    float averageLog2 = 0.0f;  ///< mean bin centre over the percentile window, fractional bins at its edges
    float lowLog2 = 0.0f;      ///< centre of the bin holding the lowPercent edge of the window
    float highLog2 = 0.0f;     ///< centre of the bin holding the highPercent edge of the window
    std::uint32_t counted = 0; ///< pixels in the histogram (all bins); 0 -> every other field is 0
};

/// Mean log2 luminance of the [lowPercent, highPercent] window of the counted pixels, in float32 exactly as
/// the adaptation shader does it (the sums in bin order; percentages clamped to [0, 100]; the running count
/// k an integer):
///   n = float(sum(bins)); lo = n * (lowPercent * 0.01); hi = n * (highPercent * 0.01); k = 0; sum = ws = 0
///   for b in 0..255: start = float(k); k += bins[b]; c = float(k); w = max(0, min(c, hi) - max(start, lo));
///                    sum += w * centre(b); ws += w
///   average = ws > 0 ? sum / ws : lowLog2      (empty window: lowPercent == highPercent)
/// lowLog2 / highLog2: centre of the first non-empty bin with c > lo / c >= hi.
[[nodiscard]] HistogramStats histogramAverage(const Histogram& histogram, float lowPercent,
                                              float highPercent) noexcept;

/// 1 inside the closed spot disc, else 0: dx = (u - spot.u) * aspect, dy = v - spot.v, dx^2 + dy^2 <= r^2,
/// aspect = width / height. For the metering-weights debug view; the reading itself uses the taps.
[[nodiscard]] float spotWeight(float u, float v, const AutoExposureSettings::SpotMetering& spot,
                               float aspect) noexcept;
/// exp(-kCenterFalloff * (dx^2 + dy^2)), dx = (u - 0.5) * aspect, dy = v - 0.5, aspect = width / height.
[[nodiscard]] float centerWeight(float u, float v, float aspect) noexcept;

struct TexelCoord {
    int x;
    int y;
};
/// Texel of spot tap `tap` (nearest, clamped to the image):
///   rp = spot.radius * H;  px = spot.u * W + kSpotTaps[tap].x * rp;  py = spot.v * H + kSpotTaps[tap].y * rp
///   x = clamp(int(floor(px)), 0, W - 1);  y = clamp(int(floor(py)), 0, H - 1)
[[nodiscard]] TexelCoord spotTapTexel(const AutoExposureSettings::SpotMetering& spot, int tap, int width,
                                      int height) noexcept;

/// Geometric mean of the meterable luminances at the first spot.taps taps (clamped to 1..13); 0 when none is.
[[nodiscard]] float meterSpot(const ImageF& image, const AutoExposureSettings::SpotMetering& spot) noexcept;
/// Geometric mean weighted by centerWeight at each pixel centre.
[[nodiscard]] float meterCenter(const ImageF& image) noexcept;
/// Geometric mean weighted by the mask's Rec.709 luma (negative or non-finite -> 0), sampled nearest at each
/// pixel centre: mx = clamp(int(floor(u * maskW)), 0, maskW - 1), likewise y. 0 when every weight is 0.
[[nodiscard]] float meterMasked(const ImageF& image, const ImageF& mask) noexcept;

/// The metered luminance for settings.metering; 0 means "no reading" (ExposureController keeps its state).
/// Mask mode without a mask (null or empty) meters like `average` and warns once. Subject mode has no reading
/// from an image alone (the subject probe is the reading: core/Subjects.h, passes/probe/).
[[nodiscard]] float meterImage(const ImageF& image, const AutoExposureSettings& settings,
                               const ImageF* mask = nullptr) noexcept;

} // namespace photopic
