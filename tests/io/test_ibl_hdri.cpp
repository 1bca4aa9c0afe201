// The nine-coefficient irradiance (core/Ibl.h) of a real HDRI, with the sun in frame, against the exact
// cosine integral over its texels: what the truncation to bands 0..2 costs where it costs most.

#include "core/Ibl.h"
#include "io/ImageIO.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace photopic {

// For a point source of power P at angle acos(c) from n the nine coefficients give
// P (1/4 + c/2 + (5/16) P2(c)) against the exact P max(c, 0); the difference is largest at c = 0, 3/32 P.
// Irradiance is linear in the radiance, so for any environment |E_sh9 - E| <= 3/32 of the integral of |L|
// over the sphere: the bound asserted here, a property of the truncation rather than a tuned threshold.
TEST(IblHdri, Sh9IrradianceOfBlenderSunriseWithinTheTruncationBound) {
    const ImageF env = readImage(test::dataDir() / "blender_sunrise.exr");
    ASSERT_EQ(env.width, 2 * env.height);
    const Sh9 sh = projectEquirectSh9(env);
    std::vector<glm::vec3> dirs;
    std::vector<double> weights;
    glm::dvec3 power(0.0);
    for (int y = 0; y < env.height; ++y) {
        const double c0 = std::cos(std::numbers::pi * y / env.height);
        const double c1 = std::cos(std::numbers::pi * (y + 1) / env.height);
        const double solidAngle = (c0 - c1) * 2.0 * std::numbers::pi / env.width;
        for (int x = 0; x < env.width; ++x) {
            dirs.push_back(equirectDirection({(x + 0.5f) / env.width, (y + 0.5f) / env.height}));
            weights.push_back(solidAngle);
            const float* p = env.at(x, y);
            power += glm::abs(glm::dvec3(p[0], p[1], p[2])) * solidAngle;
        }
    }
    double worstOfBound = 0.0;
    double worstOfPeak = 0.0;
    double peak = 0.0;
    std::vector<std::pair<glm::vec3, glm::dvec3>> results;
    for (int i = 0; i < 26; ++i) {
        // A Fibonacci lattice of normals over the whole sphere.
        const double ny = 1.0 - (i + 0.5) * 2.0 / 26;
        const double r = std::sqrt(1.0 - ny * ny);
        const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
        const glm::vec3 n(float(r * std::cos(phi)), float(ny), float(r * std::sin(phi)));
        glm::dvec3 exact(0.0);
        for (std::size_t t = 0; t < dirs.size(); ++t) {
            const double c = glm::dot(n, dirs[t]);
            if (c > 0.0) {
                const float* p = env.rgba.data() + t * 4;
                exact += glm::dvec3(p[0], p[1], p[2]) * (c * weights[t]);
            }
        }
        results.emplace_back(n, exact);
        peak = std::max({peak, exact.x, exact.y, exact.z});
    }
    for (const auto& [n, exact] : results) {
        const glm::dvec3 e(shIrradiance(sh, n));
        for (int c = 0; c < 3; ++c) {
            const double error = std::abs(e[c] - exact[c]);
            EXPECT_LE(error, 3.0 / 32.0 * power[c]) << "normal " << n.x << " " << n.y << " " << n.z;
            worstOfBound = std::max(worstOfBound, error / (3.0 / 32.0 * power[c]));
            worstOfPeak = std::max(worstOfPeak, error / peak);
        }
    }
    std::printf(
        "ibl sh9, blender_sunrise %d x %d: worst |E_sh9 - E| is %.2f of the bound, %.3f of the brightest "
        "irradiance (%.3f)\n",
        env.width, env.height, worstOfBound, worstOfPeak, peak);
}

} // namespace photopic
