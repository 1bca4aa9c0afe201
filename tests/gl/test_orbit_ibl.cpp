// The orbit scene's image-based lighting (scenes/orbit/OrbitIbl.h, orbit_pbr.h.glsl) against its CPU twins
// (core/Brdf.h, core/Ibl.h): a white furnace, a sphere grid under the real HDRI against a Monte-Carlo
// integration of the same BRDF, the proportionality of iblIntensity without drift, the fallback sky, and the
// cube, SH, table, prefilter and BRDF read back at chosen points.

#include "GlTest.h"
#include "common/TempFolder.h"
#include "io/TestData.h"

#include "core/Brdf.h"
#include "core/Ibl.h"
#include "core/Log.h"
#include "io/ImageIO.h"
#include "scenes/orbit/OrbitIbl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

namespace photopic::orbit {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

/// The normals of a sphere seen by an orthographic camera looking along -v, one per pixel centre of a
/// `pixels` x `pixels` square around its disc (pixels outside the disc are skipped).
std::vector<glm::vec3> sphereNormals(glm::vec3 v, int pixels) {
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), v));
    const glm::vec3 up = glm::cross(v, right);
    std::vector<glm::vec3> normals;
    for (int y = 0; y < pixels; ++y) {
        for (int x = 0; x < pixels; ++x) {
            const float px = (float(x) + 0.5f) / float(pixels) * 2.0f - 1.0f;
            const float py = (float(y) + 0.5f) / float(pixels) * 2.0f - 1.0f;
            const float r2 = px * px + py * py;
            if (r2 < 0.98f) {
                normals.push_back(glm::normalize(px * right + py * up + std::sqrt(1.0f - r2) * v));
            }
        }
    }
    return normals;
}

GpuIblProbeQuery shadeQuery(glm::vec3 n, glm::vec3 v, const PbrMaterial& m, float occlusion = 1.0f) {
    GpuIblProbeQuery q;
    q.normalMode = glm::vec4(n, float(IblProbeMode::Shade));
    q.view = glm::vec4(v, 0.0f);
    q.baseColorMetallic = glm::vec4(m.baseColor, m.metallic);
    q.surface = glm::vec4(m.roughness, occlusion, 0.0f, 0.0f);
    return q;
}

float luma(glm::vec3 c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

/// A smooth environment whose every direction has its own colour, so a mirrored or rotated lookup shows.
glm::vec3 analyticRadiance(glm::vec3 d) {
    return {0.3f + 0.7f * (0.5f + 0.5f * d.x), 0.2f + (0.5f + 0.5f * d.y), 0.1f + 0.9f * (0.5f + 0.5f * d.z)};
}

ImageF analyticEnvironment(int width, int height) {
    ImageF env(width, height, 1.0f);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec3 c = analyticRadiance(
                equirectDirection({(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)}));
            float* p = env.at(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
        }
    }
    return env;
}

/// 26 directions: the axes, the face diagonals and the cube corners.
std::vector<glm::vec3> testDirections() {
    std::vector<glm::vec3> dirs;
    for (int x = -1; x <= 1; ++x) {
        for (int y = -1; y <= 1; ++y) {
            for (int z = -1; z <= 1; ++z) {
                if (x != 0 || y != 0 || z != 0) {
                    dirs.push_back(glm::normalize(glm::vec3(float(x), float(y) + 0.1f, float(z) + 0.2f)));
                }
            }
        }
    }
    return dirs;
}

class OrbitIblTest : public test::GlTest {};

} // namespace

// A white environment of radiance 1: a white dielectric sphere reflects at least 95% of it at every
// roughness, and a white metal (F0 = 1) loses what the split sum's A + B says single scattering loses and
// no more.
TEST_F(OrbitIblTest, FurnaceWhiteSpheres) {
    const Ibl ibl(
        ImageF(64, 32, 1.0f),
        {.faceSize = 32, .specularLevels = 6, .prefilterSamples = 64, .lutSize = 32, .lutSamples = 512});
    const glm::vec3 v(0.0f, 0.0f, 1.0f);
    const std::vector<glm::vec3> normals = sphereNormals(v, 24);
    for (const float roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
        for (const float metallic : {0.0f, 1.0f}) {
            const PbrMaterial m{.baseColor = glm::vec3(1.0f), .metallic = metallic, .roughness = roughness};
            std::vector<GpuIblProbeQuery> queries;
            for (const glm::vec3& n : normals) {
                queries.push_back(shadeQuery(n, v, m));
            }
            const std::vector<glm::vec3> out = iblProbe(ibl, queries);
            double reflected = 0.0;
            double tableAlbedo = 0.0;
            for (std::size_t i = 0; i < out.size(); ++i) {
                reflected += double(luma(out[i]));
                const glm::vec2 ab = splitSumScaleBias(glm::dot(normals[i], v), roughness, 1024);
                tableAlbedo += double(ab.x + ab.y);
            }
            reflected /= double(out.size());
            tableAlbedo /= double(out.size());
            if (metallic == 0.0f) {
                std::printf("orbit ibl furnace: white dielectric, roughness %.2f reflects %.4f\n", roughness,
                            reflected);
                EXPECT_GE(reflected, 0.95) << "roughness " << roughness;
            } else {
                const double loss = 1.0 - reflected;
                const double knownLoss = 1.0 - tableAlbedo;
                std::printf(
                    "orbit ibl furnace: white metal, roughness %.2f loses %.4f (split sum's loss %.4f)\n",
                    roughness, loss, knownLoss);
                EXPECT_LE(loss, knownLoss + 0.005) << "roughness " << roughness;
                EXPECT_GE(loss, knownLoss - 0.02) << "roughness " << roughness;
            }
        }
    }
}

// Spheres of four roughnesses times three metallic values under data/blender_sunrise.exr (sun in frame),
// shaded on the GPU by orbit_pbr.h.glsl's pbrIbl (default options) and by a Monte-Carlo integration of
// core/Brdf.h's BRDF under the same image (core/Ibl.h integrateEnvironmentBrdf, 3 x 256 samples a pixel).
// The error of a sphere is that of the light it reflects: |sum of GPU - sum of MC| over the sum of MC, over
// its pixels and channels; the grid's mean must be within 3%, every sphere within 8%. The pixel-by-pixel
// difference is printed and bounded too, more loosely: two approximations of the method differ from the
// integral per pixel while keeping each sphere's total. SH9 irradiance rings around the sun (the truncation
// to bands 0..2 errs by up to 5.5% of the brightest irradiance for this image, see the io test), and the
// split sum reads an isotropic lobe where a grazing view stretches it.
TEST_F(OrbitIblTest, SphereGridMatchesMonteCarlo) {
    const ImageF env = readImage(test::dataDir() / "blender_sunrise.exr");
    const Ibl ibl(env);
    const EnvironmentDistribution reference(env);
    // The view sits 60 degrees of longitude from the sun and a little above it, so every sphere shows a lit
    // side, a terminator and the sun's highlight.
    std::size_t brightest = 0;
    for (std::size_t i = 0; i < env.pixelCount(); ++i) {
        if (env.rgba[i * 4 + 1] > env.rgba[brightest * 4 + 1]) {
            brightest = i;
        }
    }
    const glm::vec3 sun =
        equirectDirection({(float(brightest % std::size_t(env.width)) + 0.5f) / float(env.width),
                           (float(brightest / std::size_t(env.width)) + 0.5f) / float(env.height)});
    const float turn = kPi / 3.0f;
    const glm::vec3 sunFlat = glm::normalize(glm::vec3(sun.x, 0.0f, sun.z));
    const glm::vec3 v =
        glm::normalize(glm::vec3(sunFlat.x * std::cos(turn) - sunFlat.z * std::sin(turn), 0.3f,
                                 sunFlat.x * std::sin(turn) + sunFlat.z * std::cos(turn)));
    const std::vector<glm::vec3> normals = sphereNormals(v, 16);
    double sumOfErrors = 0.0;
    double sumOfPixelErrors = 0.0;
    double worst = 0.0;
    int spheres = 0;
    std::printf("orbit ibl sphere grid vs Monte Carlo, %zu pixels a sphere (sun towards %.2f %.2f %.2f):\n",
                normals.size(), sun.x, sun.y, sun.z);
    for (const float metallic : {0.0f, 0.5f, 1.0f}) {
        for (const float roughness : {0.2f, 0.45f, 0.7f, 1.0f}) {
            const PbrMaterial m{
                .baseColor = glm::vec3(0.8f, 0.55f, 0.3f), .metallic = metallic, .roughness = roughness};
            std::vector<GpuIblProbeQuery> queries;
            for (const glm::vec3& n : normals) {
                queries.push_back(shadeQuery(n, v, m));
            }
            const std::vector<glm::vec3> gpu = iblProbe(ibl, queries);
            double absError = 0.0;
            double signedError = 0.0;
            double total = 0.0;
            for (std::size_t i = 0; i < normals.size(); ++i) {
                const glm::vec3 mc =
                    integrateEnvironmentBrdf(reference, normals[i], v, m, 256, std::uint32_t(i));
                for (int c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(gpu[i][c]));
                    absError += std::abs(double(gpu[i][c]) - double(mc[c]));
                    signedError += double(gpu[i][c]) - double(mc[c]);
                    total += double(mc[c]);
                }
            }
            const double error = std::abs(signedError) / total;
            const double pixelError = absError / total;
            sumOfErrors += error;
            sumOfPixelErrors += pixelError;
            worst = std::max(worst, error);
            ++spheres;
            std::printf("  metallic %.1f roughness %.2f: sphere %+.4f, pixel by pixel %.4f\n", metallic,
                        roughness, signedError / total, pixelError);
            EXPECT_LE(error, 0.08) << "metallic " << metallic << " roughness " << roughness;
        }
    }
    const double mean = sumOfErrors / spheres;
    const double pixelMean = sumOfPixelErrors / spheres;
    std::printf("orbit ibl sphere grid: mean error %.4f, worst sphere %.4f; pixel by pixel mean %.4f\n", mean,
                worst, pixelMean);
    EXPECT_LE(mean, 0.03);
    EXPECT_LE(pixelMean, 0.15);
}

// iblIntensity scales image-based light exactly, and setting it is stateless: 0.5 against 2.0 is a factor 4
// on every pixel, and after 0.5, 2.0, 1.0 a thousand times the frame is the bits of the first.
TEST_F(OrbitIblTest, IntensityIsProportionalWithoutDrift) {
    Ibl ibl(analyticEnvironment(128, 64),
            {.faceSize = 32, .specularLevels = 6, .prefilterSamples = 32, .lutSize = 16, .lutSamples = 256});
    const glm::vec3 v = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
    std::vector<GpuIblProbeQuery> queries;
    for (const glm::vec3& n : sphereNormals(v, 12)) {
        queries.push_back(shadeQuery(
            n, v, {.baseColor = glm::vec3(0.7f, 0.4f, 0.2f), .metallic = 0.3f, .roughness = 0.6f}, 0.8f));
    }
    const std::vector<glm::vec3> first = iblProbe(ibl, queries);
    ibl.setIntensity(0.5f);
    const std::vector<glm::vec3> half = iblProbe(ibl, queries);
    ibl.setIntensity(2.0f);
    const std::vector<glm::vec3> twice = iblProbe(ibl, queries);
    double halfSum = 0.0;
    double twiceSum = 0.0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
        ASSERT_GT(luma(first[i]), 0.0f);
        EXPECT_NEAR(luma(twice[i]) / luma(half[i]), 4.0f, 0.08f) << "pixel " << i;
        halfSum += double(luma(half[i]));
        twiceSum += double(luma(twice[i]));
    }
    std::printf("orbit ibl intensity: mean at 2.0 / mean at 0.5 = %.6f\n", twiceSum / halfSum);
    EXPECT_NEAR(twiceSum / halfSum / 4.0, 1.0, 0.02);
    for (int i = 0; i < 1000; ++i) {
        ibl.setIntensity(0.5f);
        ibl.setIntensity(2.0f);
        ibl.setIntensity(1.0f);
    }
    const std::vector<glm::vec3> again = iblProbe(ibl, queries);
    EXPECT_EQ(std::memcmp(first.data(), again.data(), first.size() * sizeof(glm::vec3)), 0)
        << "the frame after 0.5, 2.0, 1.0 x 1000 differs from the first";
    ibl.setIntensity(-1.0f);
    EXPECT_EQ(ibl.intensity(), 0.0f);
}

// A missing and a truncated HDRI each give the procedural sky and exactly one warning naming the file.
TEST_F(OrbitIblTest, BrokenEnvironmentFallsBackToTheProceduralSky) {
    const test::TempFolder folder;
    const std::filesystem::path missing = folder / "no_such_sky.exr";
    const std::filesystem::path truncated = folder / "truncated_sky.exr";
    {
        std::ifstream in(test::dataDir() / "blender_sunrise.exr", std::ios::binary);
        const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_GT(bytes.size(), 1000u);
        std::ofstream out(truncated, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size() / 3));
    }
    const ImageF sky = Ibl::proceduralSky();
    for (const std::filesystem::path& path : {missing, truncated}) {
        std::vector<std::string> warnings;
        const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
            if (level == LogLevel::Warning) {
                warnings.emplace_back(message);
            }
        });
        const ImageF env = Ibl::loadEnvironmentOrFallback(path);
        setLogSink(previous);
        ASSERT_EQ(warnings.size(), 1u) << path;
        EXPECT_NE(warnings[0].find(path.filename().string()), std::string::npos) << warnings[0];
        std::printf("orbit ibl fallback: %s\n", warnings[0].c_str());
        ASSERT_EQ(env.width, sky.width);
        ASSERT_EQ(env.height, sky.height);
        EXPECT_EQ(env.rgba, sky.rgba);
    }
    // The default environment loads without a warning.
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning) {
            warnings.emplace_back(message);
        }
    });
    const ImageF env = Ibl::loadEnvironmentOrFallback(Ibl::defaultEnvironmentPath());
    setLogSink(previous);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(env.width, 1024);
    // The sky lights: a lighting built from it is finite and brighter towards the sun.
    const Ibl ibl(
        sky, {.faceSize = 32, .specularLevels = 4, .prefilterSamples = 16, .lutSize = 8, .lutSamples = 64});
    const glm::vec3 toSun = glm::normalize(glm::vec3(0.5f, 0.55f, -0.67f));
    EXPECT_GT(luma(shLambertRadiance(ibl.sh(), toSun)), 2.0f * luma(shLambertRadiance(ibl.sh(), -toSun)));
}

// The GPU resources against their CPU twins at chosen points: the cube's level 0 against the analytic
// environment it was made from (orientation of every face), the shader's SH9 against shLambertRadiance, the
// table texture against the CPU table, the prefiltered levels against a dense unfiltered GGX average on the
// CPU, and pbrDirect against core's brdf().
TEST_F(OrbitIblTest, GpuResourcesMatchTheirCpuTwins) {
    const IblOptions options{.faceSize = 64,
                             .specularLevels = 5,
                             .prefilterSamples = 1024,
                             .lodBias = 0.0f,
                             .lutSize = 16,
                             .lutSamples = 256};
    const Ibl ibl(analyticEnvironment(256, 128), options);
    const std::vector<glm::vec3> dirs = testDirections();
    std::vector<GpuIblProbeQuery> queries;
    for (const glm::vec3& d : dirs) {
        GpuIblProbeQuery cube;
        cube.normalMode = glm::vec4(d, float(IblProbeMode::Specular));
        cube.view.w = 0.0f;
        queries.push_back(cube);
        GpuIblProbeQuery diffuse;
        diffuse.normalMode = glm::vec4(d, float(IblProbeMode::Diffuse));
        queries.push_back(diffuse);
    }
    std::vector<glm::vec3> out = iblProbe(ibl, queries);
    double worstCube = 0.0;
    double worstSh = 0.0;
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        const glm::vec3 cube = out[2 * i];
        const glm::vec3 expected = analyticRadiance(dirs[i]);
        const glm::vec3 sh = out[2 * i + 1];
        const glm::vec3 shExpected = shLambertRadiance(ibl.sh(), dirs[i]);
        for (int c = 0; c < 3; ++c) {
            worstCube = std::max(worstCube, double(std::abs(cube[c] - expected[c]) / expected[c]));
            worstSh = std::max(worstSh, double(std::abs(sh[c] - shExpected[c]) / shExpected[c]));
        }
    }
    std::printf("orbit ibl twins: cube level 0 worst %.5f, SH9 worst %.6f\n", worstCube, worstSh);
    EXPECT_LT(worstCube, 0.01);
    EXPECT_LT(worstSh, 1e-4);

    // The table at texel centres (RGBA16F: 11 bits of mantissa).
    queries.clear();
    const int size = options.lutSize;
    for (int y = 0; y < size; y += 3) {
        for (int x = 0; x < size; x += 3) {
            GpuIblProbeQuery q;
            q.normalMode.w = float(IblProbeMode::Lut);
            q.view = glm::vec4((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size), 0.0f, 0.0f);
            queries.push_back(q);
        }
    }
    out = iblProbe(ibl, queries);
    double worstLut = 0.0;
    std::size_t k = 0;
    for (int y = 0; y < size; y += 3) {
        for (int x = 0; x < size; x += 3) {
            const glm::vec3 cpu = ibl.cpuLut()[std::size_t(y) * std::size_t(size) + std::size_t(x)];
            worstLut = std::max(worstLut, double(glm::length(out[k] - cpu)));
            ++k;
        }
    }
    std::printf("orbit ibl twins: table worst |GPU - CPU| %.6f\n", worstLut);
    EXPECT_LT(worstLut, 1e-3);

    // Prefiltered levels 1..4 against the (n.l)-weighted mean of 4096 GGX samples of the analytic radiance,
    // read without filtering. The GPU reads each of its samples from a mip level as wide as the sample's
    // share of the lobe, which blurs a little more than the lobe: 2.6% of the luminance at worst with 1024
    // samples and no level bias (6% with 128 samples and the default bias), against 17% when each level holds
    // the roughness of the level below it.
    queries.clear();
    std::vector<glm::vec3> expected;
    for (int level = 1; level < options.specularLevels; ++level) {
        const float roughness = float(level) / float(options.specularLevels - 1);
        for (std::size_t i = 0; i < dirs.size(); i += 2) {
            const glm::vec3 n = dirs[i];
            glm::dvec3 sum(0.0);
            double weight = 0.0;
            for (std::uint32_t s = 0; s < 4096; ++s) {
                const glm::vec3 h = importanceSampleGgx(hammersley(s, 4096), roughness, n);
                const glm::vec3 l = glm::reflect(-n, h);
                const float NdotL = glm::dot(n, l);
                if (NdotL > 0.0f) {
                    sum += glm::dvec3(analyticRadiance(l)) * double(NdotL);
                    weight += double(NdotL);
                }
            }
            expected.push_back(glm::vec3(sum / weight));
            GpuIblProbeQuery q;
            q.normalMode = glm::vec4(n, float(IblProbeMode::Specular));
            q.view.w = float(level);
            queries.push_back(q);
        }
    }
    out = iblProbe(ibl, queries);
    double worstPrefilter = 0.0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            worstPrefilter =
                std::max(worstPrefilter, double(std::abs(out[i][c] - expected[i][c]) / luma(expected[i])));
        }
    }
    std::printf("orbit ibl twins: prefiltered levels worst difference %.4f of the luminance\n",
                worstPrefilter);

    EXPECT_LT(worstPrefilter, 0.04);

    // pbrDirect against brdf() (n.l) E.
    queries.clear();
    expected.clear();
    for (std::size_t i = 0; i + 2 < dirs.size(); ++i) {
        const glm::vec3 n = dirs[i];
        const glm::vec3 v = glm::normalize(n + dirs[i + 1] * 0.6f);
        const glm::vec3 l = glm::normalize(n + dirs[i + 2] * 0.7f);
        const PbrMaterial m{.baseColor = glm::vec3(0.9f, 0.5f, 0.2f),
                            .metallic = float(i % 3) * 0.5f,
                            .roughness = 0.1f + 0.035f * float(i)};
        GpuIblProbeQuery q = shadeQuery(n, v, m);
        q.normalMode.w = float(IblProbeMode::Direct);
        q.light = glm::vec4(l, 3.0f);
        queries.push_back(q);
        expected.push_back(brdf(n, v, l, m) * std::max(glm::dot(n, l), 0.0f) * 3.0f);
    }
    out = iblProbe(ibl, queries);
    double worstDirect = 0.0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        worstDirect = std::max(worstDirect, double(glm::length(out[i] - expected[i]) /
                                                   std::max(glm::length(expected[i]), 1e-6f)));
    }
    std::printf("orbit ibl twins: pbrDirect worst relative difference %.6f\n", worstDirect);
    EXPECT_LT(worstDirect, 1e-4);
}

// Options out of range are rejected by name before any GL work.
TEST_F(OrbitIblTest, RejectsBadOptions) {
    const ImageF env(8, 4, 1.0f);
    EXPECT_THROW(Ibl(env, {.faceSize = 100}), std::invalid_argument);
    EXPECT_THROW(Ibl(env, {.faceSize = 32, .specularLevels = 7}), std::invalid_argument);
    EXPECT_THROW(Ibl(ImageF{}), std::invalid_argument);
}

} // namespace photopic::orbit
