// Volumetric light (screen-space radial scattering from the sun) on the testbed, 160x90: the rays point away
// from the sun, fade out as it leaves the screen, are cut by occluders, agree with the CPU reference of the
// same scattering on the ray tracer's colour and depth, hold still on a slow pan, and stay finite on broken
// inputs. The measured figures are printed and written down in docs/architecture.md ("Volumetric light").

#include "GlTest.h"

#include "core/VolumetricLight.h"
#include "gl/Objects.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedRenderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;
/// Frames before a still view is measured: the accumulation keeps 0.9^16 = 19% of its first frame, which
/// was itself a full march.
constexpr std::uint64_t kSettleFrames = 16;
/// A camera high above the scene: everything it sees around the sun is sky (the lowest view ray of a
/// 45-degree field centred on the sun, 25 degrees up, still points above the horizon).
constexpr glm::vec3 kSkyEye{0.0f, 40.0f, 0.0f};
/// A camera standing in the scene, the wall and the objects below the sun.
constexpr glm::vec3 kSceneEye{0.0f, 1.6f, 5.0f};

Settings volumetricSettings() {
    Settings s;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.volumetricLight.enabled = true;
    s.debug.view = DebugView::VolumetricLight;
    return s;
}

glm::vec3 sunDirection() {
    return testbed::environment().sunDirection;
}

/// The sun's direction turned by `yawDeg` about the vertical and raised by `pitchDeg`: a camera looking
/// that way sees the sun off centre.
glm::vec3 aroundTheSun(float yawDeg, float pitchDeg) {
    const glm::vec3 s = sunDirection();
    const float elevation = std::asin(s.y) + glm::radians(pitchDeg);
    const float azimuth = std::atan2(s.x, -s.z) + glm::radians(yawDeg);
    return {std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
            -std::cos(azimuth) * std::cos(elevation)};
}

/// The testbed's camera (field of view, planes, lens) at `eye` looking along `forward`, having looked along
/// `prevForward` one frame earlier.
Camera cameraLooking(glm::vec3 eye, glm::vec3 forward, glm::vec3 prevForward) {
    testbed::TruthOptions o;
    o.width = kW;
    o.height = kH;
    o.fixedView = testbed::FixedView{eye, eye + forward};
    Camera c = testbed::truthCamera(o);
    c.prevViewProjection = c.projection * glm::lookAt(eye, eye + prevForward, glm::vec3(0.0f, 1.0f, 0.0f));
    return c;
}

/// The testbed's objects at t = 0 (still).
std::vector<testbed::Primitive> stillPrimitives() {
    return testbed::primitivesAt(0.0, 0.0);
}

/// The testbed rasteriser as a host: draws a frame with the given camera and objects, runs the pipeline and
/// returns the volumetric-light view's raw values (the light added).
class Host {
public:
    Host() { mRenderer.resize({kW, kH}); }
    Host(const Host&) = delete;
    Host& operator=(const Host&) = delete;
    /// The renderer leaves its program current; deleted while current, its name would stay bound, and the
    /// next test's pipeline would restore it after the program is gone (a GL error in that test).
    ~Host() { glUseProgram(0); }

    ImageF render(Pipeline& pipeline, const Camera& camera, const std::vector<testbed::Primitive>& prims,
                  std::uint64_t frameIndex, ImageF* color = nullptr) {
        const FrameTime time{.dt = kDt, .frameIndex = frameIndex};
        const glm::vec2 jitter = pipeline.beginFrame(time, &camera);
        mRenderer.draw({.camera = &camera, .jitter = jitter, .primitives = &prims});
        const FrameInputs in{.color = &mRenderer.color(),
                             .depth = &mRenderer.depth(),
                             .motion = &mRenderer.motion(),
                             .camera = &camera,
                             .sunDirection = sunDirection()};
        pipeline.execute(in, time);
        if (color) {
            *color = readTextureF(mRenderer.color());
        }
        return readTextureF(pipeline.sceneReferred());
    }

    /// `frames` still frames of one view from a fresh history; returns the last.
    ImageF still(Pipeline& pipeline, const Camera& camera, const std::vector<testbed::Primitive>& prims,
                 std::uint64_t frames = kSettleFrames) {
        pipeline.reset();
        ImageF out;
        for (std::uint64_t i = 0; i < frames; ++i) {
            out = render(pipeline, camera, prims, i);
        }
        return out;
    }

private:
    testbed::TestbedRenderer mRenderer;
};

float luma(const float* c) {
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

double meanLuma(const ImageF& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            sum += luma(image.at(x, y));
        }
    }
    return sum / double(image.pixelCount());
}

/// Bilinear luma at a point in pixel units (x right, y down), clamped to the image.
float lumaAt(const ImageF& image, glm::vec2 p) {
    const glm::vec2 q = p - 0.5f;
    const int x0 = int(std::floor(q.x)), y0 = int(std::floor(q.y));
    const float fx = q.x - float(x0), fy = q.y - float(y0);
    const auto at = [&](int x, int y) {
        return luma(image.at(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1)));
    };
    return (1.0f - fy) * ((1.0f - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
           fy * ((1.0f - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

/// `frames` frames of host-given colour and linear depth, the camera looking straight at the sun.
void lookAtTheSun(Pipeline& pipeline, const Texture& color, const Texture& depth, std::uint64_t frames) {
    const glm::vec3 forward = sunDirection();
    const Camera camera = cameraLooking(kSkyEye, forward, forward);
    for (std::uint64_t i = 0; i < frames; ++i) {
        pipeline.execute({.color = &color,
                          .depth = &depth,
                          .depthKind = DepthKind::LinearView,
                          .camera = &camera,
                          .sunDirection = forward},
                         {.dt = kDt, .frameIndex = i});
    }
}

/// The sun's centre in pixel units (x right, y down).
glm::vec2 sunPixel(const Camera& camera) {
    const SunOnScreen sun = sunOnScreen(camera, sunDirection());
    return {sun.uv.x * float(kW), (1.0f - sun.uv.y) * float(kH)};
}

} // namespace

// Rays point away from the sun: over the pixels that receive light (above 2% of the largest), outside the
// sun's disc and 2 px from the border, the light falls along the direction away from the sun's screen
// position (central difference over +-1.5 px) at >= 95% of them. The view is all sky, so nothing cuts the
// rays and the field is the radial falloff alone.
TEST_F(GlTest, VolumetricLightRaysPointAwayFromTheSun) {
    Host host;
    Pipeline pipeline({.settings = volumetricSettings()});
    const Camera camera = cameraLooking(kSkyEye, aroundTheSun(6.0f, -4.0f), aroundTheSun(6.0f, -4.0f));
    const ImageF light = host.still(pipeline, camera, {});
    const glm::vec2 sun = sunPixel(camera);
    float peak = 0.0f;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            peak = std::max(peak, luma(light.at(x, y)));
        }
    }
    ASSERT_GT(peak, 0.0f);
    long counted = 0, outward = 0;
    for (int y = 2; y < kH - 2; ++y) {
        for (int x = 2; x < kW - 2; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            const glm::vec2 away = p - sun;
            if (glm::length(away) < 6.0f || luma(light.at(x, y)) < 0.02f * peak) {
                continue;
            }
            const glm::vec2 r = glm::normalize(away) * 1.5f;
            ++counted;
            outward += lumaAt(light, p + r) < lumaAt(light, p - r) ? 1 : 0;
        }
    }
    const double fraction = double(outward) / double(std::max(counted, 1L));
    std::printf("volumetric light: the light falls away from the sun at %.4f of %ld lit pixels (peak %.3f)\n",
                fraction, counted, double(peak));
    EXPECT_GT(counted, kW * kH / 4);
    EXPECT_GE(fraction, 0.95);
}

// The strength (mean light over the image) falls to 0 as the sun leaves the screen: it does not rise once the
// sun's centre is within kVolumetricSunFadeInside of the border, and it is exactly 0 beyond
// kVolumetricSunFadeOutside outside and with the sun behind the camera.
TEST_F(GlTest, VolumetricLightFadesOutAsTheSunLeavesTheScreen) {
    Host host;
    Pipeline pipeline({.settings = volumetricSettings()});
    // Yaws that move the sun from the image's centre out past its left edge (about 2 px per degree).
    const float yaws[] = {0.0f, 30.0f, 33.0f, 35.0f, 37.0f, 39.0f, 41.0f, 43.0f, 45.0f, 50.0f, 180.0f};
    double centre = 0.0, previous = std::numeric_limits<double>::infinity();
    int fading = 0;
    for (float yaw : yaws) {
        const glm::vec3 forward = aroundTheSun(yaw, 0.0f);
        const Camera camera = cameraLooking(kSkyEye, forward, forward);
        const SunOnScreen sun = sunOnScreen(camera, sunDirection());
        const double strength = meanLuma(host.still(pipeline, camera, {}, 6));
        if (yaw == 0.0f) {
            centre = strength;
        }
        std::printf(
            "volumetric light: sun at u %.3f (in front %d, fade %.3f): strength %.5f (%.3f of centred)\n",
            double(sun.uv.x), sun.inFront ? 1 : 0, double(sun.fade), strength, strength / centre);
        if (sun.uv.x < kVolumetricSunFadeInside) {
            EXPECT_LE(strength, previous + 1e-7) << yaw; // no rise as the sun leaves
            previous = strength;
        }
        if (sun.inFront && sun.uv.x < kVolumetricSunFadeInside && sun.uv.x > 0.0f) {
            EXPECT_GT(strength, 0.0) << yaw;
            ++fading;
        }
        if (!sun.inFront || sun.uv.x < -kVolumetricSunFadeOutside) {
            EXPECT_EQ(strength, 0.0) << yaw;
        }
    }
    EXPECT_GT(centre, 0.0);
    EXPECT_GE(fading, 2); // positions inside the image where the rays are fading
}

// Occluders cut the rays: a wall whose top edge runs through the sun's centre (a box placed in the sky view,
// facing the camera) leaves the rays below the sun, whose way to the sun crosses it, with a small share of
// the light at the same distances above it (a 60-degree wedge each side, 8 to 40 px from the sun).
TEST_F(GlTest, VolumetricLightOccludersCutTheRays) {
    Host host;
    Pipeline pipeline({.settings = volumetricSettings()});
    const glm::vec3 forward = sunDirection();
    const Camera camera = cameraLooking(kSkyEye, forward, forward);
    // The box, in the camera's frame: top edge through the sun's direction, 30 m away.
    const glm::mat4 cameraToWorld = glm::inverse(camera.view);
    const float distance = 30.0f, half = 20.0f;
    testbed::Primitive wall;
    wall.id = 50;
    wall.shape = testbed::Shape::Box;
    wall.size = glm::vec3(3.0f * half, half, 0.1f);
    wall.toWorld = cameraToWorld * glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -half, -distance));
    wall.toObject = glm::inverse(wall.toWorld);
    wall.prevToWorld = wall.toWorld;
    wall.material.albedo = glm::vec3(0.3f);
    wall.boundCentre = glm::vec3(wall.toWorld[3]);
    wall.boundRadius = glm::length(wall.size);
    const ImageF open = host.still(pipeline, camera, {});
    const ImageF cut = host.still(pipeline, camera, {wall});
    const glm::vec2 sun = sunPixel(camera);
    double above = 0.0, below = 0.0, openBelow = 0.0;
    long nAbove = 0, nBelow = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const glm::vec2 d = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - sun;
            const float r = glm::length(d);
            if (r < 8.0f || r > 40.0f || std::abs(d.x) > 0.5f * r) {
                continue; // outside the distances or the +-30 degree wedge about the vertical
            }
            if (d.y < 0.0f) {
                above += luma(cut.at(x, y));
                ++nAbove;
            } else {
                below += luma(cut.at(x, y));
                openBelow += luma(open.at(x, y));
                ++nBelow;
            }
        }
    }
    ASSERT_GT(nAbove, 100);
    ASSERT_GT(nBelow, 100);
    const double ratio = (below / double(nBelow)) / (above / double(nAbove));
    const double kept = below / openBelow;
    std::printf("volumetric light: below a wall through the sun's centre %.4f of the light above it "
                "(%.4f of the light there without the wall)\n",
                ratio, kept);
    EXPECT_LE(ratio, 0.15);
    EXPECT_LE(kept, 0.15);
}

// Against the CPU reference (core volumetricLightReference: the same scattering, 256 samples per pixel at
// full resolution, on the ray tracer's 4x4 supersampled colour and its depth) in the scene, the sun above
// the wall: the pass (half resolution, 64 dithered samples, accumulated over 16 still frames, on the
// rasterised colour) within 15% mean absolute error relative to the reference's mean, and its total light
// within 5%.
TEST_F(GlTest, VolumetricLightMatchesTheCpuReference) {
    Host host;
    Pipeline pipeline({.settings = volumetricSettings()});
    const glm::vec3 forward = aroundTheSun(8.0f, -6.0f);
    testbed::TruthOptions o;
    o.width = kW;
    o.height = kH;
    o.fixedView = testbed::FixedView{kSceneEye, kSceneEye + forward};
    o.samples = 4;
    const Camera camera = testbed::truthCamera(o);
    const ImageF gpu = host.still(pipeline, camera, stillPrimitives());
    const ImageF color = testbed::renderTruth(testbed::TruthKind::Color, o);
    const ImageF depth = testbed::renderTruth(testbed::TruthKind::Depth, o);
    const ImageF ref = volumetricLightReference(color, depth, sunOnScreen(camera, sunDirection()),
                                                volumetricSettings().volumetricLight, 256);
    double err = 0.0, sumRef = 0.0, sumGpu = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float g = luma(gpu.at(x, y)), r = luma(ref.at(x, y));
            err += std::abs(double(g) - double(r));
            sumRef += r;
            sumGpu += g;
        }
    }
    {
        ImageF raster;
        host.render(pipeline, camera, stillPrimitives(), 99, &raster);
        double a = 0, b = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                if (luma(raster.at(x, y)) > 100)
                    a += luma(raster.at(x, y));
                if (luma(color.at(x, y)) > 100)
                    b += luma(color.at(x, y));
            }
        std::printf("DEBUG sun energy raster %.1f truth %.1f\n", a, b);
        for (int frames : {1, 2, 4, 16}) {
            const ImageF g1 = host.still(pipeline, camera, stillPrimitives(), std::uint64_t(frames));
            double s1 = 0, s2 = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    s1 += luma(g1.at(x, y));
                    s2 += luma(ref.at(x, y));
                }
            std::printf("DEBUG frames %d total ratio %.4f\n", frames, s1 / s2);
        }
    }
    const double relative = err / std::max(sumRef, 1e-9);
    std::printf("volumetric light against the CPU reference: mean abs error %.4f of the mean, total %.4f of "
                "the reference's (reference mean %.4f)\n",
                relative, sumGpu / sumRef, sumRef / double(kW * kH));
    EXPECT_GT(sumRef, 0.0);
    EXPECT_LE(relative, 0.15);
    EXPECT_NEAR(sumGpu / sumRef, 1.0, 0.05);
}

/// Frame-to-frame change of the light on a pan: the mean absolute difference between each frame and the
/// previous one, relative to the mean light. `compensated`: the previous frame is first moved by the sun's
/// own motion on screen (the pan's, nearly uniform over a 45-degree field), so only the change that is not
/// the image moving with the camera counts: the pumping.
struct PanChange {
    double raw = 0.0;
    double compensated = 0.0;
};

PanChange panChange(bool accumulate, float degreesPerFrame) {
    Host host;
    Pipeline pipeline({.settings = volumetricSettings()});
    ImageF last;
    glm::vec2 lastSun{0.0f};
    double raw = 0.0, moved = 0.0, mean = 0.0, movedMean = 0.0;
    for (std::uint64_t i = 0; i < 28; ++i) {
        const float yaw = 8.0f + degreesPerFrame * float(i);
        const Camera camera = cameraLooking(kSceneEye, aroundTheSun(yaw, -6.0f),
                                            aroundTheSun(yaw - (i > 0 ? degreesPerFrame : 0.0f), -6.0f));
        if (!accumulate) {
            pipeline.reset();
        }
        const ImageF light = host.render(pipeline, camera, stillPrimitives(), i);
        const glm::vec2 sun = sunPixel(camera);
        if (i >= 16) {
            for (int y = 2; y < kH - 2; ++y) {
                for (int x = 2; x < kW - 2; ++x) {
                    const float l = luma(light.at(x, y));
                    raw += std::abs(double(l) - double(luma(last.at(x, y))));
                    mean += l;
                    const glm::vec2 from = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - (sun - lastSun);
                    moved += std::abs(double(l) - double(lumaAt(last, from)));
                    movedMean += l;
                }
            }
        }
        last = light;
        lastSun = sun;
    }
    return {.raw = mean > 0.0 ? raw / mean : 1.0, .compensated = movedMean > 0.0 ? moved / movedMean : 1.0};
}

// Stable on a slow pan (0.1 degree per frame, about 0.2 px, the scene view with the wall below the sun):
// the light changes between consecutive frames (frames 16 to 28) by <= 2% of its mean once the image's own
// motion is taken out, and by <= 2.5% without (a march alone, reset every frame, changes by several times
// that).
TEST_F(GlTest, VolumetricLightHoldsStillOnASlowPan) {
    const PanChange accumulated = panChange(true, 0.1f);
    const PanChange alone = panChange(false, 0.1f);
    std::printf("volumetric light on a slow pan: frame-to-frame change %.4f of the mean, %.4f with the pan's "
                "motion taken out (march alone: %.4f, %.4f)\n",
                accumulated.raw, accumulated.compensated, alone.raw, alone.compensated);
    EXPECT_LE(accumulated.compensated, 0.02);
    EXPECT_LE(accumulated.raw, 0.025);
    EXPECT_LT(accumulated.compensated, 0.5 * alone.compensated);
}

// A uniform sky of radiance c with the sun at the image's centre: every sample reaches the sun within the
// image, so the light is c x intensity x weight x exposure x the mean of decay^(64 t) over t in [0, 1],
// (1 - decay^64) / (-64 ln decay), at every pixel (the dithered offsets average to the integral). Within 2%
// at every pixel after 12 frames.
TEST_F(GlTest, VolumetricLightOfAUniformSkyIsTheAnalyticMean) {
    const int w = 64, h = 36;
    ImageF color(w, h, 2.0f), depth(w, h, std::numeric_limits<float>::infinity());
    const Texture c = makeTexture(color, "color"), d = makeTexture(depth, "depth");
    const Settings s = volumetricSettings();
    Pipeline pipeline({.settings = s});
    lookAtTheSun(pipeline, c, d, 12);
    const VolumetricLightSettings& v = s.volumetricLight;
    const double mean = (1.0 - std::pow(double(v.decay), 64.0)) / (-64.0 * std::log(double(v.decay)));
    const double expected = 2.0 * double(v.intensity * v.weight * v.exposure) * mean;
    const ImageF light = readTextureF(pipeline.sceneReferred());
    double worst = 0.0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            worst = std::max(worst, std::abs(double(light.at(x, y)[0]) / expected - 1.0));
        }
    }
    std::printf("volumetric light of a uniform sky: largest relative error %.4f (expected %.5f)\n", worst,
                expected);
    EXPECT_LE(worst, 0.02);
}

// intensity 0: the light is computed but not added, and the image is bit for bit the image without the pass;
// at the default intensity the image changes (the light is added to the frame, not only to the view).
TEST_F(GlTest, VolumetricLightAtIntensityZeroLeavesTheImageUnchanged) {
    const glm::vec3 forward = aroundTheSun(8.0f, -6.0f);
    const Camera camera = cameraLooking(kSceneEye, forward, forward);
    ImageF images[3];
    for (int i = 0; i < 3; ++i) {
        Settings s = volumetricSettings();
        s.debug.view = DebugView::None;
        s.volumetricLight.enabled = i > 0;
        s.volumetricLight.intensity = i == 1 ? 0.0f : 1.0f;
        Host host;
        Pipeline pipeline({.settings = s});
        images[i] = host.still(pipeline, camera, stillPrimitives(), 3);
    }
    EXPECT_EQ(images[0].rgba, images[1].rgba);
    EXPECT_NE(images[0].rgba, images[2].rgba);
}

// NaN, infinite and negative colour, and NaN, infinite, zero and negative depths: the image and the light
// stay finite (the sun on screen, so every dispatch does its work).
TEST_F(GlTest, VolumetricLightKeepsBrokenInputsOut) {
    const int w = 32, h = 18;
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    ImageF color(w, h, 1.0f), depth(w, h, inf);
    for (int x = 0; x < w; ++x) {
        depth.at(x, h - 1)[0] = 5.0f;
    }
    color.at(3, 3)[0] = nan;
    color.at(5, 3)[1] = inf;
    color.at(7, 3)[2] = -inf;
    color.at(9, 3)[0] = 60000.0f;
    depth.at(3, 6)[0] = nan;
    depth.at(5, 6)[0] = -inf;
    depth.at(7, 6)[0] = 0.0f;
    depth.at(9, 6)[0] = -2.0f;
    const Texture c = makeTexture(color, "color"), d = makeTexture(depth, "depth");
    for (DebugView view : {DebugView::VolumetricLight, DebugView::None}) {
        Settings s = volumetricSettings();
        s.debug.view = view;
        Pipeline pipeline({.settings = s});
        lookAtTheSun(pipeline, c, d, 3);
        for (float v : readTextureF(pipeline.sceneReferred()).rgba) {
            ASSERT_TRUE(std::isfinite(v));
        }
    }
}

} // namespace photopic::test
