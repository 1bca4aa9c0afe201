#include "core/Camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace photopic;

TEST(Halton, PublishedValuesInBases2And3) {
    const float base2[] = {0.5f, 0.25f, 0.75f, 0.125f, 0.625f, 0.375f, 0.875f, 0.0625f};
    const float base3[] = {1.0f / 3, 2.0f / 3, 1.0f / 9, 4.0f / 9, 7.0f / 9, 2.0f / 9, 5.0f / 9, 8.0f / 9};
    for (std::uint32_t i = 0; i < 8; ++i) {
        EXPECT_FLOAT_EQ(halton(i + 1, 2), base2[i]) << i;
        EXPECT_FLOAT_EQ(halton(i + 1, 3), base3[i]) << i;
    }
}

TEST(Halton, JitterIsCentredAndCyclesWithItsLength) {
    const glm::vec2 first = haltonJitter(0, 8);
    EXPECT_FLOAT_EQ(first.x, 0.0f);            // halton(1, 2) - 0.5
    EXPECT_FLOAT_EQ(first.y, 1.0f / 3 - 0.5f); // halton(1, 3) - 0.5
    EXPECT_EQ(haltonJitter(8, 8), first);
    EXPECT_EQ(haltonJitter(3, 1), first); // a cycle of one is a constant offset
    glm::vec2 mean(0.0f);
    for (std::uint64_t f = 0; f < 16; ++f) {
        const glm::vec2 j = haltonJitter(f, 16);
        EXPECT_GE(j.x, -0.5f);
        EXPECT_LT(j.x, 0.5f);
        EXPECT_GE(j.y, -0.5f);
        EXPECT_LT(j.y, 0.5f);
        mean += j / 16.0f;
    }
    EXPECT_NEAR(mean.x, 0.0f, 0.04f);
    EXPECT_NEAR(mean.y, 0.0f, 0.04f);
}

TEST(Jitter, MovesAProjectedPointByThatManyPixels) {
    const int w = 160, h = 90;
    const glm::mat4 p = perspectiveProjection(1.0f, float(w) / float(h), 0.1f, 100.0f);
    const glm::vec2 jitter(0.25f, -0.375f);
    const glm::mat4 pj = jitteredProjection(p, jitter, w, h);
    for (const glm::vec4 v : {glm::vec4(0.3f, -0.2f, -2.0f, 1.0f), glm::vec4(-4.0f, 1.0f, -40.0f, 1.0f)}) {
        const glm::vec4 a = p * v;
        const glm::vec4 b = pj * v;
        const float dxPixels = (b.x / b.w - a.x / a.w) * 0.5f * float(w);
        const float dyPixels = (b.y / b.w - a.y / a.w) * 0.5f * float(h);
        EXPECT_NEAR(dxPixels, jitter.x, 1e-4f);
        EXPECT_NEAR(dyPixels, jitter.y, 1e-4f);
        EXPECT_FLOAT_EQ(b.z / b.w, a.z / a.w); // depth is unchanged
    }
}

TEST(Depth, WindowDepthRoundTripsForFiniteAndInfiniteFar) {
    for (float far : {100.0f, std::numeric_limits<float>::infinity()}) {
        for (float z : {0.1f, 0.5f, 3.0f, 42.0f, 99.0f}) {
            const float d = windowDepthFromLinear(z, 0.1f, far);
            EXPECT_NEAR(linearDepthFromWindow(d, 0.1f, far), z, z * 1e-3f) << far << " " << z;
        }
        // The projection matrix agrees with the helper.
        const glm::mat4 p = perspectiveProjection(1.0f, 1.0f, 0.1f, far);
        const glm::vec4 c = p * glm::vec4(0.0f, 0.0f, -7.0f, 1.0f);
        EXPECT_NEAR(0.5f * c.z / c.w + 0.5f, windowDepthFromLinear(7.0f, 0.1f, far), 1e-6f);
    }
    EXPECT_NEAR(linearDepthFromReversed(1.0f, 0.1f, std::numeric_limits<float>::infinity()), 0.1f, 1e-6f);
    EXPECT_NEAR(linearDepthFromReversed(0.01f, 0.1f, std::numeric_limits<float>::infinity()), 10.0f, 1e-4f);
    EXPECT_NEAR(linearDepthFromReversed(1.0f, 0.1f, 100.0f), 0.1f, 1e-6f);
    EXPECT_NEAR(linearDepthFromReversed(0.0f, 0.1f, 100.0f), 100.0f, 1e-3f);
}

TEST(Camera, InvalidCamerasSayWhy) {
    Camera c;
    EXPECT_EQ(invalidCameraReason(c), nullptr);
    c.view[1][2] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(invalidCameraReason(c), nullptr);
    c = {};
    c.farPlane = std::numeric_limits<float>::infinity();
    EXPECT_EQ(invalidCameraReason(c), nullptr);
    c.nearPlane = 0.0f;
    EXPECT_NE(invalidCameraReason(c), nullptr);
    c = {};
    c.lens.fNumber = 0.0f;
    EXPECT_NE(invalidCameraReason(c), nullptr);
}

// viewRays: the point it gives for NDC (x, y) at the near (z = -1) and mid (z = 0) planes projects back to
// that NDC position, for a finite and an infinite far plane.
TEST(Camera, ViewRaysProjectBackToTheirNdcPoint) {
    for (const float far : {100.0f, std::numeric_limits<float>::infinity()}) {
        const glm::mat4 projection = perspectiveProjection(1.0f, 16.0f / 9.0f, 0.1f, far);
        glm::vec4 nearRay[3], farRay[3];
        viewRays(projection, nearRay, farRay);
        for (const glm::vec2 ndc : {glm::vec2(0.0f), glm::vec2(0.5f, -0.25f), glm::vec2(-1.0f, 1.0f)}) {
            for (int k = 0; k < 2; ++k) {
                const glm::vec4(&ray)[3] = k == 0 ? nearRay : farRay;
                const glm::vec4 view = ray[0] + ndc.x * ray[1] + ndc.y * ray[2];
                EXPECT_EQ(view.w, 0.0f);
                const glm::vec4 clip = projection * glm::vec4(glm::vec3(view), 1.0f);
                EXPECT_NEAR(clip.x / clip.w, ndc.x, 1e-4f) << "far " << far << " plane " << k;
                EXPECT_NEAR(clip.y / clip.w, ndc.y, 1e-4f) << "far " << far << " plane " << k;
                EXPECT_NEAR(clip.z / clip.w, k == 0 ? -1.0f : 0.0f, 1e-4f) << "far " << far << " plane " << k;
                EXPECT_LT(view.z, 0.0f); // in front of the camera
            }
        }
    }
}

// isPerspective: true for the projections whose view rays start at the eye with a near plane at constant z
// (plain, off-centre, jittered, infinite far), false for orthographic ones and for a perspective whose NDC z
// also depends on x (the screen-space passes then take their general programs). Where it is true, the near
// points viewRays gives lie on one z, the property the perspective programs rely on.
TEST(Camera, IsPerspectiveOnlyWhereViewRaysStartAtTheEye) {
    const glm::mat4 plain = perspectiveProjection(1.0f, 16.0f / 9.0f, 0.1f, 100.0f);
    const glm::mat4 infinite =
        perspectiveProjection(1.0f, 1.0f, 0.1f, std::numeric_limits<float>::infinity());
    const glm::mat4 offCentre = glm::frustum(-0.05f, 0.15f, -0.1f, 0.05f, 0.1f, 50.0f);
    const glm::mat4 jittered = jitteredProjection(plain, glm::vec2(0.3f, -0.4f), 640, 360);
    for (const glm::mat4& m : {plain, infinite, offCentre, jittered}) {
        EXPECT_TRUE(isPerspective(m));
        glm::vec4 nearRay[3], farRay[3];
        viewRays(m, nearRay, farRay);
        EXPECT_NEAR(nearRay[1].z, 0.0f, 1e-6f);
        EXPECT_NEAR(nearRay[2].z, 0.0f, 1e-6f);
    }
    EXPECT_FALSE(isPerspective(glm::ortho(-2.0f, 2.0f, -1.0f, 1.0f, 0.1f, 100.0f)));
    EXPECT_FALSE(isPerspective(jitteredProjection(glm::ortho(-2.0f, 2.0f, -1.0f, 1.0f, 0.1f, 100.0f),
                                                  glm::vec2(0.3f, -0.4f), 640, 360)));
    glm::mat4 tilted = plain;
    tilted[0][2] = 0.01f; // NDC z depends on x: the near plane is not z = const
    EXPECT_FALSE(isPerspective(tilted));
}
