// Motion blur against analytic blur lengths and the testbed's shutter-integrated ray-traced truth.

#include "GlTest.h"

#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace photopic::test {

namespace {

constexpr float kDt = 1.0f / 30.0f;

Settings blurSettings(bool enabled) {
    Settings s;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.motionBlur.enabled = enabled;
    return s;
}

/// One frame of colour, linear depth and motion (UV, in `motionFormat`) through `settings`, with a default
/// camera; the exposed scene-referred image.
ImageF blurFrame(const Settings& settings, const ImageF& color, const ImageF& depth, const ImageF& motion,
                 GLenum motionFormat = GL_RGBA32F) {
    // Half float, as a renderer's colour target: the comparisons with the blur off are to the bit, and a
    // frame without a 3D pass reads a 32-bit colour at its own precision, not rounded to half as a 3D pass
    // sees it.
    const Texture c = makeTexture(color, "color", GL_RGBA16F);
    const Texture d = makeTexture(depth, "depth");
    const Texture m = makeTexture(motion, "motion", motionFormat);
    const Camera camera;
    Pipeline pipeline({.settings = settings});
    pipeline.beginFrame({.dt = kDt, .frameIndex = 1});
    pipeline.execute(
        {.color = &c, .depth = &d, .depthKind = DepthKind::LinearView, .motion = &m, .camera = &camera},
        {.dt = kDt, .frameIndex = 1});
    EXPECT_TRUE(pipeline.status().skipped.empty());
    return readTextureF(pipeline.sceneReferred());
}

/// A uniform pan by `pixelsPerFrame` in x over a black image with one bright column (1 at x = w / 2):
/// the blurred rows are the column's streak. Returns the exposed scene-referred image.
ImageF blurColumn(const Settings& settings, float pixelsPerFrame, int w = 160, int h = 32,
                  int movingColumns = 160, bool gradient = false) {
    ImageF color(w, h, 0.0f);
    for (int y = 0; y < h; ++y) {
        for (int c = 0; c < 3; ++c) {
            color.at(w / 2, y)[c] = 1.0f;
            for (int x = 0; gradient && x < w; ++x) {
                color.at(x, y)[c] = 0.01f * float(x) + 0.02f * float(y) + 0.1f * float(c);
            }
        }
    }
    ImageF depth(w, h, 10.0f);
    ImageF motion(w, h, 0.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            motion.at(x, y)[0] = x < movingColumns ? pixelsPerFrame / float(w) : 0.0f;
        }
    }
    return blurFrame(settings, color, depth, motion);
}

/// The streak's length from its spread: a box of length L, integrated over pixels, has variance
/// (L^2 + 1) / 12. Averaged over the rows (each has its own jitter).
double streakLength(const ImageF& img) {
    double variance = 0.0;
    for (int y = 0; y < img.height; ++y) {
        double sum = 0.0, mean = 0.0, second = 0.0;
        for (int x = 0; x < img.width; ++x) {
            const double v = img.at(x, y)[1];
            sum += v;
            mean += v * (x + 0.5);
            second += v * (x + 0.5) * (x + 0.5);
        }
        mean /= sum;
        variance += second / sum - mean * mean;
    }
    variance /= img.height;
    return std::sqrt(std::max(0.0, 12.0 * variance - 1.0));
}

double relativeRmse(const ImageF& a, const ImageF& truth, const std::vector<bool>& mask, long* count) {
    double err = 0.0, ref = 0.0;
    *count = 0;
    for (int i = 0; i < truth.width * truth.height; ++i) {
        if (!mask[std::size_t(i)]) {
            continue;
        }
        ++*count;
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.rgba[std::size_t(i) * 4 + c]) - truth.rgba[std::size_t(i) * 4 + c];
            err += d * d;
            ref += double(truth.rgba[std::size_t(i) * 4 + c]) * truth.rgba[std::size_t(i) * 4 + c];
        }
    }
    return ref > 0.0 ? std::sqrt(err / ref) : 0.0;
}

std::unique_ptr<TestbedScene> sceneWith(std::initializer_list<std::string> overrides, int w, int h) {
    auto scene = std::make_unique<TestbedScene>();
    for (const std::string& a : overrides) {
        EXPECT_TRUE(scene->applyOverride(a).empty()) << a;
    }
    scene->resize({w, h});
    return scene;
}

/// Frames 0..last of the testbed through `settings`; the last frame's exposed scene-referred image.
ImageF runScene(TestbedScene& scene, const Settings& settings, std::uint64_t last) {
    Pipeline pipeline({.settings = settings});
    for (std::uint64_t f = 0; f <= last; ++f) {
        std::vector<double> telemetry;
        const FrameTime time{.dt = kDt, .frameIndex = f};
        const FrameInputs in = scene.render(time, pipeline, telemetry);
        pipeline.execute(in, time);
    }
    return readTextureF(pipeline.sceneReferred());
}

/// A truth image shown through `settings` (no blur: it is the truth), exposed scene-referred.
ImageF throughPipeline(const ImageF& image, Settings settings) {
    settings.motionBlur.enabled = false;
    Pipeline pipeline({.settings = settings});
    const Texture t = makeTexture(image, "truth");
    pipeline.execute({.color = &t}, {});
    return readTextureF(pipeline.sceneReferred());
}

} // namespace

// A uniform pan of 16 px per frame: the shutter at 180 degrees draws an 8 px streak, at 360 a 16 px one
// (twice as long), each within 10% of motion x shutter (measured 8.04 and 15.85 px); the light is
// conserved; zero motion leaves the image exactly as it was.
TEST_F(GlTest, MotionBlurLengthFollowsTheShutter) {
    Settings half = blurSettings(true);
    Settings full = blurSettings(true);
    full.motionBlur.shutterAngle = 360.0f;
    const ImageF a = blurColumn(half, 16.0f);
    const ImageF b = blurColumn(full, 16.0f);
    const double la = streakLength(a), lb = streakLength(b);
    std::printf("streak length: 180 deg %.2f px (analytic 8), 360 deg %.2f px (analytic 16), ratio %.3f\n",
                la, lb, lb / la);
    EXPECT_NEAR(la, 8.0, 0.8);
    EXPECT_NEAR(lb, 16.0, 1.6);
    EXPECT_NEAR(lb / la, 2.0, 0.15);
    double energy = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            energy += a.at(x, y)[1] / a.height;
        }
    }
    std::printf("light per row: %.3f (1 before the blur)\n", energy);
    EXPECT_NEAR(energy, 1.0, 0.05);

    const ImageF still = blurColumn(half, 0.0f);
    const ImageF off = blurColumn(blurSettings(false), 0.0f);
    EXPECT_EQ(still.rgba, off.rgba);
    Settings camera = blurSettings(true);
    camera.motionBlur.intensity = 0.0f;
    EXPECT_EQ(blurColumn(camera, 16.0f).rgba, blurColumn(blurSettings(false), 16.0f).rgba);

    // Still pixels: motion (4 px of radius) only left of x = 40. Pixels from x = 46 on, which no streak
    // reaches, are unchanged to the bit, those in the tiles next to the motion included.
    const ImageF part = blurColumn(half, 16.0f, 160, 32, 40, true);
    const ImageF sharp = blurColumn(blurSettings(false), 16.0f, 160, 32, 40, true);
    long changed = 0, blurredLeft = 0;
    for (int y = 0; y < part.height; ++y) {
        for (int x = 0; x < part.width; ++x) {
            for (int ch = 0; ch < 4; ++ch) {
                const bool same = part.at(x, y)[ch] == sharp.at(x, y)[ch];
                changed += x >= 46 && !same ? 1 : 0;
                blurredLeft += x < 40 && !same ? 1 : 0;
            }
        }
    }
    EXPECT_EQ(changed, 0);
    EXPECT_GT(blurredLeft, 1000); // the moving part did change (the gradient's ends are not linear)
}

// The velocity tiles' maximum comes from a work group per tile through shared memory on a GPU and from an
// invocation per tile on a software renderer (sharedMemoryTiles()): both pick the same velocity, the first in
// row order among equally long ones, so the blurred frames are the same bits. A field of equally long
// velocities in eight directions (ties in every tile), on sizes whose tiles overhang the image, at two tile
// sizes; and the moving testbed.
TEST_F(GlTest, MotionBlurTileMaximumIsTheSameFromASharedReduction) {
    const int w = 61, h = 37;
    ImageF color(w, h, 0.0f);
    ImageF motion(w, h, 0.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < 3; ++c) {
                color.at(x, y)[c] = float((x * 5 + y * 3 + c * 7) % 13) * 0.2f;
            }
            // Eight directions of one length (6 px a frame), and a longer one in a few pixels.
            const float angle = float((x * 3 + y * 5) % 8) * 0.78539816f;
            const float length = (x * y) % 29 == 7 ? 9.0f : 6.0f;
            motion.at(x, y)[0] = length * std::cos(angle) / float(w);
            motion.at(x, y)[1] = length * std::sin(angle) / float(h);
        }
    }
    auto blurred = [&](bool shared, int tileSize) {
        forceSharedMemoryTiles(shared);
        Settings settings = blurSettings(true);
        settings.motionBlur.tileSize = tileSize;
        settings.motionBlur.maxBlur = std::min(settings.motionBlur.maxBlur, float(tileSize));
        return blurFrame(settings, color, ImageF(w, h, 10.0f), motion, GL_RG16F).rgba;
    };
    for (const int tileSize : {8, 20}) {
        const std::vector<float> single = blurred(false, tileSize);
        EXPECT_EQ(blurred(true, tileSize), single) << "tiles of " << tileSize << " px";
        EXPECT_NE(single, blurFrame(blurSettings(false), color, ImageF(w, h, 10.0f), motion).rgba)
            << "the frame is blurred";
    }
    auto testbed = [&](bool shared) {
        forceSharedMemoryTiles(shared);
        auto scene = sceneWith({"cameraSpeed=1", "objectStart=4"}, 83, 45);
        return runScene(*scene, blurSettings(true), 3).rgba;
    };
    EXPECT_EQ(testbed(true), testbed(false)) << "the moving testbed";
}

// The velocity-tiles view holds each pixel's neighbourhood maximum blur radius: a 16 px/frame pan at 180
// degrees is 4 px of radius.
TEST_F(GlTest, MotionBlurVelocityTilesViewHoldsTheRadius) {
    Settings s = blurSettings(true);
    s.debug.view = DebugView::VelocityTiles;
    const ImageF v = blurColumn(s, 16.0f);
    EXPECT_NEAR(v.at(10, 10)[0], 4.0f, 0.01f);
    EXPECT_NEAR(v.at(100, 20)[1], 0.0f, 0.01f);
    EXPECT_NEAR(v.at(100, 20)[2], 4.0f, 0.01f);
}

namespace {

/// RMSE over the masked pixels (RGB) divided by the truth's mean there.
double rmseOverMean(const ImageF& a, const ImageF& truth, const std::vector<bool>& mask) {
    double err = 0.0, sum = 0.0;
    long n = 0;
    for (int i = 0; i < truth.width * truth.height; ++i) {
        if (!mask[std::size_t(i)]) {
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            const double t = truth.rgba[std::size_t(i) * 4 + c];
            const double d = double(a.rgba[std::size_t(i) * 4 + c]) - t;
            err += d * d;
            sum += t;
            ++n;
        }
    }
    return sum > 0.0 ? std::sqrt(err / double(n)) / (sum / double(n)) : 0.0;
}

/// Channels that differ between `a` and `b` over the pixels farther than the longest blur radius (180
/// degrees: a quarter of the longest motion, plus a pixel) from any motion in `motion` (UV); `count` gets
/// how many such pixels there are.
long changedWhereNoMotionReaches(const ImageF& motion, const ImageF& a, const ImageF& b, long* count) {
    const int w = motion.width, h = motion.height;
    float longest = 0.0f;
    for (int i = 0; i < w * h; ++i) {
        longest = std::max(longest, std::hypot(motion.rgba[std::size_t(i) * 4] * float(w),
                                               motion.rgba[std::size_t(i) * 4 + 1] * float(h)));
    }
    const int reach = int(std::ceil(0.25f * longest)) + 1;
    long changed = 0;
    *count = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool near = false;
            for (int dy = -reach; dy <= reach && !near; ++dy) {
                for (int dx = -reach; dx <= reach && !near; ++dx) {
                    const float* m = motion.at(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1));
                    near = m[0] != 0.0f || m[1] != 0.0f;
                }
            }
            if (!near) {
                ++*count;
                for (int ch = 0; ch < 4; ++ch) {
                    changed += a.at(x, y)[ch] != b.at(x, y)[ch] ? 1 : 0;
                }
            }
        }
    }
    return changed;
}

/// What a one-layer, one-sample-per-pixel input allows at best: every pixel of the frame-time image (the
/// truth's colour at its centre, as the rasteriser takes it) is a unit square that carries its colour and
/// moves exactly with the surface point it shows (rotation included); at each of the shutter truth's instants
/// the squares are drawn nearest first onto the pixel centres, and a centre no square lands on (background
/// that the motion uncovers, which no one-layer input holds) takes the truth's own colour there. Its error
/// against the truth is that of the input's sampling: edges and texture known to a pixel, sub-pixel motion,
/// surfaces hidden at the frame's time that move into view over a visible one.
ImageF singleLayerReference(const testbed::TruthOptions& o, const ImageF& still) {
    using namespace testbed;
    const int w = o.width, h = o.height;
    const auto ndc = [&](int x, int y) {
        return glm::vec2(2.0f * (float(x) + 0.5f) / float(w) - 1.0f,
                         1.0f - 2.0f * (float(y) + 0.5f) / float(h));
    };
    struct Source {
        int primitive = -1;    ///< -1: the sky
        glm::vec3 point{0.0f}; ///< object space, or the sky's direction
    };
    const TruthInstant now = truthInstant(o, 0.0);
    std::vector<Source> sources(std::size_t(w * h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Ray ray = cameraRay(now.camera, ndc(x, y));
            Hit hit;
            Source& s = sources[std::size_t(y * w + x)];
            if (intersectScene(now.primitives, ray, 0.0f, 2.0f * kFar, hit)) {
                s = {hit.primitive, hit.objectPoint};
            } else {
                s = {-1, ray.direction};
            }
        }
    }
    ImageF sum(w, h, 0.0f);
    const int count = o.shutterTimes;
    std::vector<float> nearest(std::size_t(w * h));
    std::vector<int> drawn(std::size_t(w * h));
    for (int i = 0; i < count; ++i) {
        const TruthInstant at = truthInstant(o, ((double(i) + 0.5) / count - 0.5) * shutterSeconds(o));
        const glm::mat4 viewProjection = at.camera.viewProjection();
        std::fill(nearest.begin(), nearest.end(), std::numeric_limits<float>::infinity());
        std::fill(drawn.begin(), drawn.end(), -1);
        for (int k = 0; k < w * h; ++k) {
            const Source& s = sources[std::size_t(k)];
            const glm::vec4 clip = s.primitive >= 0
                                       ? viewProjection * (at.primitives[std::size_t(s.primitive)].toWorld *
                                                           glm::vec4(s.point, 1.0f))
                                       : viewProjection * glm::vec4(s.point, 0.0f);
            if (!(clip.w > 0.0f)) {
                continue;
            }
            // The unit square centred on the point covers the centre of the pixel the point lies in.
            const int x = int(std::floor((clip.x / clip.w + 1.0f) * 0.5f * float(w)));
            const int y = int(std::floor((1.0f - clip.y / clip.w) * 0.5f * float(h)));
            const float z = s.primitive >= 0 ? clip.w : std::numeric_limits<float>::max();
            if (x >= 0 && y >= 0 && x < w && y < h && z < nearest[std::size_t(y * w + x)]) {
                nearest[std::size_t(y * w + x)] = z;
                drawn[std::size_t(y * w + x)] = k;
            }
        }
        for (int k = 0; k < w * h; ++k) {
            glm::vec3 c;
            if (const int from = drawn[std::size_t(k)]; from >= 0) {
                c = glm::vec3(still.rgba[std::size_t(from) * 4], still.rgba[std::size_t(from) * 4 + 1],
                              still.rgba[std::size_t(from) * 4 + 2]);
            } else {
                c = radiance(at.primitives, cameraRay(at.camera, ndc(k % w, k / w)));
            }
            for (int ch = 0; ch < 3; ++ch) {
                sum.rgba[std::size_t(k) * 4 + std::size_t(ch)] += c[ch] / float(count);
            }
            sum.rgba[std::size_t(k) * 4 + 3] = 1.0f;
        }
    }
    return sum;
}

} // namespace

// Against the ray tracer's shutter truth (160x90), RMSE over the truth's mean on the pixels the motion
// changes (shutter against the still frame). The truth takes what the rasteriser takes, one point per pixel
// at its centre, at 64 instants over the shutter centred on the frame's time (as the pass's streaks are
// centred on each pixel). Cases: the camera path's framing with the mover and the spinner at 12x speed, a
// pan, and a close still camera on the mover crossing the wall in the clear.
// On the path's framing the mover is 6 px across, 5.5 against a 0.3 background, and mostly hidden behind
// the small sphere; the spinner's blur is under a pixel: there the one-layer reference above (exact motion,
// uncovered background given) is itself 30.5% and 14.9% off, so the target applies to what the input
// allows: the error beyond the reference's, in quadrature, sqrt(E^2 - E_ref^2) <= 15%. Where the mover is
// seen whole, the pass's own error is held to 15%. docs/architecture.md breaks the error down.
TEST_F(GlTest, MotionBlurMatchesTheShutterTruth) {
    constexpr int kW = 160, kH = 90;
    struct Case {
        const char* name;
        std::initializer_list<std::string> overrides;
        bool boundBeyondReference; ///< the 15% holds for the error beyond the one-layer reference's
    };
    const Case cases[] = {
        {"moving objects", {"cameraSpeed=0", "cameraStart=0", "objectStart=4.5", "objectSpeed=12"}, true},
        {"pan", {"cameraStart=0.1", "cameraSpeed=3", "objectSpeed=0", "objectStart=1"}, true},
        {"mover in the clear",
         {"cameraSpeed=0", "objectStart=5.2", "objectSpeed=12", "fixedCamera=true", "eye=[0,0.9,-1.4]",
          "target=[0,0.35,-4.4]"},
         false},
    };
    constexpr double kTarget = 0.15;
    for (const Case& c : cases) {
        auto scene = sceneWith(c.overrides, kW, kH);
        const std::uint64_t last = 2;
        testbed::TruthOptions o = scene->truthOptions({.dt = kDt, .frameIndex = last});
        o.samples = 1;
        o.shutterTimes = 64;
        const Settings on = blurSettings(true);
        const ImageF stillRaw = testbed::renderTruth(testbed::TruthKind::Color, o);
        const ImageF shutter = throughPipeline(testbed::renderTruth(testbed::TruthKind::Shutter, o), on);
        const ImageF still = throughPipeline(stillRaw, on);
        const ImageF reference = throughPipeline(singleLayerReference(o, stillRaw), on);
        const ImageF motion = testbed::renderTruth(testbed::TruthKind::Motion, o);
        const ImageF blurred = runScene(*scene, on, last);
        const ImageF sharp = runScene(*scene, blurSettings(false), last);
        std::vector<bool> moving(std::size_t(kW * kH), false);
        long n = 0;
        for (int i = 0; i < kW * kH; ++i) {
            for (int ch = 0; ch < 3; ++ch) {
                const float t = shutter.rgba[std::size_t(i) * 4 + ch];
                moving[std::size_t(i)] =
                    moving[std::size_t(i)] ||
                    std::abs(t - still.rgba[std::size_t(i) * 4 + ch]) > 0.02f * (t + 0.05f);
            }
            n += moving[std::size_t(i)] ? 1 : 0;
        }
        const double error = rmseOverMean(blurred, shutter, moving);
        const double referenceError = rmseOverMean(reference, shutter, moving);
        const double unblurred = rmseOverMean(sharp, shutter, moving);
        const double beyond = std::sqrt(std::max(0.0, error * error - referenceError * referenceError));
        long m = 0;
        std::printf(
            "%s: %ld moving pixels, RMSE / mean %.1f%% (one-layer reference %.1f%%, beyond it %.1f%%; "
            "unblurred %.1f%%); RMSE / RMS %.1f%%\n",
            c.name, n, 100.0 * error, 100.0 * referenceError, 100.0 * beyond, 100.0 * unblurred,
            100.0 * relativeRmse(blurred, shutter, moving, &m));
        EXPECT_GT(n, 100);
        EXPECT_LE(c.boundBeyondReference ? beyond : error, kTarget) << c.name;
        EXPECT_LT(error, 0.5 * unblurred) << c.name;

        long unreached = 0;
        const long changed = changedWhereNoMotionReaches(motion, blurred, sharp, &unreached);
        std::printf("  %ld pixels no motion reaches, %ld channels of them changed\n", unreached, changed);
        EXPECT_EQ(changed, 0) << c.name;

        // The placement relative to TAA, measured on the same pixels (TAA's own error on fast motion, with
        // two frames of history, is part of both figures): printed for docs/architecture.md, against this
        // truth and against one anti-aliased over the pixel (8x8 samples, each its own instant), which is
        // what TAA's jittered frames converge to.
        testbed::TruthOptions area = scene->truthOptions({.dt = kDt, .frameIndex = last});
        area.samples = 8;
        const ImageF areaShutter =
            throughPipeline(testbed::renderTruth(testbed::TruthKind::Shutter, area), on);
        {
            Settings taa = blurSettings(false);
            taa.aa.mode = AntiAliasing::Taa;
            const ImageF resolved = runScene(*scene, taa, last);
            std::printf("  with TAA, no blur: %.1f%% (against the area truth %.1f%%)\n",
                        100.0 * rmseOverMean(resolved, shutter, moving),
                        100.0 * rmseOverMean(resolved, areaShutter, moving));
        }
        for (MotionBlurPlacement placement :
             {MotionBlurPlacement::BeforeTaa, MotionBlurPlacement::AfterTaa}) {
            Settings taa = on;
            taa.aa.mode = AntiAliasing::Taa;
            taa.motionBlur.placement = placement;
            const ImageF resolved = runScene(*scene, taa, last);
            const double e = rmseOverMean(resolved, shutter, moving);
            std::printf("  with TAA, blur %s: %.1f%% (against the area truth %.1f%%)\n",
                        placement == MotionBlurPlacement::BeforeTaa ? "before-taa" : "after-taa", 100.0 * e,
                        100.0 * rmseOverMean(resolved, areaShutter, moving));
            EXPECT_TRUE(std::isfinite(e));
        }
    }
}

namespace {

/// The pass on given inputs (linear depth, UV motion) at frame `frame` (the jitter's seed), exposed
/// scene-referred.
ImageF blurInputs(const ImageF& color, const ImageF& depth, const ImageF& motion, const Camera& camera,
                  const Settings& settings, std::uint64_t frame) {
    const Texture c = makeTexture(color, "color"), d = makeTexture(depth, "depth"),
                  m = makeTexture(motion, "motion");
    Pipeline pipeline({.settings = settings});
    pipeline.beginFrame({.dt = kDt, .frameIndex = frame});
    pipeline.execute(
        {.color = &c, .depth = &d, .depthKind = DepthKind::LinearView, .motion = &m, .camera = &camera},
        {.dt = kDt, .frameIndex = frame});
    return readTextureF(pipeline.sceneReferred());
}

/// Per pixel, what its centre sees over the shutter: the surfaces (object ids, 0 the sky) before and after
/// the frame's time other than the one it shows at that time, and how many instants see a surface point
/// that is hidden or off screen at the frame's time (which no one-layer input holds).
struct ShutterView {
    std::uint32_t idNow = 0;
    std::uint32_t other = 0; ///< an id seen over the shutter other than idNow (the last one found)
    int earlyOther = 0;      ///< instants before the frame's time that see another id
    int lateOther = 0;
    int hidden = 0;
};

std::vector<ShutterView> shutterViews(const testbed::TruthOptions& o) {
    using namespace testbed;
    const int w = o.width, h = o.height, count = o.shutterTimes;
    const auto ndc = [&](float x, float y) {
        return glm::vec2(2.0f * x / float(w) - 1.0f, 1.0f - 2.0f * y / float(h));
    };
    const TruthInstant now = truthInstant(o, 0.0);
    const glm::mat4 nowViewProjection = now.camera.viewProjection();
    const glm::vec3 eye(glm::inverse(now.camera.view)[3]);
    std::vector<ShutterView> views(std::size_t(w * h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            Hit hit;
            const Ray ray = cameraRay(now.camera, ndc(float(x) + 0.5f, float(y) + 0.5f));
            views[std::size_t(y * w + x)].idNow = intersectScene(now.primitives, ray, 0.0f, 2.0f * kFar, hit)
                                                      ? now.primitives[std::size_t(hit.primitive)].id
                                                      : 0u;
        }
    }
    for (int i = 0; i < count; ++i) {
        const double offset = ((double(i) + 0.5) / count - 0.5) * shutterSeconds(o);
        const TruthInstant at = truthInstant(o, offset);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                ShutterView& v = views[std::size_t(y * w + x)];
                const Ray ray = cameraRay(at.camera, ndc(float(x) + 0.5f, float(y) + 0.5f));
                Hit hit;
                const bool found = intersectScene(at.primitives, ray, 0.0f, 2.0f * kFar, hit);
                const std::uint32_t id = found ? at.primitives[std::size_t(hit.primitive)].id : 0u;
                if (id != v.idNow) {
                    v.other = id;
                    (offset < 0.0 ? v.earlyOther : v.lateOther) += 1;
                }
                // Where that point is at the frame's time, and whether it is seen there.
                glm::vec4 clip;
                glm::vec3 world(0.0f);
                if (found) {
                    world = glm::vec3(now.primitives[std::size_t(hit.primitive)].toWorld *
                                      glm::vec4(hit.objectPoint, 1.0f));
                    clip = nowViewProjection * glm::vec4(world, 1.0f);
                } else {
                    clip = nowViewProjection * glm::vec4(ray.direction, 0.0f);
                }
                bool seen = false;
                if (clip.w > 0.0f && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w) {
                    const Ray back = cameraRay(now.camera, glm::vec2(clip) / clip.w);
                    Hit first;
                    const bool any = intersectScene(now.primitives, back, 0.0f, 2.0f * kFar, first);
                    seen = found ? any && first.primitive == hit.primitive &&
                                       std::abs(first.t - glm::length(world - eye)) < 1e-3f * first.t + 1e-4f
                                 : !any;
                }
                v.hidden += seen ? 0 : 1;
            }
        }
    }
    return views;
}

std::string pixelClass(const ShutterView& v) {
    const auto name = [](std::uint32_t id) {
        return id == testbed::ids::kMover     ? std::string("mover")
               : id == testbed::ids::kSpinner ? "spinner"
                                              : "";
    };
    const bool moved = v.earlyOther + v.lateOther > 0;
    if (!name(v.idNow).empty()) {
        if (!moved) {
            return name(v.idNow) + " interior";
        }
        return name(v.idNow) + (v.earlyOther >= v.lateOther ? " leading edge" : " trailing edge");
    }
    if (moved && !name(v.other).empty()) {
        return "background " + name(v.other) + (v.lateOther >= v.earlyOther ? " arrives" : " leaves");
    }
    return "other (camera motion)";
}

} // namespace

// On demand (--gtest_also_run_disabled_tests): the motion blur's error against the shutter truth broken
// down by pixel class and by cause, for docs/architecture.md. Each figure is RMSE over the truth's mean on
// the pixels the motion changes; a class's figure is its share of that (the shares add in quadrature).
TEST_F(GlTest, DISABLED_MotionBlurErrorBreakdown) {
    constexpr int kW = 160, kH = 90;
    struct Case {
        const char* name;
        std::initializer_list<std::string> overrides;
    };
    const Case cases[] = {
        {"moving objects", {"cameraSpeed=0", "cameraStart=0", "objectStart=4.5", "objectSpeed=12"}},
        {"pan", {"cameraStart=0.1", "cameraSpeed=3", "objectSpeed=0", "objectStart=1"}},
        {"mover in the clear",
         {"cameraSpeed=0", "objectStart=5.2", "objectSpeed=12", "fixedCamera=true", "eye=[0,0.9,-1.4]",
          "target=[0,0.35,-4.4]"}},
        {"mover out from behind the cube",
         {"cameraSpeed=0", "objectStart=4.5", "objectSpeed=12", "fixedCamera=true", "eye=[1.4,0.9,-1.4]",
          "target=[1.4,0.35,-4.4]"}},
        {"spinner close",
         {"cameraSpeed=0", "objectStart=4.5", "objectSpeed=12", "fixedCamera=true", "eye=[-0.8,1.0,3.8]",
          "target=[-0.8,0.37,2.0]"}},
    };
    for (const Case& c : cases) {
        auto scene = sceneWith(c.overrides, kW, kH);
        const std::uint64_t last = 2;
        testbed::TruthOptions o = scene->truthOptions({.dt = kDt, .frameIndex = last});
        o.samples = 1;
        o.shutterTimes = 64;
        const Settings on = blurSettings(true);
        const ImageF stillRaw = testbed::renderTruth(testbed::TruthKind::Color, o);
        const ImageF depth = testbed::renderTruth(testbed::TruthKind::Depth, o);
        const ImageF motion = testbed::renderTruth(testbed::TruthKind::Motion, o);
        const ImageF shutter = throughPipeline(testbed::renderTruth(testbed::TruthKind::Shutter, o), on);
        const ImageF still = throughPipeline(stillRaw, on);
        const Camera camera = testbed::truthCamera(o);
        // The velocity at the frame's time: the motion over 1% of a frame, scaled to a frame.
        testbed::TruthOptions instant = o;
        instant.times.prevObjects = o.times.objects - 0.01 * o.times.objectRate * kDt;
        instant.times.prevCamera = o.times.camera - 0.01 * o.times.cameraRate * kDt;
        ImageF velocity = testbed::renderTruth(testbed::TruthKind::Motion, instant);
        for (float& v : velocity.rgba) {
            v *= 100.0f;
        }
        const std::vector<ShutterView> views = shutterViews(o);
        std::vector<bool> moving(std::size_t(kW * kH), false);
        for (int i = 0; i < kW * kH; ++i) {
            for (int ch = 0; ch < 3; ++ch) {
                const float t = shutter.rgba[std::size_t(i) * 4 + ch];
                moving[std::size_t(i)] =
                    moving[std::size_t(i)] ||
                    std::abs(t - still.rgba[std::size_t(i) * 4 + ch]) > 0.02f * (t + 0.05f);
            }
        }
        double sum = 0.0, maxMotionError = 0.0;
        long n = 0;
        for (int i = 0; i < kW * kH; ++i) {
            n += moving[std::size_t(i)] ? 1 : 0;
            for (int ch = 0; ch < 3 && moving[std::size_t(i)]; ++ch) {
                sum += shutter.rgba[std::size_t(i) * 4 + ch];
            }
        }
        const double mean = sum / double(3 * n);
        std::printf("== %s: %ld moving pixels, truth mean %.3f\n", c.name, n, mean);
        {
            // The rasteriser's motion against the ray tracer's (same definition: now minus one frame ago).
            Pipeline pipeline({.settings = on});
            ImageF rasterMotion;
            for (std::uint64_t f = 0; f <= last; ++f) {
                std::vector<double> telemetry;
                const FrameTime time{.dt = kDt, .frameIndex = f};
                const FrameInputs in = scene->render(time, pipeline, telemetry);
                rasterMotion = readTextureF(*in.motion);
                pipeline.execute(in, time);
            }
            double instantGap = 0.0;
            for (int i = 0; i < kW * kH; ++i) {
                const float* r = rasterMotion.at(i % kW, i / kW);
                const std::size_t k = std::size_t(i) * 4;
                maxMotionError = std::max(
                    maxMotionError,
                    double(std::hypot((r[0] - motion.rgba[k]) * kW, (r[1] - motion.rgba[k + 1]) * kH)));
                instantGap += std::pow((velocity.rgba[k] - motion.rgba[k]) * kW, 2.0f) +
                              std::pow((velocity.rgba[k + 1] - motion.rgba[k + 1]) * kH, 2.0f);
            }
            std::printf("  motion input: rasteriser against the ray tracer at most %.3f px/frame apart; "
                        "backward difference against the velocity at the frame's time: RMS %.3f px/frame\n",
                        maxMotionError, std::sqrt(instantGap / (kW * kH)));
        }
        const auto report = [&](const char* label, const ImageF& image) {
            std::map<std::string, double> byClass;
            double all = 0.0, hiddenShare = 0.0;
            for (int i = 0; i < kW * kH; ++i) {
                if (!moving[std::size_t(i)]) {
                    continue;
                }
                double e = 0.0;
                for (int ch = 0; ch < 3; ++ch) {
                    const double d =
                        double(image.rgba[std::size_t(i) * 4 + ch]) - shutter.rgba[std::size_t(i) * 4 + ch];
                    e += d * d;
                }
                all += e;
                byClass[pixelClass(views[std::size_t(i)])] += e;
                hiddenShare += views[std::size_t(i)].hidden > 0 ? e : 0.0;
            }
            const auto share = [&](double e) { return 100.0 * std::sqrt(e / double(3 * n)) / mean; };
            std::printf("  %-36s %5.1f%% | hidden at t %4.1f |", label, share(all), share(hiddenShare));
            for (const auto& [name, e] : byClass) {
                std::printf(" %s %.1f", name.c_str(), share(e));
            }
            std::printf("\n");
        };
        std::map<std::string, int> classCount;
        long hiddenPixels = 0;
        for (int i = 0; i < kW * kH; ++i) {
            if (moving[std::size_t(i)]) {
                ++classCount[pixelClass(views[std::size_t(i)])];
                hiddenPixels += views[std::size_t(i)].hidden > 0 ? 1 : 0;
            }
        }
        std::printf("  pixels:");
        for (const auto& [name, count] : classCount) {
            std::printf(" %s %d,", name.c_str(), count);
        }
        std::printf(" of them %ld see a surface hidden at the frame's time\n", hiddenPixels);

        report("pass (rasterised inputs)", runScene(*scene, on, last));
        report("unblurred", runScene(*scene, blurSettings(false), last));
        report("pass (ray-traced inputs)", blurInputs(stillRaw, depth, motion, camera, on, last));
        report("  velocity at the frame's time", blurInputs(stillRaw, depth, velocity, camera, on, last));
        for (const auto& [label, sampleCount, tileSize] :
             {std::tuple{"  64 samples", 64, 20}, std::tuple{"  tiles of 8 px", 15, 8}}) {
            Settings s = on;
            s.motionBlur.sampleCount = sampleCount;
            s.motionBlur.tileSize = tileSize;
            s.motionBlur.maxBlur = std::min(s.motionBlur.maxBlur, float(tileSize));
            report(label, blurInputs(stillRaw, depth, motion, camera, s, last));
        }
        for (float angle : {150.0f, 210.0f}) {
            Settings s = on;
            s.motionBlur.shutterAngle = angle;
            report(angle < 180.0f ? "  shutter 150 (truth 180)" : "  shutter 210 (truth 180)",
                   blurInputs(stillRaw, depth, motion, camera, s, last));
        }
        {
            ImageF mean16(kW, kH, 0.0f);
            for (std::uint64_t f = 0; f < 16; ++f) {
                const ImageF r = blurInputs(stillRaw, depth, motion, camera, on, 100 + f);
                for (std::size_t k = 0; k < mean16.rgba.size(); ++k) {
                    mean16.rgba[k] += r.rgba[k] / 16.0f;
                }
            }
            report("  mean of 16 jitters", mean16);
        }
        report("one-layer reference", throughPipeline(singleLayerReference(o, stillRaw), on));
        testbed::TruthOptions fine = o;
        fine.shutterTimes = 1024;
        report("truth with 1024 instants",
               throughPipeline(testbed::renderTruth(testbed::TruthKind::Shutter, fine), on));
    }
}

// NaN and infinite motion and depth give finite colour.
TEST_F(GlTest, MotionBlurKeepsBrokenInputsOut) {
    const int w = 32, h = 16;
    ImageF color(w, h, 0.5f), depth(w, h, 5.0f), motion(w, h, 0.05f);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    motion.at(3, 3)[0] = nan;
    motion.at(4, 3)[1] = inf;
    depth.at(10, 5)[0] = nan;
    depth.at(11, 5)[0] = -1.0f;
    depth.at(12, 5)[0] = 0.0f;
    const Texture c = makeTexture(color, "color"), d = makeTexture(depth, "depth"),
                  m = makeTexture(motion, "motion");
    const Camera camera;
    Pipeline pipeline({.settings = blurSettings(true)});
    pipeline.beginFrame({.dt = kDt, .frameIndex = 1});
    pipeline.execute(
        {.color = &c, .depth = &d, .depthKind = DepthKind::LinearView, .motion = &m, .camera = &camera},
        {.dt = kDt, .frameIndex = 1});
    for (float v : readTextureF(pipeline.sceneReferred()).rgba) {
        ASSERT_TRUE(std::isfinite(v));
    }
}

} // namespace photopic::test
