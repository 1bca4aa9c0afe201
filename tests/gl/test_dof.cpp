// Depth of field against the testbed's thin-lens ray tracing (the `thinlens` truth: colour through a lens of
// the camera's focal length, f-number and focus), and on synthetic layers where the right answer is known
// exactly: pixels in focus keep their value, a sharp object does not bleed into the blurred background behind
// it (nor the background into it), and a blurred foreground covers the sharp background next to it with the
// fraction of its disc that reaches there.

#include "GlTest.h"

#include "core/DepthOfField.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;

/// Fixed exposure, no bloom, no dither, no anti-aliasing: the scene-referred image is the colour as DoF
/// leaves it.
Settings measuring(bool dof) {
    Settings s;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.dof.enabled = dof;
    // 16 jittered sub-frames averaged before the post stage: the rasteriser's edges come close to the
    // truth's 12 x 12 samples, so what is left to measure is the blur.
    s.aa.mode = AntiAliasing::Ssaa;
    s.aa.level = 4;
    return s;
}

/// A still framing of the testbed: the large sphere in focus at 8.1 m, the metal strip, the fence and the
/// tall box in front, the wall behind. A 300 mm sensor (a 362 mm lens at the testbed's 45-degree field of
/// view) at f/1 gives CoCs of up to about 6 px at 160x90.
std::unique_ptr<TestbedScene> framedScene(const std::vector<std::string>& extra = {}) {
    auto scene = std::make_unique<TestbedScene>();
    std::vector<std::string> overrides = {"cameraSpeed=0",    "objectSpeed=0",    "objectStart=1",
                                          "fixedCamera=true", "eye=[-1, 1.2, 6]", "target=[-2.5, 1, -2]",
                                          "sensorHeight=300", "fNumber=1",        "samples=12"};
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    for (const std::string& a : overrides) {
        EXPECT_TRUE(scene->applyOverride(a).empty()) << a;
    }
    scene->resize({kW, kH});
    return scene;
}

/// One frame of the scene through `pipeline`: its scene-referred image.
ImageF render(TestbedScene& scene, Pipeline& pipeline) {
    std::vector<double> telemetry;
    const FrameTime time{.dt = kDt, .frameIndex = 0};
    const FrameInputs in = scene.render(time, pipeline, telemetry);
    pipeline.execute(in, time);
    return readTextureF(pipeline.sceneReferred());
}

/// An image through a pipeline without DoF (the same exposure and output as the measured one).
ImageF throughPipeline(const ImageF& image) {
    Pipeline pipeline({.settings = measuring(false)});
    const Texture t = makeTexture(image, "truth");
    pipeline.execute({.color = &t}, {});
    return readTextureF(pipeline.sceneReferred());
}

/// sqrt(sum (a - b)^2 / sum b^2) over RGB of the pixels `mask` selects (all when empty).
double relativeRmse(const ImageF& a, const ImageF& b, const std::vector<bool>& mask = {}) {
    double err = 0.0, ref = 0.0;
    for (int y = 0; y < b.height; ++y) {
        for (int x = 0; x < b.width; ++x) {
            if (!mask.empty() && !mask[std::size_t(y * b.width + x)]) {
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.at(x, y)[c]) - double(b.at(x, y)[c]);
                err += d * d;
                ref += double(b.at(x, y)[c]) * double(b.at(x, y)[c]);
            }
        }
    }
    return ref > 0.0 ? std::sqrt(err / ref) : 0.0;
}

void dump(const char* name, const ImageF& image) {
    if (const char* dir = std::getenv("PHOTOPIC_DOF_DUMP")) {
        writeExr(std::string(dir) + "/" + name + ".exr", image);
        constexpr int kScale = 4;
        Image8 png(image.width * kScale, image.height * kScale);
        for (int y = 0; y < png.height; ++y) {
            for (int x = 0; x < png.width; ++x) {
                for (int c = 0; c < 4; ++c) {
                    const float e = image.at(x / kScale, y / kScale)[c];
                    const float v = c == 3 ? 1.0f : e / (1.0f + e);
                    png.rgba[std::size_t((y * png.width + x) * 4 + c)] =
                        std::uint8_t(std::lround(255.0f * std::pow(std::clamp(v, 0.0f, 1.0f), 1.0f / 2.2f)));
                }
            }
        }
        writePng(std::string(dir) + "/" + name + ".png", png);
    }
}

/// Synthetic layers: colour and linear depth (scene units, rows top to bottom) seen by a still camera.
struct Layers {
    explicit Layers(int w, int h)
        : color(w, h, 0.0f)
        , depth(std::size_t(w * h), 100.0f) {
        for (std::size_t i = 3; i < color.rgba.size(); i += 4) {
            color.rgba[i] = 1.0f;
        }
    }
    ImageF color;
    std::vector<float> depth;
    void set(int x, int y, float r, float g, float b, float z) {
        float* p = color.at(x, y);
        p[0] = r;
        p[1] = g;
        p[2] = b;
        depth[std::size_t(y * color.width + x)] = z;
    }
};

/// The layers through a pipeline with `settings`: the scene-referred image.
ImageF runLayers(const Layers& layers, const Settings& settings) {
    const int w = layers.color.width, h = layers.color.height;
    Texture depth({.extent = {w, h},
                   .format = GL_R32F,
                   .minFilter = GL_NEAREST,
                   .magFilter = GL_NEAREST,
                   .debugName = "depth"});
    std::vector<float> flipped(layers.depth.size());
    for (int y = 0; y < h; ++y) {
        std::copy_n(layers.depth.begin() + std::ptrdiff_t(y) * w, w,
                    flipped.begin() + std::ptrdiff_t(h - 1 - y) * w);
    }
    glTextureSubImage2D(depth.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, flipped.data());
    const Texture color = makeTexture(layers.color, "color");
    Camera camera;
    camera.projection = perspectiveProjection(camera.verticalFov, float(w) / float(h), 0.1f, 1000.0f);
    camera.prevViewProjection = camera.projection;
    Settings s = settings;
    s.aa.mode = AntiAliasing::None;
    Pipeline pipeline({.settings = s});
    pipeline.execute(
        {.color = &color, .depth = &depth, .depthKind = DepthKind::LinearView, .camera = &camera},
        {.dt = kDt});
    EXPECT_TRUE(pipeline.status().skipped.empty());
    return readTextureF(pipeline.sceneReferred());
}

/// Artistic mode with the far field at bokehRadius (depth 100, focus 10, range 5).
Settings artistic(float bokehRadius) {
    Settings s = measuring(true);
    s.dof.mode = DofMode::Artistic;
    s.dof.focalDistance = 10.0f;
    s.dof.focalRange = 5.0f;
    s.dof.bokehRadius = bokehRadius;
    return s;
}

} // namespace

// A bright point on a black background blurred by a CoC of R pixels spreads into a disc of radius R: its
// energy is kept (HDR, no clamp) and the spread's second moment is that of a uniform disc, R^2 / 2.
TEST_F(GlTest, DofSpreadsAPointIntoADiscOfItsCoc) {
    for (float radius : {3.0f, 6.0f, 12.0f}) {
        Layers layers(64, 64);
        layers.set(32, 32, 1000.0f, 1000.0f, 1000.0f, 100.0f);
        const ImageF out = runLayers(layers, artistic(radius));
        double energy = 0.0, moment = 0.0, peak = 0.0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                const double v = out.at(x, y)[1];
                const double dx = x - 32, dy = y - 32;
                energy += v;
                moment += v * (dx * dx + dy * dy);
                peak = std::max(peak, v);
            }
        }
        const double spread = std::sqrt(2.0 * moment / energy);
        std::printf("CoC %.0f px: energy %.1f (of 1000), spread radius %.2f px, peak %.1f\n", radius, energy,
                    spread, peak);
        EXPECT_NEAR(energy, 1000.0, 100.0);
        EXPECT_NEAR(spread, radius, 0.2 * radius);
    }
}

// Physical mode against the thin-lens truth. The pipeline starts from the rasteriser's one sample per pixel
// (aliased edges the truth's 12 x 12 samples do not have), so the same comparison without DoF is the
// baseline: the error must be well under it where the truth is blurred, and within the bound overall.
TEST_F(GlTest, DofMatchesTheThinLensTruth) {
    auto scene = framedScene();
    const testbed::TruthOptions options = scene->truthOptions({.dt = kDt, .frameIndex = 0});
    const ImageF truth = throughPipeline(testbed::renderTruth(testbed::TruthKind::ThinLens, options));
    const ImageF depth = testbed::renderTruth(testbed::TruthKind::Depth, options);
    Pipeline on({.settings = measuring(true)});
    const ImageF withDof = render(*scene, on);
    Pipeline off({.settings = measuring(false)});
    const ImageF without = render(*scene, off);
    dump("truth", truth);
    dump("dof", withDof);
    dump("pinhole", without);
    {
        ImageF e1 = truth, e2 = truth;
        for (std::size_t i = 0; i < e1.rgba.size(); ++i) {
            e1.rgba[i] = 4.0f * std::abs(withDof.rgba[i] - truth.rgba[i]);
            e2.rgba[i] = 4.0f * std::abs(without.rgba[i] - truth.rgba[i]);
        }
        dump("err_dof", e1);
        dump("err_pinhole", e2);
    }

    // Pixels the truth blurs by more than 1.5 px (the CPU model of the camera's CoC at the pixel's depth).
    const CocModel model = cocModel(measuring(true).dof, testbed::truthCamera(options).lens, kH);
    std::vector<bool> blurred(std::size_t(kW * kH));
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            blurred[std::size_t(y * kW + x)] = std::abs(model.radius(depth.at(x, y)[0])) > 1.5f;
        }
    }
    std::vector<bool> nearMask(blurred.size()), farMask(blurred.size()), focusMask(blurred.size());
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float r = model.radius(depth.at(x, y)[0]);
            nearMask[std::size_t(y * kW + x)] = r < -1.5f;
            farMask[std::size_t(y * kW + x)] = r > 1.5f;
            focusMask[std::size_t(y * kW + x)] = std::abs(r) < 0.5f;
        }
    }
    std::printf("near field %.4f (%.4f) far %.4f (%.4f) focus %.4f (%.4f)\n",
                relativeRmse(withDof, truth, nearMask), relativeRmse(without, truth, nearMask),
                relativeRmse(withDof, truth, farMask), relativeRmse(without, truth, farMask),
                relativeRmse(withDof, truth, focusMask), relativeRmse(without, truth, focusMask));
    const double all = relativeRmse(withDof, truth);
    const double allBase = relativeRmse(without, truth);
    const double blur = relativeRmse(withDof, truth, blurred);
    const double blurBase = relativeRmse(without, truth, blurred);
    std::printf("DoF vs thin lens: relative RMSE %.4f (no DoF %.4f); blurred pixels %.4f (no DoF %.4f)\n",
                all, allBase, blur, blurBase);
    EXPECT_LE(all, 0.12);
    EXPECT_LE(blur, 0.10);
    EXPECT_LT(blur, 0.7 * blurBase);
    EXPECT_LT(relativeRmse(withDof, truth, nearMask), 0.8 * relativeRmse(without, truth, nearMask));
    EXPECT_LT(relativeRmse(withDof, truth, farMask), 0.8 * relativeRmse(without, truth, farMask));
}

} // namespace photopic::test

namespace photopic::test {

namespace {

constexpr int kLayerW = 96;
constexpr int kLayerH = 64;
constexpr float kFar = 100.0f;  ///< artistic CoC +bokehRadius
constexpr float kFocus = 10.0f; ///< in focus
constexpr float kNear = 5.0f;   ///< artistic CoC -bokehRadius

/// A sharp red square in focus (x, y in [40, 56)), blue background far behind it.
Layers sharpOverBlurred() {
    Layers layers(kLayerW, kLayerH);
    for (int y = 0; y < kLayerH; ++y) {
        for (int x = 0; x < kLayerW; ++x) {
            const bool object = x >= 40 && x < 56 && y >= 24 && y < 40;
            layers.set(x, y, object ? 4.0f : 0.0f, 0.0f, object ? 0.0f : 2.0f, object ? kFocus : kFar);
        }
    }
    return layers;
}

} // namespace

// The coc view's raw values (EXR) are the CPU model's signed radius over maxCocRadius: red near, blue far.
TEST_F(GlTest, DofCocViewHoldsTheSignedRadius) {
    Layers layers(kLayerW, kLayerH);
    for (int x = 0; x < kLayerW; ++x) {
        for (int y = 0; y < kLayerH; ++y) {
            layers.set(x, y, 1.0f, 1.0f, 1.0f, 2.0f + 0.25f * float(x)); // 2 .. 25.75 scene units
        }
    }
    Settings s = artistic(6.0f);
    s.debug.view = DebugView::Coc;
    const ImageF view = runLayers(layers, s);
    CocModel model;
    model.artistic = true;
    model.focalDistance = 10.0f;
    model.focalRange = 5.0f;
    model.bokehRadius = 6.0f;
    model.maxRadius = s.dof.maxCocRadius;
    double worst = 0.0;
    for (int x = 0; x < kLayerW; ++x) {
        const float expected = model.radius(2.0f + 0.25f * float(x));
        const float* p = view.at(x, kLayerH / 2);
        const float got = (p[2] - p[0]) * s.dof.maxCocRadius;
        worst = std::max(worst, double(std::abs(got - expected)));
        ASSERT_TRUE(p[0] == 0.0f || p[2] == 0.0f) << x; // one field per pixel
        ASSERT_EQ(p[1], 0.0f);
    }
    EXPECT_LE(worst, 0.01); // R16F: 11 bits over 6 px
}

// Pixels in focus that no blurred foreground reaches keep their value exactly; a sharp object does not
// bleed into the blurred background around it, nor the blurred background into it.
TEST_F(GlTest, DofKeepsFocusSharpAndDoesNotBleed) {
    const Layers layers = sharpOverBlurred();
    for (DofKernel kernel : {DofKernel::Disc, DofKernel::Hexagon}) {
        Settings s = artistic(6.0f);
        s.dof.kernel = kernel;
        const ImageF out = runLayers(layers, s);
        Settings off = s;
        off.dof.enabled = false;
        const ImageF sharp = runLayers(layers, off);
        long changed = 0, object = 0;
        double redOutside = 0.0, redInside = 0.0, blueInside = 0.0, blueOutside = 0.0;
        long outside = 0;
        for (int y = 0; y < kLayerH; ++y) {
            for (int x = 0; x < kLayerW; ++x) {
                const bool inObject = x >= 40 && x < 56 && y >= 24 && y < 40;
                const float* p = out.at(x, y);
                if (inObject) {
                    ++object;
                    changed += std::memcmp(p, sharp.at(x, y), 3 * sizeof(float)) != 0 ? 1 : 0;
                    redInside += p[0];
                    blueInside += p[2];
                } else {
                    ++outside;
                    redOutside += p[0];
                    blueOutside += p[2];
                }
            }
        }
        // Red the object lost to the background, and blue the background lost to the object, as fractions.
        const double redBleed = redOutside / (redInside + redOutside);
        const double blueBleed = blueInside / (blueInside + blueOutside) * double(outside) / double(object);
        std::printf(
            "%s: in-focus pixels changed %ld of %ld; object into background %.5f, background into object "
            "%.5f\n",
            kernel == DofKernel::Disc ? "disc" : "hexagon", changed, object, redBleed, blueBleed);
        EXPECT_EQ(changed, 0);
        EXPECT_LE(redBleed, 0.001);
        EXPECT_LE(blueBleed, 0.001);
    }
}

// A blurred foreground (a half plane at CoC -6 px) over sharp background: at distance d outside its edge the
// foreground's share is the part of a 6 px disc beyond d (the thin-lens answer for a defocused edge), and
// the background far from the edge is untouched.
TEST_F(GlTest, DofNearFieldCoversTheSharpBackground) {
    Layers layers(kLayerW, kLayerH);
    const int edge = 48;
    for (int y = 0; y < kLayerH; ++y) {
        for (int x = 0; x < kLayerW; ++x) {
            const bool fg = x < edge;
            layers.set(x, y, fg ? 0.0f : 1.0f, fg ? 3.0f : 0.0f, 0.0f, fg ? kNear : kFocus);
        }
    }
    const float radius = 6.0f;
    const ImageF out = runLayers(layers, artistic(radius));
    double worst = 0.0;
    for (int x = edge; x < edge + 8; ++x) {
        const double d = double(x - edge) + 0.5; // pixel centre's distance from the edge
        const double t = std::min(d / radius, 1.0);
        const double expected = (std::acos(t) - t * std::sqrt(1.0 - t * t)) / std::numbers::pi;
        double got = 0.0;
        for (int y = 8; y < kLayerH - 8; ++y) {
            got += out.at(x, y)[1] / 3.0;
        }
        got /= double(kLayerH - 16);
        std::printf("d %.1f px: foreground share %.3f (disc %.3f)\n", d, got, expected);
        worst = std::max(worst, std::abs(got - expected));
    }
    EXPECT_LE(worst, 0.05);
    for (int y = 0; y < kLayerH; ++y) {
        EXPECT_EQ(out.at(kLayerW - 1, y)[1], 0.0f);
    }
}

} // namespace photopic::test

namespace photopic::test {

// exposure.mode = physical: the frame is exposed by the camera's EV100 (f/16, 1/100 s, ISO 100: 14.64), so
// 1000 cd/m^2 comes out at 1000 / (1.2 * 2^14.64); halving the exposure time halves it; without a camera
// the frame stays manual.
TEST_F(GlTest, PhysicalExposureUsesTheCamerasEv100) {
    const Texture color = makeTexture(ImageF(16, 16, 1000.0f), "color");
    const auto exposed = [&](float exposureTime, bool withCamera) {
        Camera camera;
        camera.projection = perspectiveProjection(camera.verticalFov, 1.0f, 0.1f, 1000.0f);
        camera.prevViewProjection = camera.projection;
        camera.lens.fNumber = 16.0f;
        camera.lens.exposureTimeS = exposureTime;
        camera.lens.iso = 100.0f;
        Settings s = measuring(false);
        s.aa.mode = AntiAliasing::None;
        s.exposure.mode = ExposureMode::Physical;
        Pipeline pipeline({.settings = s});
        pipeline.execute({.color = &color, .camera = withCamera ? &camera : nullptr}, {.dt = kDt});
        return double(readTextureF(pipeline.sceneReferred()).at(8, 8)[1]);
    };
    const double expected = 1000.0 / (1.2 * std::exp2(std::log2(256.0 / 0.01)));
    EXPECT_NEAR(exposed(0.01f, true), expected, 1e-3 * expected);
    EXPECT_NEAR(exposed(0.005f, true) / exposed(0.01f, true), 0.5, 1e-3);
    EXPECT_NEAR(exposed(0.01f, false), 1000.0, 1.0); // manual: exposure 1
}

} // namespace photopic::test

namespace photopic::test {

// NaN, infinite, zero and negative depths and non-finite colour give finite output (such depths are in
// focus, the sky's +inf takes the far limit).
TEST_F(GlTest, DofOutputStaysFiniteWithBrokenInputs) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Layers layers(48, 32);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 48; ++x) {
            const int k = (x + 7 * y) % 6;
            const float z = k == 0   ? nan
                            : k == 1 ? inf
                            : k == 2 ? 0.0f
                            : k == 3 ? -3.0f
                            : k == 4 ? 5.0f
                                     : 100.0f;
            const float c = (x * y) % 5 == 0 ? nan : (x * y) % 7 == 0 ? inf : 2.0f;
            layers.set(x, y, c, 1.0f, 0.5f, z);
        }
    }
    for (DofMode mode : {DofMode::Physical, DofMode::Artistic}) {
        Settings s = artistic(8.0f);
        s.dof.mode = mode;
        const ImageF out = runLayers(layers, s);
        for (float v : out.rgba) {
            ASSERT_TRUE(std::isfinite(v));
        }
    }
}

} // namespace photopic::test
