// The CPU side of image-based lighting against independent integrals: the glTF BRDF's pieces against their
// closed forms, the split-sum table (Karis 2013) against a brute-force quadrature over the hemisphere, the
// nine-coefficient irradiance (Ramamoorthi & Hanrahan 2001) against exact cosine-weighted integrals, GGX
// sampling against its density, and a white furnace that ties the BRDF and the table together.

#include "core/Brdf.h"
#include "core/Ibl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace photopic {

namespace {

constexpr double kPi = std::numbers::pi;

/// The specular integral of the BRDF for F0 = 0 and F0 = 1 split as the table splits it, by the midpoint rule
/// on a grid uniform in solid angle (cos theta x phi), v in the xz half-plane so phi covers [0, pi] twice.
glm::dvec2 bruteForceScaleBias(double NdotV, double roughness, int cosSteps, int phiSteps) {
    const double alpha = roughness * roughness;
    const glm::dvec3 v(std::sqrt(1.0 - NdotV * NdotV), 0.0, NdotV);
    const double cell = (1.0 / cosSteps) * (kPi / phiSteps);
    glm::dvec2 sum(0.0);
    for (int i = 0; i < cosSteps; ++i) {
        const double ct = (i + 0.5) / cosSteps;
        const double st = std::sqrt(1.0 - ct * ct);
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = (j + 0.5) * kPi / phiSteps;
            const glm::dvec3 l(st * std::cos(phi), st * std::sin(phi), ct);
            const glm::dvec3 h = glm::normalize(v + l);
            const double dv = double(ggxDistribution(float(h.z), float(alpha))) *
                              double(smithGgxVisibility(float(NdotV), float(ct), float(alpha)));
            const double w = double(schlickWeight(float(glm::dot(v, h))));
            sum += glm::dvec2(1.0 - w, w) * (dv * ct * cell);
        }
    }
    return 2.0 * sum;
}

/// Unit vectors spread evenly over the sphere (a Fibonacci lattice).
std::vector<glm::vec3> sphereDirections(int count) {
    std::vector<glm::vec3> dirs;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - (i + 0.5) * 2.0 / count;
        const double r = std::sqrt(1.0 - y * y);
        dirs.emplace_back(float(r * std::cos(golden * i)), float(y), float(r * std::sin(golden * i)));
    }
    return dirs;
}

/// Cosine-weighted integral of a radiance function over the hemisphere around n, by the midpoint rule in
/// (cos theta, phi) about n: the exact irradiance to within the quadrature's error.
template <class Radiance>
double exactIrradiance(glm::dvec3 n, Radiance radiance, int steps) {
    glm::dvec3 t =
        std::abs(n.z) < 0.9 ? glm::cross(glm::dvec3(0, 0, 1), n) : glm::cross(glm::dvec3(1, 0, 0), n);
    t = glm::normalize(t);
    const glm::dvec3 b = glm::cross(n, t);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double ct = (i + 0.5) / steps;
        const double st = std::sqrt(1.0 - ct * ct);
        for (int j = 0; j < 2 * steps; ++j) {
            const double phi = (j + 0.5) * kPi / steps;
            const glm::dvec3 l = t * (st * std::cos(phi)) + b * (st * std::sin(phi)) + n * ct;
            sum += radiance(l) * ct;
        }
    }
    return sum * (1.0 / steps) * (kPi / steps);
}

} // namespace

// --- BRDF ---

// D is a density of microfacet normals: its projected integral over the hemisphere is 1 for every alpha.
TEST(Brdf, GgxDistributionIsNormalised) {
    for (const float roughness : {0.2f, 0.5f, 0.8f, 1.0f}) {
        const float alpha = roughness * roughness;
        const int steps = 200000;
        double sum = 0.0;
        for (int i = 0; i < steps; ++i) {
            const double c = (i + 0.5) / steps;
            sum += double(ggxDistribution(float(c), alpha)) * c;
        }
        EXPECT_NEAR(sum * 2.0 * kPi / steps, 1.0, 1e-3) << "roughness " << roughness;
    }
    // alpha = 1 is the uniform distribution of normals, D = 1 / pi.
    EXPECT_NEAR(ggxDistribution(0.3f, 1.0f), 1.0f / float(kPi), 1e-6f);
}

TEST(Brdf, SmithVisibilityClosedForms) {
    // At n.v = n.l = 1 nothing is masked: G2 = 1 and V = 1 / 4 for every alpha.
    for (const float alpha : {0.0f, 0.1f, 0.5f, 1.0f}) {
        EXPECT_NEAR(smithGgxVisibility(1.0f, 1.0f, alpha), 0.25f, 1e-6f);
    }
    // alpha = 0: no masking anywhere, V = 1 / (4 n.v n.l).
    EXPECT_NEAR(smithGgxVisibility(0.3f, 0.7f, 0.0f), 1.0f / (4.0f * 0.3f * 0.7f), 1e-5f);
    EXPECT_FLOAT_EQ(smithGgxVisibility(0.3f, 0.7f, 0.4f), smithGgxVisibility(0.7f, 0.3f, 0.4f));
    EXPECT_LT(smithGgxVisibility(0.3f, 0.7f, 0.8f), smithGgxVisibility(0.3f, 0.7f, 0.2f));
    EXPECT_EQ(smithGgxVisibility(0.5f, 0.0f, 0.5f), 0.0f);
    EXPECT_EQ(smithGgxVisibility(-0.1f, 0.5f, 0.5f), 0.0f);
}

TEST(Brdf, SchlickFresnel) {
    EXPECT_FLOAT_EQ(fresnelSchlick(0.04f, 1.0f), 0.04f);
    EXPECT_FLOAT_EQ(fresnelSchlick(0.04f, 0.0f), 1.0f);
    EXPECT_NEAR(fresnelSchlick(0.04f, 0.5f), 0.04f + 0.96f / 32.0f, 1e-7f);
    const glm::vec3 f = fresnelSchlick(glm::vec3(1.0f, 0.5f, 0.0f), 0.5f);
    EXPECT_NEAR(f.y, 0.5f + 0.5f / 32.0f, 1e-7f);
    EXPECT_NEAR(f.z, 1.0f / 32.0f, 1e-7f);
}

// n = v = l: h = n, D = 1 / (pi alpha^2), V = 1/4, F = F0; worked by hand from glTF's appendix B.
TEST(Brdf, HandWorkedNormalIncidence) {
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const PbrMaterial dielectric{.baseColor = {1.0f, 0.5f, 0.25f}, .metallic = 0.0f, .roughness = 0.5f};
    // alpha = 0.25, alpha^2 = 0.0625.
    const float specular = 0.04f * (1.0f / (float(kPi) * 0.0625f)) * 0.25f;
    const glm::vec3 expected = glm::vec3(specular) + 0.96f * dielectric.baseColor / float(kPi);
    const glm::vec3 got = brdf(n, n, n, dielectric);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], expected[c], 1e-5f * expected[c]) << c;
    }
    const PbrMaterial metal{.baseColor = {0.9f, 0.6f, 0.3f}, .metallic = 1.0f, .roughness = 0.5f};
    const BrdfLobes lobes = brdfLobes(n, n, n, metal);
    EXPECT_EQ(lobes.diffuse, glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(lobes.specular[c], metal.baseColor[c] / (float(kPi) * 0.0625f) * 0.25f, 1e-5f);
    }
}

TEST(Brdf, ReciprocalAndZeroBelowTheHorizon) {
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const glm::vec3 v = glm::normalize(glm::vec3(0.3f, 0.8f, -0.2f));
    const glm::vec3 l = glm::normalize(glm::vec3(-0.6f, 0.4f, 0.5f));
    const PbrMaterial m{.baseColor = {0.8f, 0.4f, 0.2f}, .metallic = 0.3f, .roughness = 0.6f};
    const glm::vec3 a = brdf(n, v, l, m);
    const glm::vec3 b = brdf(n, l, v, m);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a[c], b[c], 1e-6f * a[c]);
    }
    EXPECT_EQ(brdf(n, v, glm::vec3(0.0f, -1.0f, 0.0f), m), glm::vec3(0.0f));
    EXPECT_EQ(brdf(n, glm::normalize(glm::vec3(1.0f, -0.1f, 0.0f)), l, m), glm::vec3(0.0f));
}

// --- Sampling ---

TEST(IblSampling, HammersleyPoints) {
    EXPECT_EQ(hammersley(0, 8), glm::vec2(0.0f, 0.0f));
    EXPECT_EQ(hammersley(1, 8), glm::vec2(0.125f, 0.5f));
    EXPECT_EQ(hammersley(2, 8), glm::vec2(0.25f, 0.25f));
    EXPECT_EQ(hammersley(3, 8), glm::vec2(0.375f, 0.75f));
    EXPECT_EQ(hammersley(5, 8), glm::vec2(0.625f, 0.625f));
}

TEST(IblSampling, GgxHalfVectorsAreUnitAndAroundTheNormal) {
    const std::vector<glm::vec3> normals = {
        {0, 0, 1}, {0, 0, -1}, {0, 1, 0}, glm::normalize(glm::vec3(1, -2, 3))};
    for (const glm::vec3 n : normals) {
        for (const float roughness : {0.0f, 0.3f, 1.0f}) {
            for (std::uint32_t i = 0; i < 256; ++i) {
                const glm::vec3 h = importanceSampleGgx(hammersley(i, 256), roughness, n);
                ASSERT_NEAR(glm::length(h), 1.0f, 1e-5f);
                ASSERT_GE(glm::dot(n, h), -1e-6f);
                if (roughness == 0.0f) {
                    ASSERT_GT(glm::dot(n, h), 1.0f - 1e-6f);
                }
            }
        }
    }
}

// The reflected directions l = reflect(-v, h) fall into bins of the sphere as often as the integral of
// D (n.h) / (4 v.h) over each bin says. The bins are 8 polar bands about n x 4 azimuth sectors; the expected
// masses come from a fine midpoint quadrature of the density. Pearson's statistic is compared with the 99.9%
// quantile of chi-square for 31 degrees of freedom (61.1): what independent random samples would pass, and
// Hammersley points, being more even, do by a wide margin.
TEST(IblSampling, ReflectedDirectionsFollowTheirDensity) {
    constexpr int kBands = 8;
    constexpr int kSectors = 4;
    constexpr std::uint32_t kSamples = 4096;
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 v = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f));
    auto bin = [](glm::vec3 l) {
        const int band = std::min(kBands - 1, int((1.0f - l.z) * 0.5f * kBands));
        const float phi = std::atan2(l.y, l.x) + float(kPi);
        const int sector = std::min(kSectors - 1, int(phi / (2.0f * float(kPi)) * kSectors));
        return band * kSectors + sector;
    };
    for (const float roughness : {0.5f, 0.8f}) {
        std::vector<double> expected(kBands * kSectors, 0.0);
        const int steps = 400;
        for (int i = 0; i < steps; ++i) {
            const double z = -1.0 + (i + 0.5) * 2.0 / steps;
            const double r = std::sqrt(1.0 - z * z);
            for (int j = 0; j < 2 * steps; ++j) {
                const double phi = -kPi + (j + 0.5) * kPi / steps;
                const glm::vec3 l(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
                const glm::vec3 h = glm::normalize(v + l);
                // A half vector below n's horizon is sampled as -h: l's density is that of |n.h|.
                const double pdf = ggxReflectionPdf(std::abs(glm::dot(n, h)), glm::dot(v, h), roughness);
                expected[std::size_t(bin(l))] += pdf * (2.0 / steps) * (kPi / steps);
            }
        }
        std::vector<double> observed(kBands * kSectors, 0.0);
        for (std::uint32_t i = 0; i < kSamples; ++i) {
            const glm::vec3 h = importanceSampleGgx(hammersley(i, kSamples), roughness, n);
            observed[std::size_t(bin(glm::reflect(-v, h)))] += 1.0;
        }
        double chi2 = 0.0;
        double total = 0.0;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            total += expected[k];
            const double e = expected[k] * kSamples;
            if (e > 0.0) {
                chi2 += (observed[k] - e) * (observed[k] - e) / e;
            }
        }
        std::printf("ibl ggx sampling, roughness %.1f: density mass %.5f, chi-square %.3f\n", roughness,
                    total, chi2);
        EXPECT_NEAR(total, 1.0, 2e-3) << "the density integrates to 1 over the sphere";
        EXPECT_LT(chi2, 61.1) << "roughness " << roughness;
    }
}

TEST(IblSampling, FilteredSampleLod) {
    const float texel = cubemapTexelSolidAngle(256);
    EXPECT_NEAR(texel * 6.0f * 256.0f * 256.0f, 4.0f * float(kPi), 1e-4f);
    // A sample standing for 4 texels reads level 1; for 16, level 2; for fewer than 1, level 0.
    EXPECT_NEAR(filteredSampleLod(1.0f / (64.0f * 4.0f * texel), 64, texel), 1.0f, 1e-5f);
    EXPECT_NEAR(filteredSampleLod(1.0f / (64.0f * 16.0f * texel), 64, texel), 2.0f, 1e-5f);
    EXPECT_NEAR(filteredSampleLod(1.0f / (64.0f * 16.0f * texel), 64, texel, 1.0f), 3.0f, 1e-5f);
    EXPECT_EQ(filteredSampleLod(1.0f / (64.0f * 0.5f * texel), 64, texel), 0.0f);
    // Roughness 0: every sample is the mirror direction with an infinite density, so the prefilter reads the
    // source itself, whatever the sample count.
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (std::uint32_t i = 0; i < 16; ++i) {
        const glm::vec3 h = importanceSampleGgx(hammersley(i, 16), 0.0f, n);
        EXPECT_EQ(filteredSampleLod(ggxReflectionPdf(h.z, h.z, 0.0f), 16, texel), 0.0f);
    }
    // Rougher lobes are lower at their peak (h = n, D = 1 / (pi alpha^2)): the peak sample reads a higher
    // level.
    float previous = -1.0f;
    for (const float roughness : {0.2f, 0.4f, 0.6f, 0.8f, 1.0f}) {
        const glm::vec3 h = importanceSampleGgx(hammersley(0, 16), roughness, n);
        const float lod = filteredSampleLod(ggxReflectionPdf(h.z, h.z, roughness), 16, texel);
        EXPECT_GT(lod, previous) << roughness;
        previous = lod;
    }
}

// --- Split sum ---

// The table's trends, on texels with n.v >= 0.27: towards grazing views the estimate's error grows (the
// samples that reflect below the horizon are lost; a 512-sample texel at n.v = 1/64 is off by up to 0.05)
// and the true A + B there is no longer monotonic in roughness (it dips near roughness 0.15 and recovers).
TEST(IblSplitSum, TableIsBoundedAndMonotonic) {
    constexpr int kSize = 32;
    const SplitSumLut lut = splitSumLut(kSize, 512);
    ASSERT_EQ(lut.rg.size(), std::size_t(kSize * kSize * 2));
    // Texel centres: x is n.v, y roughness, both (i + 0.5) / size.
    EXPECT_EQ(lut.at(3, 20), splitSumScaleBias(3.5f / kSize, 20.5f / kSize, 512));
    float maxSum = 0.0f;
    float worstRise = -1.0f;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 ab = lut.at(x, y);
            ASSERT_GE(ab.x, 0.0f);
            ASSERT_GE(ab.y, 0.0f);
            maxSum = std::max(maxSum, ab.x + ab.y);
            if (x < 8) {
                continue;
            }
            // Towards the normal: less Fresnel (B falls). A has no such trend: rough lobes reflect more at
            // grazing views than at normal incidence.
            worstRise = std::max(worstRise, ab.y - lut.at(x - 1, y).y);
            if (y > 0) {
                // Rougher: more energy lost to the single-scattering model (A + B falls).
                const glm::vec2 smoother = lut.at(x, y - 1);
                worstRise = std::max(worstRise, (ab.x + ab.y) - (smoother.x + smoother.y));
            }
        }
    }
    std::printf("ibl split sum 32 x 32: max A + B %.6f, worst trend violation %.2e\n", maxSum, worstRise);
    EXPECT_LE(maxSum, 1.0f + 1e-4f);
    EXPECT_LE(worstRise, 0.0f);
}

// At roughness 0 the lobe is the mirror direction: the integral is Schlick's Fresnel at n.v itself, so
// A = 1 - (1 - n.v)^5 and B = (1 - n.v)^5, and at n.v = 1, A = 1 and B = 0.
TEST(IblSplitSum, SmoothSurfaceIsFresnelAtTheView) {
    for (const float NdotV : {0.05f, 0.3f, 0.7f, 1.0f}) {
        const glm::vec2 ab = splitSumScaleBias(NdotV, 0.0f, 64);
        const float w = schlickWeight(NdotV);
        EXPECT_NEAR(ab.x, 1.0f - w, 1e-5f) << NdotV;
        EXPECT_NEAR(ab.y, w, 1e-5f) << NdotV;
    }
    const glm::vec2 normal = splitSumScaleBias(1.0f, 0.0f, 64);
    EXPECT_NEAR(normal.x + normal.y, 1.0f, 1e-6f);
    EXPECT_NEAR(normal.y, 0.0f, 1e-6f);
}

// Each estimate is checked against the other within the sum of their own error bounds, each taken as its
// change from a 4x coarser estimate: the midpoint rule's error falls 4x per halving of the grid and the
// Hammersley estimate's about 4x per 4x the samples, so a converging estimate is within that change of its
// limit.
TEST(IblSplitSum, MatchesBruteForceQuadrature) {
    double maxError = 0.0;
    double maxBound = 0.0;
    for (const double roughness : {0.3, 0.5, 0.7, 1.0}) {
        for (const double NdotV : {0.15, 0.5, 0.9}) {
            const glm::dvec2 fine = bruteForceScaleBias(NdotV, roughness, 600, 300);
            const glm::dvec2 coarse = bruteForceScaleBias(NdotV, roughness, 300, 150);
            const glm::dvec2 lut(splitSumScaleBias(float(NdotV), float(roughness), 16384));
            const glm::dvec2 lutCoarse(splitSumScaleBias(float(NdotV), float(roughness), 4096));
            for (int c = 0; c < 2; ++c) {
                maxBound =
                    std::max(maxBound, std::abs(fine[c] - coarse[c]) + std::abs(lut[c] - lutCoarse[c]));
                maxError = std::max(maxError, std::abs(lut[c] - fine[c]));
            }
        }
    }
    std::printf("ibl split sum, 16384 samples vs quadrature: max error %.6f, bound %.6f\n", maxError,
                maxBound);
    EXPECT_LE(maxError, maxBound);
    EXPECT_LT(maxError, 2e-3);
}

// At roughness 1, alpha = 1: D = 1 / pi and V = 1 / (2 (n.l + n.v)); at n.v = 1 the albedo is
// integral over [0, 1] of mu / (1 + mu) = 1 - ln 2 = 0.307, the single-scattering loss that makes rough
// metals darker than they should be.
TEST(IblSplitSum, SingleScatteringLosesEnergyWhenRough) {
    const glm::vec2 normal = splitSumScaleBias(1.0f, 1.0f, 4096);
    EXPECT_NEAR(normal.x + normal.y, 1.0 - std::log(2.0), 2e-3);
    for (const double NdotV : {0.2, 0.5, 1.0}) {
        const glm::dvec2 brute = bruteForceScaleBias(NdotV, 1.0, 400, 200);
        const glm::vec2 ab = splitSumScaleBias(float(NdotV), 1.0f, 4096);
        std::printf("ibl split sum, roughness 1, n.v %.1f: A + B %.5f, quadrature %.5f\n", NdotV, ab.x + ab.y,
                    brute.x + brute.y);
        EXPECT_NEAR(ab.x + ab.y, brute.x + brute.y, 2e-3);
        EXPECT_LT(brute.x + brute.y, 0.7);
    }
}

// --- Environments and irradiance ---

TEST(IblEquirect, DirectionConvention) {
    const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-6f; };
    EXPECT_TRUE(near(equirectDirection({0.5f, 0.5f}), {0, 0, -1})) << "the centre looks down -z";
    EXPECT_TRUE(near(equirectDirection({0.75f, 0.5f}), {1, 0, 0})) << "the right quarter is +x";
    EXPECT_TRUE(near(equirectDirection({0.25f, 0.5f}), {-1, 0, 0}));
    EXPECT_TRUE(near(equirectDirection({0.0f, 0.5f}), {0, 0, 1})) << "the edges are behind";
    EXPECT_TRUE(near(equirectDirection({0.3f, 0.0f}), {0, 1, 0})) << "the top row is up";
    EXPECT_TRUE(near(equirectDirection({0.3f, 1.0f}), {0, -1, 0}));
    for (const glm::vec3 d : sphereDirections(200)) {
        EXPECT_LT(glm::length(equirectDirection(equirectUv(d)) - d), 1e-5f);
    }
}

TEST(IblSh9, ConstantEnvironmentIsPiL) {
    ImageF env(64, 32);
    for (std::size_t i = 0; i < env.pixelCount(); ++i) {
        env.rgba[i * 4 + 0] = 2.0f;
        env.rgba[i * 4 + 1] = 1.0f;
        env.rgba[i * 4 + 2] = 0.5f;
    }
    const Sh9 sh = projectEquirectSh9(env);
    double maxRel = 0.0;
    for (const glm::vec3 n : sphereDirections(100)) {
        const glm::vec3 e = shIrradiance(sh, n);
        const glm::vec3 expected = float(kPi) * glm::vec3(2.0f, 1.0f, 0.5f);
        for (int c = 0; c < 3; ++c) {
            maxRel = std::max(maxRel, std::abs(double(e[c]) / double(expected[c]) - 1.0));
        }
        EXPECT_NEAR(shLambertRadiance(sh, n).x, 2.0f, 2e-3f);
    }
    std::printf("ibl sh9, constant environment 64 x 32: max relative error %.3g\n", maxRel);
    EXPECT_LT(maxRel, 1e-3);
}

// A sky of radiance L above the horizon and black below. Its irradiance, pi L (1 + n.y) / 2, lies in bands 0
// and 1 alone (the cosine lobe has no odd bands above 1, and a hemisphere has no even bands above 0), so the
// nine coefficients carry no truncation error here: what is left is the texels' quadrature, which the
// tolerance covers (the horizon falls on a row boundary, so the sky is exactly the upper 16 rows).
TEST(IblSh9, SkyAboveBlackBelow) {
    constexpr float kSky = 1.5f;
    ImageF env(64, 32);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 64; ++x) {
            std::fill_n(env.at(x, y), 3, kSky);
        }
    }
    const Sh9 sh = projectEquirectSh9(env);
    const auto sky = [](glm::dvec3 l) { return l.y > 0.0 ? double(kSky) : 0.0; };
    std::vector<glm::vec3> normals = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}};
    for (const glm::vec3 n : sphereDirections(12)) {
        normals.push_back(n);
    }
    double maxError = 0.0;
    for (const glm::vec3 n : normals) {
        const double exact = exactIrradiance(glm::dvec3(n), sky, 200);
        const double got = shIrradiance(sh, n).x;
        maxError = std::max(maxError, std::abs(got - exact) / (kPi * kSky));
        EXPECT_NEAR(got, exact, 2e-3 * kPi * kSky) << n.x << " " << n.y << " " << n.z;
    }
    EXPECT_NEAR(shIrradiance(sh, {0, 1, 0}).x, kPi * kSky, 2e-3 * kPi * kSky);
    EXPECT_NEAR(shIrradiance(sh, {0, -1, 0}).x, 0.0, 2e-3 * kPi * kSky);
    std::printf("ibl sh9, sky above black below: max |E - exact| / (pi L) %.3g, E(up) / (pi L) %.6f, E(down) "
                "/ (pi L) %.3g\n",
                maxError, shIrradiance(sh, {0, 1, 0}).x / (kPi * kSky),
                shIrradiance(sh, {0, -1, 0}).x / (kPi * kSky));
}

// One bright texel is a point light of power P = L * (its solid angle) at its centre d. The nine coefficients
// give E(n) = P (1/4 + (n.d) / 2 + (5/16) P2(n.d)) (the bands' A_l (2l + 1) / 4pi): largest at n = d, where
// it is 17/16 P against the exact P, the truncation overshoot that ringing of a small bright source brings.
TEST(IblSh9, BrightTexelPeaksAtItsDirection) {
    ImageF env(64, 32);
    constexpr int kX = 41;
    constexpr int kY = 9;
    std::fill_n(env.at(kX, kY), 3, 1000.0f);
    const glm::vec3 d = equirectDirection({(kX + 0.5f) / 64.0f, (kY + 0.5f) / 32.0f});
    const double solidAngle =
        (std::cos(kPi * kY / 32.0) - std::cos(kPi * (kY + 1) / 32.0)) * 2.0 * kPi / 64.0;
    const double power = 1000.0 * solidAngle;
    const Sh9 sh = projectEquirectSh9(env);
    const float peak = shIrradiance(sh, d).x;
    EXPECT_NEAR(peak, power * 17.0 / 16.0, 1e-4 * power);
    for (const glm::vec3 n : sphereDirections(2000)) {
        const double c = glm::dot(n, d);
        const double expected = power * (0.25 + 0.5 * c + 5.0 / 16.0 * 0.5 * (3.0 * c * c - 1.0));
        ASSERT_NEAR(shIrradiance(sh, n).x, expected, 1e-4 * power);
        ASSERT_LE(shIrradiance(sh, n).x, peak);
    }
}

// Shifting the image a quarter turn to the right moves the content at longitude phi to phi + pi/2, the
// rotation R(x, y, z) = (-z, y, x) about +y: band 0 is unchanged, the band-1 coefficients (the vector
// (L11, L1-1, L10) in x, y, z) turn by R, and the irradiance follows, E'(R n) = E(n). The texels map onto
// texels of the same solid angle, so the match is exact up to rounding.
TEST(IblSh9, QuarterTurnRotatesTheCoefficients) {
    ImageF env(64, 32);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
            float* p = env.at(x, y);
            p[0] = 0.2f + 0.01f * float(x);
            p[1] = 0.1f + 0.02f * float(y);
            p[2] = (x / 8 + y / 8) % 2 == 0 ? 1.0f : 0.0f;
        }
    }
    std::fill_n(env.at(10, 6), 3, 500.0f);
    ImageF turned(64, 32);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
            std::copy_n(env.at(x, y), 4, turned.at((x + 16) % 64, y));
        }
    }
    const Sh9 a = projectEquirectSh9(env);
    const Sh9 b = projectEquirectSh9(turned);
    const auto rotate = [](glm::vec3 v) { return glm::vec3(-v.z, v.y, v.x); };
    for (int c = 0; c < 3; ++c) {
        const float scale = std::abs(a.c[0][c]);
        EXPECT_NEAR(b.c[0][c], a.c[0][c], 1e-5f * scale);
        const glm::vec3 band1(a.c[3][c], a.c[1][c], a.c[2][c]);
        const glm::vec3 expected = rotate(band1);
        EXPECT_NEAR(b.c[3][c], expected.x, 1e-5f * scale);
        EXPECT_NEAR(b.c[1][c], expected.y, 1e-5f * scale);
        EXPECT_NEAR(b.c[2][c], expected.z, 1e-5f * scale);
    }
    for (const glm::vec3 n : sphereDirections(50)) {
        const glm::vec3 e = shIrradiance(a, n);
        const glm::vec3 f = shIrradiance(b, rotate(n));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(f[c], e[c], 1e-4f * (std::abs(e[c]) + 1.0f));
        }
    }
}

TEST(IblSh9, RejectsAnEmptyImage) {
    EXPECT_THROW((void)projectEquirectSh9(ImageF{}), std::invalid_argument);
    EXPECT_THROW((void)splitSumLut(0, 16), std::invalid_argument);
}

// --- White furnace ---

namespace {

/// Directional albedo of brdf(): the integral of f (n.l) over the hemisphere under a white environment of
/// radiance 1. Multiple importance sampling (the balance heuristic) of cosine-weighted and GGX-sampled
/// directions, Hammersley points for both, so neither lobe is missed: the diffuse lobe by GGX samples of a
/// smooth surface, nor the narrow specular lobe by cosine samples.
glm::dvec3 furnaceAlbedo(const PbrMaterial& material, float NdotV, std::uint32_t count) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV);
    const float roughness = std::max(material.roughness, kMinRoughness);
    const auto weight = [&](glm::vec3 l) {
        if (l.z <= 0.0f) {
            return glm::dvec3(0.0);
        }
        const glm::vec3 h = glm::normalize(v + l);
        const double pdf = double(l.z) / kPi + double(ggxReflectionPdf(h.z, glm::dot(v, h), roughness));
        return glm::dvec3(brdf(n, v, l, material)) * (double(l.z) / (double(count) * pdf));
    };
    glm::dvec3 sum(0.0);
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec2 xi = hammersley(i, count);
        const float r = std::sqrt(xi.y);
        const float phi = 2.0f * float(kPi) * xi.x;
        sum += weight({r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0f - xi.y)});
        sum += weight(glm::reflect(-v, importanceSampleGgx(xi, roughness, n)));
    }
    return sum;
}

} // namespace

// A white dielectric keeps nearly all the light: what the Fresnel lobe takes the (1 - F) diffuse lobe gives
// up, and only the specular lobe's small single-scattering loss goes. glTF's BRDF is not energy-conserving at
// grazing views, though: the diffuse lobe is weighted by 1 - F at v.h, near F0 for most light directions,
// while the specular lobe takes F near n.v, so a grazing view reflects more than it receives (1.30 at n.v =
// 0.2, roughness 0). Only at normal incidence is the albedo bounded by 1.
TEST(IblFurnace, WhiteDielectricReflectsNearlyAll) {
    double lowest = 2.0;
    double highest = 0.0;
    for (const float roughness : {0.0f, 0.25f, 0.5f}) {
        for (const float NdotV : {0.2f, 0.5f, 1.0f}) {
            const PbrMaterial m{.baseColor = glm::vec3(1.0f), .metallic = 0.0f, .roughness = roughness};
            const double albedo = furnaceAlbedo(m, NdotV, 4096).x;
            lowest = std::min(lowest, albedo);
            highest = std::max(highest, albedo);
            EXPECT_GE(albedo, 0.95) << "roughness " << roughness << " n.v " << NdotV;
            if (NdotV == 1.0f) {
                EXPECT_LE(albedo, 1.0 + 1e-3) << "roughness " << roughness;
            }
        }
    }
    std::printf("ibl furnace, white dielectric, roughness 0..0.5, n.v 0.2..1: albedo %.4f..%.4f\n", lowest,
                highest);
}

// A white metal (F = 1) reflects the integral of D V (n.l), which is A + B of the split-sum table: the
// furnace by the BRDF and the table by its own estimator must agree. Both lose 1 - (A + B) to the missing
// multiple scattering.
TEST(IblFurnace, WhiteMetalLosesWhatTheTableSays) {
    double maxDiff = 0.0;
    double lowest = 2.0;
    for (const float roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
        for (const float NdotV : {0.2f, 0.5f, 1.0f}) {
            const PbrMaterial m{.baseColor = glm::vec3(1.0f), .metallic = 1.0f, .roughness = roughness};
            const double albedo = furnaceAlbedo(m, NdotV, 4096).x;
            const glm::vec2 ab = splitSumScaleBias(NdotV, roughness, 4096);
            maxDiff = std::max(maxDiff, std::abs(albedo - double(ab.x + ab.y)));
            lowest = std::min(lowest, albedo);
            EXPECT_LE(albedo, 1.0 + 1e-3) << "roughness " << roughness << " n.v " << NdotV;
        }
    }
    std::printf("ibl furnace, white metal: lowest albedo %.4f, max |albedo - (A + B)| %.5f\n", lowest,
                maxDiff);
    // Each estimate is within its 4096-to-16384-sample change of the integral (at most 4.4e-3 in the
    // quadrature test above; the furnace's GGX-sampled terms are no larger than the split sum's weights), so
    // the two agree to 1%.
    EXPECT_LT(maxDiff, 0.01);
}

// The diffuse lobe's Fresnel weight W(n.v) against the midpoint rule on a grid uniform in solid angle.
TEST(IblDiffuseFresnel, MatchesBruteForceQuadrature) {
    for (const float NdotV : {1.0f, 0.7f, 0.3f, 0.05f}) {
        const glm::dvec3 v(std::sqrt(1.0 - double(NdotV) * NdotV), 0.0, NdotV);
        const int cosSteps = 400;
        const int phiSteps = 400;
        double sum = 0.0;
        for (int i = 0; i < cosSteps; ++i) {
            const double c = (i + 0.5) / cosSteps;
            const double s = std::sqrt(1.0 - c * c);
            for (int j = 0; j < phiSteps; ++j) {
                const double phi = 2.0 * kPi * (j + 0.5) / phiSteps;
                const glm::dvec3 l(s * std::cos(phi), s * std::sin(phi), c);
                const double VdotH = glm::dot(v, glm::normalize(v + l));
                sum += std::pow(1.0 - VdotH, 5.0) * c / kPi;
            }
        }
        const double exact = sum * (1.0 / cosSteps) * (2.0 * kPi / phiSteps);
        const float w = diffuseSchlickWeight(NdotV, 4096);
        std::printf("ibl diffuse Fresnel weight W(%.2f) = %.5f (quadrature %.5f)\n", NdotV, w, exact);
        EXPECT_NEAR(w, exact, 2e-4 + 0.01 * exact) << "n.v " << NdotV;
    }
    EXPECT_LT(diffuseSchlickWeight(1.0f, 1024), diffuseSchlickWeight(0.2f, 1024));
}

namespace {

ImageF gradientEnvironment(int width, int height) {
    ImageF env(width, height, 1.0f);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height});
            float* p = env.at(x, y);
            p[0] = 0.2f + d.x * d.x;
            p[1] = 1.0f + d.y;
            p[2] = 0.05f + std::max(d.z, 0.0f);
        }
    }
    return env;
}

} // namespace

// The sampler returns the density that pdf() reports for the same direction, and a sample lies in the texel
// its density belongs to; the densities integrate to 1 over the sphere.
TEST(IblEnvironmentMc, SamplerDensityIsConsistent) {
    const ImageF env = gradientEnvironment(64, 32);
    const EnvironmentDistribution dist(env);
    for (std::uint32_t i = 0; i < 256; ++i) {
        const glm::vec4 s = dist.sample(hammersley(i, 256));
        ASSERT_GT(s.w, 0.0f);
        EXPECT_NEAR(glm::length(glm::vec3(s)), 1.0f, 1e-5f);
        EXPECT_NEAR(dist.pdf(glm::vec3(s)), s.w, 1e-4f * s.w) << "sample " << i;
    }
    double integral = 0.0;
    for (int y = 0; y < env.height; ++y) {
        const double band =
            (std::cos(kPi * y / env.height) - std::cos(kPi * (y + 1) / env.height)) * 2.0 * kPi / env.width;
        for (int x = 0; x < env.width; ++x) {
            integral +=
                double(dist.pdf(equirectDirection({(x + 0.5f) / env.width, (y + 0.5f) / env.height}))) * band;
        }
    }
    EXPECT_NEAR(integral, 1.0, 1e-4);
    EXPECT_THROW(EnvironmentDistribution(ImageF{}), std::invalid_argument);
}

// Under a uniform white environment the integral is the directional albedo, which the split-sum table and the
// diffuse Fresnel weight give independently: F0 A + B + (1 - F0) (1 - W) c.
TEST(IblEnvironmentMc, UniformEnvironmentGivesTheTableAlbedo) {
    const EnvironmentDistribution white(ImageF(32, 16, 1.0f));
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    double worst = 0.0;
    for (const float roughness : {0.1f, 0.5f, 1.0f}) {
        for (const float metallic : {0.0f, 1.0f}) {
            for (const float NdotV : {0.3f, 0.8f}) {
                const PbrMaterial m{
                    .baseColor = glm::vec3(0.8f, 0.5f, 0.2f), .metallic = metallic, .roughness = roughness};
                const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV);
                const glm::vec3 mc = integrateEnvironmentBrdf(white, n, v, m, 2048, 7u);
                const glm::vec2 ab = splitSumScaleBias(NdotV, std::max(roughness, kMinRoughness), 4096);
                const float w = diffuseSchlickWeight(NdotV, 4096);
                const glm::vec3 f0 = specularF0(m);
                const glm::vec3 expected =
                    f0 * ab.x + ab.y + (glm::vec3(1.0f) - f0) * (1.0f - w) * diffuseColor(m);
                for (int c = 0; c < 3; ++c) {
                    const double error = std::abs(double(mc[c]) - expected[c]) / expected[c];
                    worst = std::max(worst, error);
                    EXPECT_LT(error, 0.01) << "roughness " << roughness << " metallic " << metallic << " n.v "
                                           << NdotV << " channel " << c;
                }
            }
        }
    }
    std::printf("ibl environment MC, uniform white: worst relative difference from the tables %.4f\n", worst);
}

// One bright texel and nothing else: the integral is the BRDF towards that texel times its radiance, its
// cosine and its solid angle (the texel is 2.8 degrees across, over which the rough lobe barely changes).
TEST(IblEnvironmentMc, SingleBrightTexelIsThePointLightSum) {
    ImageF env(128, 64, 0.0f);
    const int tx = 40;
    const int ty = 20;
    float* p = env.at(tx, ty);
    p[0] = p[1] = p[2] = 1000.0f;
    const EnvironmentDistribution dist(env);
    const glm::vec3 l = equirectDirection({(tx + 0.5f) / 128.0f, (ty + 0.5f) / 64.0f});
    const double band = (std::cos(kPi * ty / 64.0) - std::cos(kPi * (ty + 1) / 64.0)) * 2.0 * kPi / 128.0;
    const glm::vec3 n = glm::normalize(l + glm::vec3(0.3f, 0.2f, 0.1f));
    const glm::vec3 v = glm::normalize(glm::reflect(-l, n) + glm::vec3(0.0f, 0.3f, 0.0f));
    const PbrMaterial m{.baseColor = glm::vec3(0.9f, 0.6f, 0.3f), .metallic = 0.0f, .roughness = 0.6f};
    const glm::vec3 mc = integrateEnvironmentBrdf(dist, n, v, m, 256, 1u);
    const glm::vec3 expected = brdf(n, v, l, m) * glm::dot(n, l) * 1000.0f * float(band);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(mc[c], expected[c], 0.02f * expected[c]) << "channel " << c;
    }
}

} // namespace photopic
