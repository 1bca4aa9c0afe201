// The glTF BRDF's pieces (core/Brdf.h) against their closed forms and a case worked by hand.

#include "core/Brdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace photopic {

namespace {
constexpr double kPi = std::numbers::pi;
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

} // namespace photopic
