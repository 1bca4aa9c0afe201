// The glare kernels (core/Glare.h): the analytic PSF and its closed-form enclosed energy, the sampled kernel
// (normalised, symmetric, following the analytic profile, independent of the resolution in degrees), the
// halo split, the camera kernel's spikes, and the settings that choose them.

#include "core/Glare.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace photopic {
namespace {

constexpr double kPi = 3.14159265358979323846;

GlareKernelParameters eye(float pitch, float radius = 4.0f) {
    return {.kernel = GlareKernel::Eye, .radiusDeg = radius, .degreesPerPixel = pitch};
}

GlareKernelParameters camera(float pitch, int blades, float rotation = 0.0f) {
    return {.kernel = GlareKernel::Camera,
            .radiusDeg = 4.0f,
            .degreesPerPixel = pitch,
            .blades = blades,
            .bladeRotationDeg = rotation};
}

double sum(const GlareKernelImage& k) {
    return std::accumulate(k.weights.begin(), k.weights.end(), 0.0);
}

/// Kernel energy within `thetaDeg` of the centre (pixel centres inside).
double within(const GlareKernelImage& k, float pitch, double thetaDeg) {
    double e = 0.0;
    for (int dy = -k.radius; dy <= k.radius; ++dy)
        for (int dx = -k.radius; dx <= k.radius; ++dx)
            if (std::hypot(double(dx), double(dy)) * pitch <= thetaDeg)
                e += k.at(dx, dy);
    return e;
}

TEST(GlareKernel, EnclosedEnergyIsTheIntegralOfTheRadialProfile) {
    for (const GlareKernelParameters& p : {eye(0.05f), camera(0.05f, 6)}) {
        // Midpoint rule on a log-spaced radius: 2 pi t psf(t) dt from 0 to 2 degrees.
        double numeric = 0.0;
        const int steps = 200000;
        for (int i = 0; i < steps; ++i) {
            const double t0 = 2.0 * std::pow(double(i) / steps, 3.0),
                         t1 = 2.0 * std::pow(double(i + 1) / steps, 3.0);
            const double t = 0.5 * (t0 + t1);
            numeric += 2.0 * kPi * t * glareRadialProfile(p, t) * (t1 - t0);
        }
        EXPECT_NEAR(glareEnclosedEnergy(p, 2.0), numeric, 2e-4 * numeric) << int(p.kernel);
    }
}

TEST(GlareKernel, EyeProfileIsTheWeightedSumOfCoreAndHalo) {
    const GlareKernelParameters p = eye(0.05f);
    for (const double t : {0.0, 0.01, 0.1, 1.0, 3.0}) {
        const double o = t + 0.02;
        const double want = 0.384 * 2.61e6 * std::exp(-(t / 0.02) * (t / 0.02)) +
                            0.478 * 20.91 / (o * o * o) + 0.138 * 72.37 / (o * o);
        EXPECT_NEAR(glarePsf(p, t, 0.0), want, 1e-9 * want) << t;
        EXPECT_NEAR(glarePsf(p, t * 0.6, t * 0.8), want, 1e-9 * want) << t;
    }
    EXPECT_EQ(glarePsf(p, 4.5, 0.0), 0.0) << "nothing past the extent";
}

TEST(GlareKernel, SamplesSumToOneAndAreSymmetric) {
    for (const GlareKernelParameters& p :
         {eye(0.05f), eye(0.375f, 20.0f), camera(0.05f, 6), camera(0.1f, 5)}) {
        const GlareKernelImage k = sampleGlareKernel(p);
        EXPECT_NEAR(sum(k), 1.0, 1e-5);
        EXPECT_GT(k.core(), 0.0f);
        for (int dy = -k.radius; dy <= k.radius; dy += 3) {
            for (int dx = -k.radius; dx <= k.radius; dx += 2) {
                // Point symmetric (a diffraction pattern is); the eye kernel also under mirrors.
                EXPECT_NEAR(k.at(dx, dy), k.at(-dx, -dy), 1e-6f * k.core() + 1e-4f * k.at(dx, dy))
                    << int(p.kernel) << " " << p.degreesPerPixel << " at " << dx << ", " << dy;
                if (p.kernel == GlareKernel::Eye) {
                    EXPECT_NEAR(k.at(dx, dy), k.at(dy, dx), 1e-4f * k.at(dx, dy) + 1e-12f);
                    EXPECT_NEAR(k.at(dx, dy), k.at(-dx, dy), 1e-4f * k.at(dx, dy) + 1e-12f);
                }
            }
        }
    }
}

TEST(GlareKernel, SamplesFollowTheAnalyticProfile) {
    const float pitch = 0.05f;
    const GlareKernelParameters p = eye(pitch);
    const GlareKernelImage k = sampleGlareKernel(p);
    const double total = k.energy;
    // The samples' total is the PSF's energy within the extent, but for the pixels next to the centre, where
    // a sample at the pixel's centre is not the mean over its square.
    EXPECT_NEAR(total, glareEnclosedEnergy(p, 4.0), 0.1 * total);
    for (const int d : {1, 2, 8, 12, 24, 48, 70}) {
        const double want = glarePsf(p, d * pitch, 0.0) * pitch * pitch / total;
        EXPECT_NEAR(k.at(d, 0), want, 1e-5 * want) << d;
        const double diagonal = glarePsf(p, d * pitch, d * pitch) * pitch * pitch / total;
        EXPECT_NEAR(k.at(d, d), diagonal, 1e-5 * diagonal) << d;
    }
    // The centre pixel holds what falls on its square: more than its inscribed disc, less than the circle
    // about it.
    EXPECT_GT(k.core() * total, glareEnclosedEnergy(p, 0.5 * pitch));
    EXPECT_LT(k.core() * total, glareEnclosedEnergy(p, 0.5 * std::sqrt(2.0) * pitch));
}

TEST(GlareKernel, AnglesNotPixelsSetItsSize) {
    // The same kernel at two resolutions of one field of view: the energy within an angle is the same.
    const GlareKernelImage coarse = sampleGlareKernel(eye(0.08f));
    const GlareKernelImage fine = sampleGlareKernel(eye(0.04f));
    EXPECT_EQ(fine.radius, 2 * coarse.radius);
    for (const double theta : {0.5, 1.0, 2.0, 3.0}) {
        EXPECT_NEAR(within(coarse, 0.08f, theta), within(fine, 0.04f, theta), 0.01) << theta;
    }
}

TEST(GlareKernel, HaloIsTheKernelWithoutItsCentre) {
    const GlareKernelImage k = sampleGlareKernel(eye(0.05f));
    const GlareKernelImage halo = glareHalo(k);
    EXPECT_EQ(halo.core(), 0.0f);
    EXPECT_NEAR(sum(halo), 1.0, 1e-5);
    const double s = 1.0 - double(k.core());
    EXPECT_NEAR(halo.at(5, 2) * s, k.at(5, 2), 1e-6 * k.at(5, 2));
    // The eye keeps about half of a pixel's light in it at this pitch: most of the core and f1.
    EXPECT_GT(k.core(), 0.3f);
    EXPECT_LT(k.core(), 0.9f);
}

TEST(GlareKernel, CameraSpikesOnePerEdgeTwiceForOddBlades) {
    EXPECT_EQ(glareSpikeCount(6), 6);
    EXPECT_EQ(glareSpikeCount(8), 8);
    EXPECT_EQ(glareSpikeCount(5), 10);
    EXPECT_EQ(glareSpikeCount(7), 14);
    for (const int blades : {5, 6}) {
        const float pitch = 0.05f;
        const GlareKernelImage k = sampleGlareKernel(camera(pitch, blades, 10.0f));
        const int spikes = glareSpikeCount(blades);
        // On a circle of 30 pixels (the largest of the 3x3 pixels about a point, a ray being about a pixel
        // wide): maxima at each spike's angle, far above the midpoints between them.
        const auto at = [&](double degrees) {
            const double a = degrees * kPi / 180.0;
            const int x = int(std::lround(30.0 * std::cos(a))), y = int(std::lround(30.0 * std::sin(a)));
            float most = 0.0f;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    most = std::max(most, k.at(x + i, y + j));
            return most;
        };
        for (int s = 0; s < spikes; ++s) {
            const double on = 10.0 + 360.0 * s / spikes;
            const double between = on + 180.0 / spikes;
            EXPECT_GT(at(on), 4.0f * at(between)) << blades << " blades, spike " << s;
            EXPECT_NEAR(at(on), at(10.0), 0.3f * at(10.0)) << blades << " blades, spike " << s;
        }
    }
}

TEST(GlareKernel, BadInputIsNamed) {
    const auto message = [](const GlareKernelParameters& p) {
        try {
            (void)sampleGlareKernel(p);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("did not throw");
    };
    EXPECT_NE(message(eye(0.0f)).find("degrees per pixel 0"), std::string::npos);
    EXPECT_NE(message(eye(0.05f, -1.0f)).find("radiusDeg -1"), std::string::npos);
    EXPECT_NE(message(camera(0.05f, 2)).find("blades 2"), std::string::npos);
}

TEST(GlareSettings, ModeAndKernelReadByName) {
    Settings s;
    applySettingsOverride(s, "bloom.mode=glare");
    applySettingsOverride(s, "bloom.glareKernel=camera");
    applySettingsOverride(s, "bloom.fieldOfViewDeg=40");
    EXPECT_EQ(s.bloom.mode, BloomMode::Glare);
    EXPECT_EQ(s.bloom.glareKernel, GlareKernel::Camera);
    EXPECT_EQ(s.bloom.fieldOfViewDeg, 40.0f);
    const auto issues = readSettingsJson(R"({"postEffects": {"bloom": {"glareKernel": "owl"}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].path, "postEffects.bloom.glareKernel");
    EXPECT_EQ(issues[0].code, SettingsIssueCode::BadEnum);
    Settings t;
    const auto mix = readSettingsJson(R"({"postEffects": {"bloom": {"mode": "glare", "intensity": 2}}})", t);
    ASSERT_EQ(mix.size(), 1u);
    EXPECT_EQ(mix[0].path, "postEffects.bloom.intensity");
}

} // namespace
} // namespace photopic
