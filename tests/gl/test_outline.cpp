// Outlines against edges found by the same rule on the ray tracer's depth and normals (pixel centres), on
// still testbed frames: precision and recall, and no outline on the inside of planes, tilted or not.

#include "GlTest.h"

#include "gl/TextureIo.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedScene.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;

Settings outlineSettings(bool enabled) {
    Settings s;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.outline.enabled = enabled;
    s.outline.color = glm::vec3(7.0f, 0.0f, 7.0f);
    return s;
}

/// The outline rule on CPU images (rows top to bottom; the rule is symmetric in y, so the flip is moot).
std::vector<bool> truthEdges(const ImageF& depth, const ImageF& normals, const OutlineSettings& s) {
    const auto w = [&](int x, int y) {
        x = std::clamp(x, 0, kW - 1);
        y = std::clamp(y, 0, kH - 1);
        const float z = depth.at(x, y)[0];
        return z > 0.0f && std::isfinite(z) ? 1.0 / double(z) : 0.0;
    };
    const auto n = [&](int x, int y) {
        x = std::clamp(x, 0, kW - 1);
        y = std::clamp(y, 0, kH - 1);
        const float* v = normals.at(x, y);
        const glm::dvec3 d(v[0], v[1], v[2]);
        return w(x, y) > 0.0 && glm::dot(d, d) > 0.25 ? glm::normalize(d) : glm::dvec3(0.0);
    };
    const auto turn = [&](int ax, int ay, int bx, int by) {
        const glm::dvec3 a = n(ax, ay), b = n(bx, by);
        return glm::dot(a, a) > 0.0 && glm::dot(b, b) > 0.0 ? 1.0 - glm::dot(a, b) : 0.0;
    };
    std::vector<bool> edges(std::size_t(kW * kH), false);
    const int k = s.width;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const double w0 = w(x, y);
            if (w0 <= 0.0) {
                continue;
            }
            const double jx = (2.0 * w0 - w(x - k, y) - w(x + k, y)) / w0;
            const double jy = (2.0 * w0 - w(x, y - k) - w(x, y + k)) / w0;
            bool edge = std::max(jx, jy) > s.depthThreshold;
            const double tx = jx > -s.depthThreshold ? turn(x - k, y, x + k, y) : 0.0;
            const double ty = jy > -s.depthThreshold ? turn(x, y - k, x, y + k) : 0.0;
            edge = edge || std::max(tx, ty) > s.normalThreshold;
            edges[std::size_t(y * kW + x)] = edge;
        }
    }
    return edges;
}

/// Pixels the pipeline outlined: the frame with outlines differs from the frame without.
std::vector<bool> outlined(TestbedScene& scene) {
    ImageF images[2];
    for (int i = 0; i < 2; ++i) {
        Pipeline pipeline({.settings = outlineSettings(i == 1)});
        std::vector<double> telemetry;
        const FrameTime time{.dt = kDt, .frameIndex = 0};
        const FrameInputs in = scene.render(time, pipeline, telemetry);
        pipeline.execute(in, time);
        images[i] = readTextureF(pipeline.sceneReferred());
    }
    std::vector<bool> edges(std::size_t(kW * kH), false);
    for (int i = 0; i < kW * kH; ++i) {
        for (int c = 0; c < 3; ++c) {
            edges[std::size_t(i)] = edges[std::size_t(i)] || images[0].rgba[std::size_t(i) * 4 + c] !=
                                                                 images[1].rgba[std::size_t(i) * 4 + c];
        }
    }
    return edges;
}

} // namespace

TEST_F(GlTest, OutlineMatchesEdgesOfTheTruthsDepthAndNormals) {
    for (float t : {0.3f, 1.5f}) {
        TestbedScene scene;
        for (const std::string& a :
             {std::string("cameraSpeed=0"), std::string("objectSpeed=0"), "cameraStart=" + std::to_string(t),
              "objectStart=" + std::to_string(t)}) {
            ASSERT_TRUE(scene.applyOverride(a).empty()) << a;
        }
        scene.resize({kW, kH});
        const testbed::TruthOptions o = scene.truthOptions({.dt = kDt, .frameIndex = 0});
        const std::vector<bool> truth =
            truthEdges(testbed::renderTruth(testbed::TruthKind::Depth, o),
                       testbed::renderTruth(testbed::TruthKind::Normals, o), OutlineSettings{});
        const std::vector<bool> ours = outlined(scene);
        const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, o);
        long both = 0, nTruth = 0, nOurs = 0, planeInside = 0, planePixels = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                const std::size_t i = std::size_t(y * kW + x);
                // Match within one pixel: rasterised and traced depths differ in the last bits at a jump.
                bool near = false;
                for (int d = 0; d < 9 && !near; ++d) {
                    const int qx = std::clamp(x + d % 3 - 1, 0, kW - 1),
                              qy = std::clamp(y + d / 3 - 1, 0, kH - 1);
                    near = truth[std::size_t(qy * kW + qx)];
                }
                nTruth += truth[i] ? 1 : 0;
                nOurs += ours[i] ? 1 : 0;
                both += ours[i] && near ? 1 : 0;
                // Inside the ground or the wall (planes; the ground is seen at grazing angles at 1.5 s): the
                // 5x5 neighbourhood is one of them.
                const float id = ids.at(x, y)[0];
                bool inside = id == float(testbed::ids::kGround) || id == float(testbed::ids::kWall);
                for (int d = 0; d < 25 && inside; ++d) {
                    const int qx = x + d % 5 - 2, qy = y + d / 5 - 2;
                    inside = qx >= 0 && qy >= 0 && qx < kW && qy < kH && ids.at(qx, qy)[0] == id;
                }
                planePixels += inside ? 1 : 0;
                planeInside += inside && ours[i] ? 1 : 0;
            }
        }
        long found = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                if (!truth[std::size_t(y * kW + x)]) {
                    continue;
                }
                bool near = false;
                for (int d = 0; d < 9 && !near; ++d) {
                    const int qx = std::clamp(x + d % 3 - 1, 0, kW - 1),
                              qy = std::clamp(y + d / 3 - 1, 0, kH - 1);
                    near = ours[std::size_t(qy * kW + qx)];
                }
                found += near ? 1 : 0;
            }
        }
        const double precision = nOurs ? double(both) / double(nOurs) : 0.0;
        const double recall = nTruth ? double(found) / double(nTruth) : 0.0;
        std::printf(
            "outline at %.1f s: %ld px (truth %ld), precision %.3f, recall %.3f; plane interiors %ld px, "
            "outlined %ld\n",
            t, nOurs, nTruth, precision, recall, planePixels, planeInside);
        EXPECT_GT(nTruth, 200);
        EXPECT_GE(precision, 0.95);
        EXPECT_GE(recall, 0.95);
        EXPECT_GT(planePixels, 1000);
        EXPECT_EQ(planeInside, 0);
    }
}

// NaN, infinite, zero and negative depths and NaN normals: finite colour.
TEST_F(GlTest, OutlineKeepsBrokenInputsOut) {
    const int w = 16, h = 16;
    ImageF color(w, h, 0.5f), depth(w, h, 5.0f), normals(w, h, 0.0f);
    for (int i = 0; i < w * h; ++i) {
        normals.rgba[std::size_t(i) * 4 + 2] = 1.0f;
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    depth.at(3, 3)[0] = nan;
    depth.at(5, 3)[0] = std::numeric_limits<float>::infinity();
    depth.at(7, 3)[0] = 0.0f;
    depth.at(9, 3)[0] = -2.0f;
    normals.at(4, 8)[0] = nan;
    const Texture c = makeTexture(color, "color"), d = makeTexture(depth, "depth"),
                  n = makeTexture(normals, "n");
    const Camera camera;
    Pipeline pipeline({.settings = outlineSettings(true)});
    pipeline.execute(
        {.color = &c, .depth = &d, .depthKind = DepthKind::LinearView, .normals = &n, .camera = &camera}, {});
    for (float v : readTextureF(pipeline.sceneReferred()).rgba) {
        ASSERT_TRUE(std::isfinite(v));
    }
}

} // namespace photopic::test
