#include "core/Metering.h"

#include "core/Color.h"
#include "core/Log.h"

#include <algorithm>
#include <cmath>

namespace photopic {

namespace {

/// Accumulates a weighted geometric mean: exp2(sum(w log2 L) / sum(w)) over meterable L with w > 0.
class LogMean {
public:
    void add(float luminance, float weight) noexcept {
        if (!isMeterableLuminance(luminance) || !(weight > 0.0f)) {
            return;
        }
        mSum += double(weight) * double(std::log2(luminance));
        mWeight += double(weight);
    }
    /// The mean luminance, or 0 when nothing was added.
    [[nodiscard]] float result() const noexcept {
        if (!(mWeight > 0.0)) {
            return 0.0f;
        }
        return std::exp2(static_cast<float>(mSum / mWeight));
    }

private:
    double mSum = 0.0;
    double mWeight = 0.0;
};

float pixelU(int x, int width) noexcept {
    return (float(x) + 0.5f) / float(width);
}

} // namespace

float pixelLuminance(const ImageF& image, int x, int y) noexcept {
    const float* p = image.at(x, y);
    return luma709({p[0], p[1], p[2]});
}

float meterAverage(const ImageF& image) noexcept {
    LogMean mean;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            mean.add(pixelLuminance(image, x, y), 1.0f);
        }
    }
    return mean.result();
}

int histogramBin(float luminance, float log2Min, float log2Max) noexcept {
    if (!(luminance >= -kMaxMeterableLuminance && luminance <= kMaxMeterableLuminance)) {
        return -1; // NaN or +-inf: in no bin
    }
    if (!(luminance >= kMinMeterableLuminance)) {
        return 0; // zero, negative or denormal: the darkest pixels, underflow
    }
    const float lg = std::log2(luminance);
    if (lg < log2Min) {
        return 0;
    }
    const float t = std::min((lg - log2Min) / (log2Max - log2Min), 1.0f); // >= 0 here: saturate
    return static_cast<int>(1.0f + kHistogramRangeBins * t);
}

float histogramBinCentreLog2(int bin, float log2Min, float log2Max) noexcept {
    const float binWidth = (log2Max - log2Min) / kHistogramRangeBins;
    return log2Min + (float(bin) - 0.5f) * binWidth;
}

Histogram buildHistogram(const ImageF& image, float log2Min, float log2Max) {
    Histogram h;
    h.log2Min = log2Min;
    h.log2Max = log2Max;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const int bin = histogramBin(pixelLuminance(image, x, y), log2Min, log2Max);
            if (bin >= 0) {
                ++h.bins[std::size_t(bin)];
            }
        }
    }
    return h;
}

HistogramStats histogramAverage(const Histogram& histogram, float lowPercent, float highPercent) noexcept {
    HistogramStats stats;
    std::uint32_t total = 0;
    for (const std::uint32_t c : histogram.bins) {
        total += c;
    }
    if (total == 0) {
        return stats;
    }
    stats.counted = total;
    const float n = float(total);
    const float lo = n * (std::clamp(lowPercent, 0.0f, 100.0f) * 0.01f);
    const float hi = n * (std::clamp(highPercent, 0.0f, 100.0f) * 0.01f);
    // The running count is kept as an integer: a float one drops counts past 2^24 pixels (an 8K frame).
    std::uint32_t running = 0;
    float sum = 0.0f;
    float weightSum = 0.0f;
    bool lowFound = false;
    bool highFound = false;
    for (int b = 0; b < kHistogramBins; ++b) {
        const float count = float(histogram.bins[std::size_t(b)]);
        const float start = float(running);
        running += histogram.bins[std::size_t(b)];
        const float cumulative = float(running);
        const float centre = histogramBinCentreLog2(b, histogram.log2Min, histogram.log2Max);
        const float w = std::max(0.0f, std::min(cumulative, hi) - std::max(start, lo));
        sum += w * centre;
        weightSum += w;
        if (count > 0.0f && !lowFound && cumulative > lo) {
            stats.lowLog2 = centre;
            lowFound = true;
        }
        if (count > 0.0f && !highFound && cumulative >= hi) {
            stats.highLog2 = centre;
            highFound = true;
        }
    }
    stats.averageLog2 = weightSum > 0.0f ? sum / weightSum : stats.lowLog2;
    return stats;
}

float spotWeight(float u, float v, const AutoExposureSettings::SpotMetering& spot, float aspect) noexcept {
    const float dx = (u - spot.u) * aspect;
    const float dy = v - spot.v;
    return dx * dx + dy * dy <= spot.radius * spot.radius ? 1.0f : 0.0f;
}

float centerWeight(float u, float v, float aspect) noexcept {
    const float dx = (u - 0.5f) * aspect;
    const float dy = v - 0.5f;
    return std::exp(-kCenterFalloff * (dx * dx + dy * dy));
}

TexelCoord spotTapTexel(const AutoExposureSettings::SpotMetering& spot, int tap, int width,
                        int height) noexcept {
    const auto& offset = kSpotTaps[std::size_t(std::clamp(tap, 0, int(kSpotTaps.size()) - 1))];
    const float radiusPixels = spot.radius * float(height);
    const float px = spot.u * float(width) + offset[0] * radiusPixels;
    const float py = spot.v * float(height) + offset[1] * radiusPixels;
    return {std::clamp(static_cast<int>(std::floor(px)), 0, width - 1),
            std::clamp(static_cast<int>(std::floor(py)), 0, height - 1)};
}

float meterSpot(const ImageF& image, const AutoExposureSettings::SpotMetering& spot) noexcept {
    if (image.empty()) {
        return 0.0f;
    }
    const int taps = std::clamp(spot.taps, 1, int(kSpotTaps.size()));
    LogMean mean;
    for (int i = 0; i < taps; ++i) {
        const TexelCoord t = spotTapTexel(spot, i, image.width, image.height);
        mean.add(pixelLuminance(image, t.x, t.y), 1.0f);
    }
    return mean.result();
}

float meterCenter(const ImageF& image) noexcept {
    if (image.empty()) {
        return 0.0f;
    }
    const float aspect = float(image.width) / float(image.height);
    LogMean mean;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            mean.add(pixelLuminance(image, x, y),
                     centerWeight(pixelU(x, image.width), pixelU(y, image.height), aspect));
        }
    }
    return mean.result();
}

float meterMasked(const ImageF& image, const ImageF& mask) noexcept {
    if (image.empty() || mask.empty()) {
        return 0.0f;
    }
    LogMean mean;
    for (int y = 0; y < image.height; ++y) {
        const float v = pixelU(y, image.height);
        const int my = std::clamp(static_cast<int>(std::floor(v * float(mask.height))), 0, mask.height - 1);
        for (int x = 0; x < image.width; ++x) {
            const float u = pixelU(x, image.width);
            const int mx = std::clamp(static_cast<int>(std::floor(u * float(mask.width))), 0, mask.width - 1);
            const float w = pixelLuminance(mask, mx, my);
            // A NaN or infinite weight is 0: `w <= FLT_MAX` is false for both (LogMean drops w <= 0).
            mean.add(pixelLuminance(image, x, y), w <= kMaxMeterableLuminance ? w : 0.0f);
        }
    }
    return mean.result();
}

float meterImage(const ImageF& image, const AutoExposureSettings& settings, const ImageF* mask) noexcept {
    switch (settings.metering) {
    case MeteringMode::Average:
        return meterAverage(image);
    case MeteringMode::Histogram: {
        const Histogram h = buildHistogram(image, settings.histogramLog2Min, settings.histogramLog2Max);
        const HistogramStats stats = histogramAverage(h, settings.lowPercent, settings.highPercent);
        return stats.counted > 0 ? std::exp2(stats.averageLog2) : 0.0f;
    }
    case MeteringMode::Spot:
        return meterSpot(image, settings.spot);
    case MeteringMode::Center:
        return meterCenter(image);
    case MeteringMode::Mask:
        if (mask == nullptr || mask->empty()) {
            try {
                warnOnce(
                    "metering.mask.missing",
                    "autoExposure.metering is \"mask\" but no mask image is loaded; metering the average");
            } catch (...) { // logging must not take the frame down
            }
            return meterAverage(image);
        }
        return meterMasked(image, *mask);
    case MeteringMode::Subject:
        // The subject's probe (core/Subjects.h probeImage, or the pipeline's probe pass) is the reading; an
        // image alone has none, so exposure holds.
        return 0.0f;
    }
    return 0.0f;
}

} // namespace photopic
