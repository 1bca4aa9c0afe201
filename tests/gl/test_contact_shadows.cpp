// Contact shadows against the testbed's ray-traced sun visibility (occluders within the contact distance),
// through the lighting stage as a host uses it: the testbed's rasteriser draws its G-buffer, the pipeline's
// lighting stage hands back the sun visibility, and the rasteriser shades again with it.
//
// Classification (docs/architecture.md, "Contact shadows"): a pixel takes part when the ray tracer's surface
// there faces the sun (view-space normal . sun > 0.05: away from the terminator, where a normal's last bits
// decide); it is "shadowed" when the visibility is below 0.5, else "lit", for the reference and for the
// lighting stage's output alike.

#include "GlTest.h"

#include "gl/Objects.h"
#include "gl/TextureIo.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedRenderer.h"
#include "scenes/testbed/TestbedScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;
constexpr float kShadowed = 0.5f; ///< visibility below this: shadowed
constexpr float kFacing = 0.05f;  ///< normal . sun above this: the pixel is classified
/// Frames of accumulation before a still frame is measured (the history weight 0.9 leaves 0.9^12 = 28% of the
/// first frame, which was itself a full march).
constexpr std::uint64_t kSettleFrames = 12;

/// The testbed's truth options for a still frame at path time `seconds` (objects held at the same time), the
/// sun truth counting occluders within the default contact distance.
testbed::TruthOptions stillOptions(float seconds) {
    TestbedScene scene;
    const float distance = ContactShadowsSettings{}.distance;
    for (const std::string& a :
         {std::string("cameraSpeed=0"), std::string("objectSpeed=0"),
          "cameraStart=" + std::to_string(seconds), "objectStart=" + std::to_string(seconds),
          "sunMaxDistance=" + std::to_string(distance)}) {
        EXPECT_TRUE(scene.applyOverride(a).empty()) << a;
    }
    scene.resize({kW, kH});
    return scene.truthOptions({.dt = kDt, .frameIndex = 0});
}

/// The default contact shadows, fixed exposure.
Settings contactSettings() {
    Settings s;
    s.autoExposure.enabled = false;
    s.contactShadows.enabled = true;
    return s;
}

/// A host: the testbed's rasteriser driven frame by frame through both stages, the camera and objects held
/// at the options' time.
class Host {
public:
    explicit Host(const testbed::TruthOptions& options)
        : mOptions(options) {
        mRenderer.resize({options.width, options.height});
    }

    struct Frame {
        ImageF visibility; ///< the lighting stage's contact shadows (R), empty when it handed none
        ImageF color;      ///< the host's colour, shaded with them when there were any
    };

    float sunScale = 1.0f;  ///< the testbed's sun illuminance scale (0: no sun)
    bool objectIds = true;  ///< hand the pipeline the object-id texture
    bool resetEach = false; ///< Pipeline::reset() before every frame: no history is ever used

    Frame render(Pipeline& pipeline, std::uint64_t frameIndex) {
        const FrameTime time{.dt = kDt, .frameIndex = frameIndex};
        const Camera camera = testbed::truthCamera(mOptions);
        const std::vector<testbed::Primitive> prims =
            testbed::primitivesAt(mOptions.times.objects, mOptions.times.prevObjects);
        if (resetEach) {
            pipeline.reset();
        }
        const glm::vec2 jitter = pipeline.beginFrame(time, &camera);
        testbed::TestbedRenderer::DrawInfo draw{
            .camera = &camera, .jitter = jitter, .primitives = &prims, .sunScale = sunScale};
        mRenderer.draw(draw);
        const FrameInputs in{.color = &mRenderer.color(),
                             .depth = &mRenderer.depth(),
                             .normals = &mRenderer.normals(),
                             .motion = &mRenderer.motion(),
                             .camera = &camera,
                             .sunDirection = testbed::environment().sunDirection,
                             .objectId = objectIds ? &mRenderer.objectId() : nullptr};
        const LightingOutputs& lit = pipeline.renderLighting(in, time);
        Frame f;
        if (lit.contactShadows != nullptr) {
            f.visibility = readTextureF(*lit.contactShadows);
            draw.sunVisibility = lit.contactShadows;
            mRenderer.draw(draw);
        }
        f.color = readTextureF(mRenderer.color());
        pipeline.execute(in, time);
        return f;
    }

    /// Frames 0 .. count - 1; returns the last.
    Frame run(Pipeline& pipeline, std::uint64_t count) {
        Frame f;
        for (std::uint64_t i = 0; i < count; ++i) {
            f = render(pipeline, i);
        }
        return f;
    }

private:
    testbed::TruthOptions mOptions;
    testbed::TestbedRenderer mRenderer;
};

/// Which pixels face the sun (the ray tracer's normals; the sky and surfaces turned away are left out).
std::vector<bool> facingPixels(const testbed::TruthOptions& options) {
    const ImageF normals = testbed::renderTruth(testbed::TruthKind::Normals, options);
    const Camera camera = testbed::truthCamera(options);
    const glm::vec3 sun = glm::normalize(glm::mat3(camera.view) * testbed::environment().sunDirection);
    std::vector<bool> facing(std::size_t(kW * kH), false);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float* n = normals.at(x, y);
            const glm::vec3 normal(n[0], n[1], n[2]);
            facing[std::size_t(y * kW + x)] =
                glm::dot(normal, normal) > 0.5f && glm::dot(normal, sun) > kFacing;
        }
    }
    return facing;
}

struct Agreement {
    long classified = 0;   ///< pixels facing the sun
    long agree = 0;        ///< both shadowed or both lit
    long refShadowed = 0;  ///< reference shadowed
    long found = 0;        ///< ... and shadowed by contact shadows too
    long refLit = 0;       ///< reference lit
    long falseShadows = 0; ///< ... but shadowed by contact shadows
    [[nodiscard]] double agreement() const { return classified ? double(agree) / double(classified) : 0.0; }
    [[nodiscard]] double recall() const { return refShadowed ? double(found) / double(refShadowed) : 0.0; }
    [[nodiscard]] double falseRate() const { return refLit ? double(falseShadows) / double(refLit) : 1.0; }
};

Agreement classify(const ImageF& ours, const ImageF& truth, const std::vector<bool>& facing) {
    Agreement a;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (!facing[std::size_t(y * kW + x)]) {
                continue;
            }
            const bool ref = truth.at(x, y)[0] < kShadowed;
            const bool got = ours.at(x, y)[0] < kShadowed;
            ++a.classified;
            a.agree += ref == got ? 1 : 0;
            a.refShadowed += ref ? 1 : 0;
            a.found += ref && got ? 1 : 0;
            a.refLit += ref ? 0 : 1;
            a.falseShadows += !ref && got ? 1 : 0;
        }
    }
    return a;
}

/// Darkening (1 - visibility) over the pixels the reference leaves fully lit: facing the sun, visibility 1,
/// and no reference shadow in their 3x3 neighbourhood (a shadow's edge falls within a pixel there).
struct Fog {
    long pixels = 0;
    double mean = 0.0;
    double p99 = 0.0;
    double max = 0.0;
};

Fog fogOverLitPixels(const ImageF& ours, const ImageF& truth, const std::vector<bool>& facing) {
    std::vector<double> dark;
    for (int y = 1; y < kH - 1; ++y) {
        for (int x = 1; x < kW - 1; ++x) {
            bool lit = facing[std::size_t(y * kW + x)];
            for (int d = 0; d < 9 && lit; ++d) {
                const int qx = x + d % 3 - 1, qy = y + d / 3 - 1;
                lit = !facing[std::size_t(qy * kW + qx)] || truth.at(qx, qy)[0] >= 1.0f;
            }
            if (lit) {
                dark.push_back(1.0 - double(ours.at(x, y)[0]));
            }
        }
    }
    Fog f;
    f.pixels = long(dark.size());
    if (dark.empty()) {
        return f;
    }
    std::sort(dark.begin(), dark.end());
    double sum = 0.0;
    for (double d : dark) {
        sum += d;
    }
    f.mean = sum / double(dark.size());
    f.p99 = dark[std::min(dark.size() - 1, std::size_t(0.99 * double(dark.size())))];
    f.max = dark.back();
    return f;
}

bool finiteInUnitRange(const ImageF& image) {
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float v = image.at(x, y)[0];
            if (!(v >= 0.0f && v <= 1.0f)) {
                return false;
            }
        }
    }
    return true;
}

/// Path times measured: shot 0 panning (the wall, spheres, cube and poles far off), shot 0 after the dolly
/// (closer), shot 1 (a low camera towards the sun through the poles).
constexpr float kTimes[] = {0.3f, 0.9f, 1.5f};

} // namespace

// Against the ray tracer's sun visibility within the contact distance (0.18 m), the default settings, 160x90,
// after 12 still frames. Over the pixels facing the sun, contact shadows and the reference agree on >= 90%
// of them (shadowed vs lit at 0.5). Most classified pixels are lit, so an output that shadows nothing would
// agree too: contact shadows must also find >= 30% of the reference's shadowed pixels (measured: 50%, 35%
// and 75%; the misses are occluders narrower than a pixel, which the depth buffer does not hold: the metal
// strip's 2 cm front face, the wall's foot 15 m away) and shadow <= 0.5% of its lit ones.
TEST_F(GlTest, ContactShadowsAgreeWithTheRayTracedSunVisibility) {
    for (float seconds : kTimes) {
        const testbed::TruthOptions options = stillOptions(seconds);
        const ImageF truth = testbed::renderTruth(testbed::TruthKind::Sun, options);
        const std::vector<bool> facing = facingPixels(options);
        Host host(options);
        Pipeline pipeline({.settings = contactSettings()});
        const Host::Frame f = host.run(pipeline, kSettleFrames);
        ASSERT_FALSE(f.visibility.empty());
        const Agreement a = classify(f.visibility, truth, facing);
        std::printf(
            "contact shadows at %.1f s: agreement %.4f over %ld px facing the sun; reference shadowed "
            "%ld px, found %.3f; reference lit %ld px, shadowed %.4f\n",
            double(seconds), a.agreement(), a.classified, a.refShadowed, a.recall(), a.refLit, a.falseRate());
        EXPECT_GT(a.refShadowed, 30) << seconds;
        EXPECT_GE(a.agreement(), 0.90) << seconds;
        EXPECT_GE(a.recall(), 0.30) << seconds;
        EXPECT_LE(a.falseRate(), 0.005) << seconds;
    }
}

// No grey fog: where the reference is fully lit (facing the sun, visibility 1, and no reference shadow in the
// pixel's 3x3 neighbourhood), contact shadows darken the sun's light by <= 2% on average and at the 99th
// percentile.
TEST_F(GlTest, ContactShadowsLeaveLitSurfacesLit) {
    for (float seconds : kTimes) {
        const testbed::TruthOptions options = stillOptions(seconds);
        const ImageF truth = testbed::renderTruth(testbed::TruthKind::Sun, options);
        Host host(options);
        Pipeline pipeline({.settings = contactSettings()});
        const Host::Frame f = host.run(pipeline, kSettleFrames);
        ASSERT_FALSE(f.visibility.empty());
        const Fog fog = fogOverLitPixels(f.visibility, truth, facingPixels(options));
        std::printf("contact shadows at %.1f s over %ld fully lit px: darkening mean %.4f, 99th percentile "
                    "%.4f, max %.4f\n",
                    double(seconds), fog.pixels, fog.mean, fog.p99, fog.max);
        EXPECT_GT(fog.pixels, 1000) << seconds;
        EXPECT_LE(fog.mean, 0.02) << seconds;
        EXPECT_LE(fog.p99, 0.02) << seconds;
    }
}

// The factor multiplies the sun's term only: with the sun off, the host's colour is bit-identical with and
// without contact shadows; with the sun on, it is not (the factor does reach the shading).
TEST_F(GlTest, ContactShadowsTouchOnlyTheSunTerm) {
    const testbed::TruthOptions options = stillOptions(0.9f);
    Settings off = contactSettings();
    off.contactShadows.enabled = false;
    for (float sun : {0.0f, 1.0f}) {
        Host with(options), without(options);
        with.sunScale = without.sunScale = sun;
        Pipeline on({.settings = contactSettings()});
        Pipeline plain({.settings = off});
        const Host::Frame a = with.run(on, 3);
        const Host::Frame b = without.run(plain, 3);
        ASSERT_FALSE(a.visibility.empty());
        ASSERT_TRUE(b.visibility.empty());
        const bool identical =
            std::memcmp(a.color.rgba.data(), b.color.rgba.data(), a.color.rgba.size() * sizeof(float)) == 0;
        EXPECT_EQ(identical, sun == 0.0f) << "sun scale " << sun;
    }
}

// A still camera: the start offset moves every frame, the accumulation averages it. After settling, the
// visibility changes by <= 0.002 per frame on average and no pixel by more than 0.1 on more than 0.2% of
// pixels, and by less than half of what the march alone (no history: reset every frame) changes.
TEST_F(GlTest, ContactShadowsAreStableOnAStillCamera) {
    const testbed::TruthOptions options = stillOptions(0.9f);
    const auto flicker = [&](bool accumulate, double& mean, double& jumps) {
        Host host(options);
        host.resetEach = !accumulate;
        Pipeline pipeline({.settings = contactSettings()});
        ImageF previous = host.run(pipeline, kSettleFrames).visibility;
        double sum = 0.0;
        long big = 0, n = 0;
        for (std::uint64_t i = kSettleFrames; i < kSettleFrames + 8; ++i) {
            const ImageF current = host.render(pipeline, i).visibility;
            for (int y = 0; y < kH; ++y) {
                for (int x = 0; x < kW; ++x) {
                    const double d = std::abs(double(current.at(x, y)[0]) - double(previous.at(x, y)[0]));
                    sum += d;
                    big += d > 0.1 ? 1 : 0;
                    ++n;
                }
            }
            previous = current;
        }
        mean = sum / double(n);
        jumps = double(big) / double(n);
    };
    double accumulated = 0.0, accumulatedJumps = 0.0, raw = 0.0, rawJumps = 0.0;
    flicker(true, accumulated, accumulatedJumps);
    flicker(false, raw, rawJumps);
    std::printf("contact shadows, still camera: mean change per frame %.5f (march alone %.5f); pixels "
                "changing by > 0.1: %.4f (march alone %.4f)\n",
                accumulated, raw, accumulatedJumps, rawJumps);
    EXPECT_LE(accumulated, 0.002);
    EXPECT_LE(accumulatedJumps, 0.002);
    EXPECT_LT(accumulated, 0.5 * raw);
}

// contactShadows.mask: only the listed objects receive (and cast) contact shadows; every pixel of another
// object keeps visibility 1. Without an object-id input a mask cannot be honoured: the pass is skipped and
// says what it lacks.
TEST_F(GlTest, ContactShadowsMaskLimitsTheEffectToListedObjects) {
    const testbed::TruthOptions options = stillOptions(0.9f);
    const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, options);
    Settings s = contactSettings();
    s.contactShadows.mask = {testbed::ids::kGround, testbed::ids::kStrip};
    Pipeline pipeline({.settings = s});
    Host host(options);
    const ImageF masked = host.run(pipeline, 3).visibility;
    Pipeline unmaskedPipeline({.settings = contactSettings()});
    Host unmaskedHost(options);
    const ImageF unmasked = unmaskedHost.run(unmaskedPipeline, 3).visibility;
    ASSERT_FALSE(masked.empty());
    long otherPixels = 0, otherNotOne = 0, otherShadowedUnmasked = 0, listedShadowed = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const auto id = std::uint32_t(ids.at(x, y)[0]);
            if (id == testbed::ids::kGround || id == testbed::ids::kStrip) {
                listedShadowed += masked.at(x, y)[0] < kShadowed ? 1 : 0;
            } else if (id != 0) {
                ++otherPixels;
                otherNotOne += masked.at(x, y)[0] != 1.0f ? 1 : 0;
                otherShadowedUnmasked += unmasked.at(x, y)[0] < kShadowed ? 1 : 0;
            }
        }
    }
    std::printf("mask {ground, strip}: %ld px of other objects (%ld shadowed without the mask), %ld not 1; "
                "%ld listed px shadowed\n",
                otherPixels, otherShadowedUnmasked, otherNotOne, listedShadowed);
    EXPECT_GT(otherShadowedUnmasked, 100); // the mask has something to remove
    EXPECT_EQ(otherNotOne, 0);
    EXPECT_GT(listedShadowed, 10); // the strip's edge still shadows the ground

    host.objectIds = false;
    const Host::Frame none = host.render(pipeline, 3);
    EXPECT_TRUE(none.visibility.empty());
    const PipelineStatus status = pipeline.status();
    const auto skipped = std::find_if(status.skipped.begin(), status.skipped.end(),
                                      [](const SkippedPass& p) { return p.pass == "contact shadows"; });
    ASSERT_NE(skipped, status.skipped.end());
    EXPECT_EQ(skipped->missing, std::vector<std::string>{"objectId"});
}

// NaN and infinities in depth (and NaN normals and motion) never reach the visibility: every value stays in
// [0, 1]. A sun direction that is not a finite, non-zero vector is an input error, and the pass is skipped.
TEST_F(GlTest, ContactShadowsSurviveBrokenInputs) {
    constexpr int w = 64, h = 36;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    ImageF depth(w, h, 0.0f), normals(w, h, 0.0f), motion(w, h, 0.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // A floor receding from the camera with a box standing on it, broken every few pixels.
            float z = 2.0f + 0.1f * float(h - y);
            glm::vec3 n(0.0f, 1.0f, 0.0f);
            if (x > 20 && x < 40 && y < 20) {
                z = 3.0f;
                n = glm::vec3(0.0f, 0.0f, 1.0f);
            }
            const int k = (x * 7 + y * 13) % 11;
            z = k == 0 ? nan : k == 1 ? inf : k == 2 ? -inf : k == 3 ? 0.0f : z;
            if (k == 4) {
                n = glm::vec3(nan);
            }
            depth.at(x, y)[0] = z;
            normals.at(x, y)[0] = n.x;
            normals.at(x, y)[1] = n.y;
            normals.at(x, y)[2] = n.z;
            motion.at(x, y)[0] = k == 5 ? nan : 0.0f;
        }
    }
    const Texture color = makeTexture(ImageF(w, h, 0.5f), "colour");
    const Texture depthTexture = makeTexture(depth, "depth");
    const Texture normalTexture = makeTexture(normals, "normals");
    const Texture motionTexture = makeTexture(motion, "motion");
    Camera camera;
    camera.projection = perspectiveProjection(camera.verticalFov, float(w) / float(h), 0.1f, 100.0f);
    camera.prevViewProjection = camera.viewProjection();
    FrameInputs in{.color = &color,
                   .depth = &depthTexture,
                   .depthKind = DepthKind::LinearView,
                   .normals = &normalTexture,
                   .motion = &motionTexture,
                   .camera = &camera,
                   .sunDirection = glm::vec3(0.2f, 0.8f, -0.5f)};
    Pipeline pipeline({.settings = contactSettings()});
    for (std::uint64_t i = 0; i < 4; ++i) {
        const LightingOutputs& lit = pipeline.renderLighting(in, {.dt = kDt, .frameIndex = i});
        ASSERT_NE(lit.contactShadows, nullptr);
        EXPECT_TRUE(finiteInUnitRange(readTextureF(*lit.contactShadows))) << "frame " << i;
        pipeline.execute(in, {.dt = kDt, .frameIndex = i});
    }

    in.sunDirection = glm::vec3(nan, 1.0f, 0.0f);
    EXPECT_EQ(pipeline.renderLighting(in, {.dt = kDt, .frameIndex = 4}).contactShadows, nullptr);
    const PipelineStatus status = pipeline.status();
    EXPECT_NE(std::find(status.inputErrors.begin(), status.inputErrors.end(),
                        "sunDirection: not a finite, non-zero vector"),
              status.inputErrors.end());
    in.sunDirection = glm::vec3(0.0f);
    EXPECT_EQ(pipeline.renderLighting(in, {.dt = kDt, .frameIndex = 5}).contactShadows, nullptr);
    pipeline.execute(in, {.dt = kDt, .frameIndex = 5});
}

// The debug views: `contact-shadows` shows the factor, and its scene-referred (EXR) image holds the factor's
// raw values; `contact-shadows-steps` shows the steps each march took over the step count (0 for the
// sky, 1 for a march that found nothing and stayed on screen). After the first frames, no GL object is made.
TEST_F(GlTest, ContactShadowsDebugViewsShowRawValues) {
    const testbed::TruthOptions options = stillOptions(0.9f);
    const ImageF depth = testbed::renderTruth(testbed::TruthKind::Depth, options);
    Settings s = contactSettings();
    s.debug.view = DebugView::ContactShadows;
    Pipeline pipeline({.settings = s});
    Host host(options);
    const Host::Frame f = host.run(pipeline, 2);
    ASSERT_FALSE(f.visibility.empty());
    const ImageF raw = readTextureF(pipeline.sceneReferred());
    double maxDifference = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            for (int c = 0; c < 3; ++c) {
                maxDifference =
                    std::max(maxDifference, double(std::abs(raw.at(x, y)[c] - f.visibility.at(x, y)[0])));
            }
        }
    }
    EXPECT_EQ(maxDifference, 0.0);

    s.debug.view = DebugView::ContactShadowSteps;
    pipeline.setSettings(s);
    host.run(pipeline, 2);
    const GlObjectCounts before = glObjectCounts();
    host.render(pipeline, 2);
    host.render(pipeline, 3);
    EXPECT_EQ(glObjectCounts(), before);
    const ImageF steps = readTextureF(pipeline.sceneReferred());
    long sky = 0, skyZero = 0, full = 0, partial = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float v = steps.at(x, y)[0];
            EXPECT_TRUE(v >= 0.0f && v <= 1.0f);
            if (!std::isfinite(depth.at(x, y)[0])) {
                ++sky;
                skyZero += v == 0.0f ? 1 : 0;
            } else {
                full += v == 1.0f ? 1 : 0;
                partial += v > 0.0f && v < 1.0f ? 1 : 0;
            }
        }
    }
    EXPECT_GT(sky, 100);
    EXPECT_EQ(skyZero, sky);
    EXPECT_GT(full, 1000);  // lit ground: every step taken
    EXPECT_GT(partial, 10); // hits stop early
}

} // namespace photopic::test
