#pragma once
// The glow of a point of light: a supersampled disc on a background, and how far its glow (an image with
// an effect minus the same without) is from radially symmetric (the means of 8 sectors of each annulus, each
// pixel divided by the glow's radial profile at its own distance, against their mean) and whether it falls
// off monotonically from the core; and the frame helpers the bloom and glare tests share.

#include "GlTest.h"

#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "pipeline/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

namespace photopic::test {

/// An exposure state of `exposure` in a buffer, as the bloom, glare and tone-map passes read it.
inline Buffer exposureState(float exposure, std::string_view name = "test exposure state") {
    GpuExposureState state;
    state.exposure = exposure;
    return Buffer({.size = sizeof(state), .data = &state, .debugName = name});
}

/// The scene-referred image `pipeline` makes of `image`.
inline ImageF sceneOf(Pipeline& pipeline, const ImageF& image) {
    const Texture input = makeTexture(image, "test input");
    pipeline.execute({.color = &input}, {});
    return readTextureF(pipeline.sceneReferred());
}

/// The sum of the red, green and blue values of every pixel.
inline double sumRgb(const ImageF& image) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        sum += double(image.rgba[i * 4]) + image.rgba[i * 4 + 1] + image.rgba[i * 4 + 2];
    return sum;
}

} // namespace photopic::test

namespace photopic::test::glow {

constexpr int kSize = 160;

struct Source {
    float x = 80.0f; ///< centre, pixels (centres of pixels at +0.5)
    float y = 80.0f;
    float radius = 2.5f;
    float value = 2000.0f;
    float background = 0.0f;
};

/// The disc's coverage of each pixel, 8x8 supersampled, over the background.
inline ImageF pointLight(const Source& s) {
    ImageF image(kSize, kSize);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            int inside = 0;
            for (int j = 0; j < 8; ++j)
                for (int i = 0; i < 8; ++i)
                    inside += std::hypot(float(x) + (float(i) + 0.5f) / 8.0f - s.x,
                                         float(y) + (float(j) + 0.5f) / 8.0f - s.y) <= s.radius
                                  ? 1
                                  : 0;
            const float v = s.background + (s.value - s.background) * float(inside) / 64.0f;
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = v;
            p[3] = 1.0f;
        }
    }
    return image;
}

inline ImageF sceneReferred(const Settings& settings, const ImageF& image) {
    Pipeline pipeline({.settings = settings});
    return sceneOf(pipeline, image);
}

/// Fixed exposure, linear curve, no dither or AA: the scene-referred image is the scene and its bloom.
inline Settings measured(Settings s) {
    s.autoExposure.enabled = false;
    s.tonemapping.exposure = 0.0f;
    s.tonemapping.mode = ToneMapper::Linear;
    s.output.dither = false;
    s.aa.mode = AntiAliasing::None;
    return s;
}

struct Figures {
    double worstSpread = 0.0; ///< largest |sector mean - annulus mean| / annulus mean
    double worstRise = 0.0;   ///< largest rise of an annulus mean over the one inside it, relative
    int annuli = 0;
};

/// The glow (with bloom minus without) in 2-pixel annuli from the source's edge + 1 outwards, while it stays
/// above 1e-3 of the first annulus's. Each pixel's glow is divided by the radial profile at its own distance
/// (the mean over every direction of the pixels in a 0.25-pixel ring, interpolated), so that a perfectly
/// round glow gives 1 in every sector whatever pixel centres a sector holds; sectors reaching past the
/// image's edge are left out (there the profile comes from the rings' other pixels).
/// `from`: the first annulus's inner radius when positive (else the source's edge + 1).
inline Figures measure(const ImageF& with, const ImageF& without, const Source& s, float from = -1.0f) {
    constexpr float kBin = 0.25f;
    constexpr int kBins = 200; // 50 pixels
    std::vector<double> ringSum(kBins, 0.0);
    std::vector<int> ringCount(kBins, 0);
    const auto glow = [&](int x, int y) { return double(with.at(x, y)[1]) - double(without.at(x, y)[1]); };
    const auto radiusOf = [&](int x, int y) {
        return std::hypot(float(x) + 0.5f - s.x, float(y) + 0.5f - s.y);
    };
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            // Only the glow outside the source: inside it an energy-conserving glow is the source's loss,
            // negative, and would bend the profile of the first annulus.
            const float r = radiusOf(x, y);
            const int bin = int(r / kBin);
            if (bin < kBins && r >= s.radius + 1.0f - kBin) {
                ringSum[std::size_t(bin)] += glow(x, y);
                ++ringCount[std::size_t(bin)];
            }
        }
    }
    const auto profile = [&](float r) {
        // Between the centres of the rings that hold pixels on either side.
        const float t = r / kBin - 0.5f;
        int lo = std::clamp(int(std::floor(t)), 0, kBins - 1);
        int hi = std::clamp(lo + 1, 0, kBins - 1);
        while (lo > 0 && ringCount[std::size_t(lo)] == 0)
            --lo;
        while (hi < kBins - 1 && ringCount[std::size_t(hi)] == 0)
            ++hi;
        const auto mean = [&](int bin) { return ringSum[std::size_t(bin)] / ringCount[std::size_t(bin)]; };
        if (ringCount[std::size_t(lo)] == 0)
            lo = hi; // nothing inside: the first ring outwards
        const double a = ringCount[std::size_t(lo)] ? mean(lo) : 0.0;
        const double b = ringCount[std::size_t(hi)] ? mean(hi) : a;
        const float w = hi == lo ? 0.0f : std::clamp((t - float(lo)) / float(hi - lo), 0.0f, 1.0f);
        // Geometric between rings of the same sign: a glow falling as a power of the distance or
        // exponentially is exact so, where a straight line between sparse rings near a light is not.
        if (a > 0.0 && b > 0.0)
            return a * std::pow(b / a, double(w));
        return a + (b - a) * double(w);
    };
    Figures f;
    double first = 0.0;
    double previous = 0.0;
    for (float r0 = from > 0.0f ? from : s.radius + 1.0f; r0 < 40.0f; r0 += 2.0f) {
        double ratio[8] = {};
        double sums = 0.0;
        int counts[8] = {};
        int total = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const float r = radiusOf(x, y);
                if (r < r0 || r >= r0 + 2.0f)
                    continue;
                const float dx = float(x) + 0.5f - s.x;
                const float dy = float(y) + 0.5f - s.y;
                // Sectors centred on the axes and the diagonals, where a square and a circle differ most.
                const int k = int((std::atan2(dy, dx) + 3.14159265f + 0.39269908f) / 6.2831853f * 8.0f) % 8;
                const double p = profile(r);
                ratio[k] += p > 0.0 ? glow(x, y) / p : 0.0;
                ++counts[k];
                sums += glow(x, y);
                ++total;
            }
        }
        bool clipped[8] = {};
        int n = 0;
        for (int k = 0; k < 8; ++k) {
            const float a = float(k) / 8.0f * 6.2831853f - 3.14159265f;
            const float ex = s.x + (r0 + 2.0f) * std::cos(a);
            const float ey = s.y + (r0 + 2.0f) * std::sin(a);
            clipped[k] = counts[k] == 0 || ex < 0.0f || ey < 0.0f || ex > float(kSize) || ey > float(kSize);
            n += clipped[k] ? 0 : 1;
        }
        const double mean = total ? sums / total : 0.0;
        if (n < 3)
            break;
        if (first == 0.0)
            first = mean;
        if (!(first > 0.0) || !(mean > 1e-3 * first))
            break;
        double meanRatio = 0.0;
        for (int k = 0; k < 8; ++k)
            meanRatio += clipped[k] ? 0.0 : ratio[k] / counts[k];
        meanRatio /= n;
        for (int k = 0; k < 8; ++k) {
            if (!clipped[k])
                f.worstSpread =
                    std::max(f.worstSpread, std::abs(ratio[k] / counts[k] - meanRatio) / meanRatio);
        }
        if (previous > 0.0)
            f.worstRise = std::max(f.worstRise, (mean - previous) / previous);
        previous = mean;
        ++f.annuli;
    }
    return f;
}

} // namespace photopic::test::glow
