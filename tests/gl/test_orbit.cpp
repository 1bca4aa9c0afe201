// The orbit scene: its renderer's colour spaces, the image-based light's global intensity (proportional,
// no drift, the starfield untouched), HDR values past 1 before tone mapping and the false-colour bands,
// tone mapping exactly once, the calibration controls (amb, hemi, exp), anti-aliasing modes without a
// degradation, motion vectors with the ship's own motion, and warning-free shaders.

#include "GlTest.h"
#include "OrbitQuad.h"

#include "core/Color.h"
#include "core/Log.h"
#include "core/ToneCurves.h"
#include "gl/Debug.h"
#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "scenes/SceneSettings.h"
#include "scenes/orbit/OrbitIbl.h"
#include "scenes/orbit/OrbitRenderer.h"
#include "scenes/orbit/OrbitScene.h"
#include "scenes/orbit/OrbitShadowMap.h"
#include "scenes/orbit/OrbitShip.h"
#include "scenes/orbit/OrbitWorld.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 90;
constexpr float kDt = 1.0f / 30.0f;

bool isShip(std::uint32_t id) {
    return id >= orbit::ids::kFirstShip && id < orbit::ids::kEarth;
}

/// An orbit scene at a still script time with the given --set assignments.
std::unique_ptr<OrbitScene> makeScene(float start, std::initializer_list<const char*> overrides) {
    auto scene = std::make_unique<OrbitScene>();
    // A small environment cube keeps each scene's image-based-light build short; the light is the same kind.
    std::vector<std::string> all = {"start=" + std::to_string(start), "speed=0", "iblSize=32"};
    all.insert(all.end(), overrides.begin(), overrides.end());
    applySceneOverrides(*scene, all);
    scene->resize({kWidth, kHeight});
    return scene;
}

struct Frame {
    ImageF color;                   ///< the scene's HDR colour (the pipeline's input)
    std::vector<std::uint32_t> ids; ///< top to bottom
    Image8 display;
};

Frame renderFrame(OrbitScene& scene, Pipeline& pipeline, std::uint64_t index = 0) {
    std::vector<double> telemetry;
    const FrameTime time{.dt = kDt, .frameIndex = index};
    const FrameInputs in = scene.render(time, pipeline, telemetry);
    Frame f{readTextureF(*in.color), readTextureU32(*in.objectId, 1), {}};
    f.display = readTexture8(pipeline.execute(in, time));
    return f;
}

Frame renderFrame(OrbitScene& scene, std::uint64_t index = 0, Settings* settings = nullptr) {
    Settings s = settings != nullptr ? *settings : scene.defaultSettings();
    Pipeline pipeline({.settings = s});
    return renderFrame(scene, pipeline, index);
}

/// A script time at which the sun's disc is on screen, clear of the ship, and not eclipsed.
float timeWithSunInView() {
    for (float t = 0.0f; t <= 12.0f; t += 0.25f) {
        const Camera c = orbit::orbitCamera(t, t, 14.0f, kWidth, kHeight);
        const glm::vec3 sun = orbit::sunDirectionAt(t);
        const glm::vec4 clip = c.viewProjection() * glm::vec4(sun, 0.0f);
        if (clip.w <= 0.0f || orbit::sunVisibility(orbit::kEarth, glm::vec3(0.0f), sun) < 1.0f) {
            continue;
        }
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        if (std::abs(ndc.x) < 0.8f && std::abs(ndc.y) < 0.8f && glm::length(ndc) > 0.5f) {
            return t;
        }
    }
    return -1.0f;
}

} // namespace

// The driver compiles a graphics program for each draw state it meets (NVIDIA says so: gl/Debug.h). The
// first frames meet every state of the scene's draws (shadow map, meshes, background); frames after them
// repeat those states and must compile nothing.
TEST_F(GlTest, OrbitFramesAfterTheFirstCompileNoProgramForTheirDrawState) {
    auto scene = makeScene(2.0f, {});
    Pipeline pipeline({.settings = scene->defaultSettings()});
    renderFrame(*scene, pipeline, 0);
    renderFrame(*scene, pipeline, 1);
    const std::uint64_t warmUp = glDebugRecompileCount();
    for (std::uint64_t frame = 2; frame < 5; ++frame)
        renderFrame(*scene, pipeline, frame);
    EXPECT_EQ(glDebugRecompileCount(), warmUp) << "programs compiled again for states the frames repeat";
}

TEST_F(GlTest, OrbitColourTexturesDecodeSrgbAndDataTexturesStayLinear) {
    // One quad, both textures made from the same grey image (code value 128): the emissive (colour) use
    // must come out sRGB-decoded, the metal-rough (data) use as stored.
    orbit::Model model;
    orbit::TextureImage image{.name = "grey 128", .width = 4, .height = 4};
    image.rgba.assign(4 * 4 * 4, 128);
    model.images.push_back(image);
    model.textures.push_back({.image = 0, .srgb = true});
    model.textures.push_back({.image = 0, .srgb = false});
    orbit::Material m{.name = "probe",
                      .baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f},
                      .metallicFactor = 0.0f,
                      .roughnessFactor = 1.0f,
                      .emissiveFactor = {1.0f, 1.0f, 1.0f},
                      .doubleSided = true};
    m.emissiveTexture = 0;
    m.metallicRoughnessTexture = 1;
    model.materials.push_back(m);
    model.meshes.push_back(orbitQuad());

    orbit::OrbitRenderer renderer;
    renderer.resize({32, 32});
    renderer.setModel(model, glm::mat4(1.0f));
    const Camera camera = orbitQuadCamera();
    orbit::OrbitRenderer::DrawInfo draw{.camera = &camera};
    draw.lights = {.sun = 0.0f, .ambient = 0.0f, .hemi = 0.0f, .ibl = 0.0f};
    renderer.draw(draw);
    const ImageF colour = readTextureF(renderer.color());
    const ImageF material = readTextureF(renderer.material());
    const float* c = colour.at(16, 16);
    const float* mat = material.at(16, 16);
    EXPECT_NEAR(c[0], srgbDecode(128.0f / 255.0f), 1e-3f) << "a colour texture is decoded from sRGB";
    EXPECT_NEAR(c[1], srgbDecode(128.0f / 255.0f), 1e-3f);
    EXPECT_NEAR(mat[3], 128.0f / 255.0f, 1e-3f) << "a data texture is read as stored (roughness)";
}

TEST_F(GlTest, OrbitIblIntensityIsProportionalAndLeavesTheStarfieldAlone) {
    // Lit by the image-based light alone (sun, amb and hemi off): the hull's light scales with ibl.
    const auto render = [](const char* ibl) {
        auto scene = makeScene(2.0f, {"post=\"raw\"", "sun=0", "amb=0", "hemi=0", ibl});
        return renderFrame(*scene);
    };
    const Frame low = render("ibl=0.5");
    const Frame high = render("ibl=2");
    double sumLow = 0.0;
    double sumHigh = 0.0;
    long hull = 0;
    long background = 0;
    long backgroundDiffer = 0;
    // Every part but the window lights, whose emission is not the IBL's.
    const std::uint32_t lightsId = orbit::ids::kFirstShip + std::uint32_t(orbit::ShipPart::Lights);
    for (std::size_t i = 0; i < low.ids.size(); ++i) {
        const float* a = low.color.rgba.data() + 4 * i;
        const float* b = high.color.rgba.data() + 4 * i;
        if (isShip(low.ids[i]) && low.ids[i] == high.ids[i] && low.ids[i] != lightsId) {
            sumLow += luma709({a[0], a[1], a[2]});
            sumHigh += luma709({b[0], b[1], b[2]});
            ++hull;
        } else if (low.ids[i] == 0 && high.ids[i] == 0) {
            ++background;
            backgroundDiffer += std::memcmp(a, b, 3 * sizeof(float)) != 0 ? 1 : 0;
        }
    }
    ASSERT_GT(hull, 300) << "the ship is in view";
    ASSERT_GT(sumHigh, 0.0);
    const double ratio = sumLow / sumHigh;
    RecordProperty("iblRatio", std::to_string(ratio));
    EXPECT_NEAR(ratio, 0.25, 0.25 * 0.02) << "ibl 0.5 / ibl 2 on a region lit only by the IBL";
    ASSERT_GT(background, 1000);
    EXPECT_EQ(backgroundDiffer, 0) << "the starfield and nebula do not use the IBL";
}

TEST_F(GlTest, OrbitIblIntensitySetBackAndForthDoesNotDrift) {
    auto scene = makeScene(2.0f, {"ibl=1"});
    Pipeline pipeline({.settings = scene->defaultSettings()});
    const Frame first = renderFrame(*scene, pipeline);
    for (int i = 0; i < 1000; ++i) {
        applySceneOverrides(*scene, std::vector<std::string>{"ibl=0.5", "ibl=2", "ibl=1"});
    }
    Pipeline again({.settings = scene->defaultSettings()});
    const Frame later = renderFrame(*scene, again);
    EXPECT_EQ(first.color.rgba, later.color.rgba) << "bit-identical after 3000 changes of ibl";
    for (std::size_t m = 0; m < scene->renderer().meshes().materials().size(); ++m) {
        EXPECT_EQ(scene->renderer().iblBaseline(int(m)), 1.0f) << "material " << m << "'s stored baseline";
    }
}

TEST_F(GlTest, OrbitHasHdrValuesPastEightAndShowsEveryExposureBand) {
    const float t = timeWithSunInView();
    ASSERT_GE(t, 0.0f) << "the script shows the sun somewhere";
    auto scene = makeScene(t, {"post=\"raw\""});
    const Frame f = renderFrame(*scene);
    float shipMax = 0.0f;
    float sunMax = 0.0f;
    long shipOverOne = 0;
    for (std::size_t i = 0; i < f.ids.size(); ++i) {
        const float* p = f.color.rgba.data() + 4 * i;
        const float y = luma709({p[0], p[1], p[2]});
        if (isShip(f.ids[i])) {
            shipMax = std::max(shipMax, y);
            shipOverOne += y >= 1.0f ? 1 : 0;
        } else if (f.ids[i] == 0) {
            sunMax = std::max(sunMax, y);
        }
    }
    RecordProperty("shipMax", std::to_string(shipMax));
    EXPECT_GE(sunMax, 8.0f) << "the sun's disc, before tone mapping";
    EXPECT_GE(shipMax, 2.0f) << "the sun-lit ship's highlights, before tone mapping";
    EXPECT_GT(shipOverOne, 0);

    // The same frame through debug.view = exposure: the false-colour bands of >= 1, >= 2 and >= 8 appear.
    Settings s = scene->defaultSettings();
    s.debug.view = DebugView::Exposure;
    s.output.dither = false;
    const Frame bands = renderFrame(*scene, 0, &s);
    const std::uint8_t colours[4][3] = {{255, 255, 0}, {255, 128, 0}, {255, 0, 255}, {255, 255, 255}};
    int found[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < bands.ids.size(); ++i) {
        const std::uint8_t* p = bands.display.rgba.data() + 4 * i;
        for (int b = 0; b < 4; ++b) {
            found[b] += std::abs(p[0] - colours[b][0]) <= 1 && std::abs(p[1] - colours[b][1]) <= 1 &&
                        std::abs(p[2] - colours[b][2]) <= 1;
        }
    }
    EXPECT_GT(found[0], 0) << ">= 1 band";
    EXPECT_GT(found[1], 0) << ">= 2 band";
    EXPECT_GT(found[3], 0) << ">= 8 band (the sun)";
    RecordProperty("bandPixels", std::to_string(found[0]) + "," + std::to_string(found[1]) + "," +
                                     std::to_string(found[2]) + "," + std::to_string(found[3]));
}

TEST_F(GlTest, OrbitLumaViewIsTheGreyOfTheExposedLuma) {
    auto scene = makeScene(2.0f, {"post=\"raw\""});
    Settings s = scene->defaultSettings();
    s.debug.view = DebugView::Luma;
    s.output.dither = false;
    const Frame f = renderFrame(*scene, 0, &s);
    long coloured = 0;
    long worse = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const std::uint8_t* p = f.display.at(x, y);
            coloured += p[0] != p[1] || p[1] != p[2];
            // Raw calibration exposes at 1: the grey is sRGB(min(luma, 1)), no tone curve.
            const float* in = f.color.at(x, y);
            const float luma = std::clamp(luma709({in[0], in[1], in[2]}), 0.0f, 1.0f);
            worse += std::abs(int(p[0]) - int(std::lround(srgbEncode(luma) * 255.0f))) > 1;
        }
    }
    EXPECT_EQ(coloured, 0) << "pixels that are not grey";
    EXPECT_EQ(worse, 0) << "pixels off sRGB(luma) by more than one code value";
}

TEST_F(GlTest, OrbitToneMapsExactlyOnce) {
    // Raw calibration at exp 1: no bloom, no auto exposure. The display image must be the CPU tone curve
    // applied once to the scene's colour (within one code value, as the 2D chain's test holds).
    auto scene = makeScene(2.0f, {"post=\"raw\""});
    Settings s = scene->defaultSettings();
    s.output.dither = false;
    s.aa.mode = AntiAliasing::None; // SMAA, the scene's default, blends edges after the curve
    const Frame f = renderFrame(*scene, 0, &s);
    long worse = 0;
    long twice = 0;
    long bright = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const float* in = f.color.at(x, y);
            const glm::vec3 c = toneMap(ToneMapper::Neutral, {in[0], in[1], in[2]}, {});
            const std::uint8_t* got = f.display.at(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                const int expected = int(std::lround(srgbEncode(std::clamp(c[ch], 0.0f, 1.0f)) * 255.0f));
                worse += std::abs(int(got[ch]) - expected) > 1 ? 1 : 0;
                const glm::vec3 c2 = toneMap(ToneMapper::Neutral, c, {});
                const int doubled = int(std::lround(srgbEncode(std::clamp(c2[ch], 0.0f, 1.0f)) * 255.0f));
                twice += std::abs(int(got[ch]) - doubled) > 1 ? 1 : 0;
            }
            bright += luma709({in[0], in[1], in[2]}) > 0.2f ? 1 : 0;
        }
    }
    EXPECT_GT(bright, 50) << "the frame has mid tones and highlights";
    EXPECT_GT(twice, 100) << "tone mapping twice would be told apart";
    EXPECT_EQ(worse, 0) << "channels off the single tone curve by more than one code value";
}

TEST_F(GlTest, OrbitCalibrationFillsDarkenShadowsAndExposureBrightens) {
    // In the eclipse the ship is lit by the fills and the IBL only; the seed's calibration line
    // post=raw&exp=0.9&sun=3.8&amb=0&hemi=0 against more fill, and against a higher exp.
    const auto meanShip = [](std::initializer_list<const char*> sets, bool display) {
        auto scene = makeScene(6.0f, sets);
        const Frame f = renderFrame(*scene);
        double sum = 0.0;
        long n = 0;
        for (std::size_t i = 0; i < f.ids.size(); ++i) {
            if (f.ids[i] == orbit::ids::kFirstShip + std::uint32_t(orbit::ShipPart::Hull)) {
                const float* p = f.color.rgba.data() + 4 * i;
                const std::uint8_t* d = f.display.rgba.data() + 4 * i;
                sum += display ? (d[0] + d[1] + d[2]) / 3.0 : double(luma709({p[0], p[1], p[2]}));
                ++n;
            }
        }
        return n > 0 ? sum / double(n) : -1.0;
    };
    const double dark = meanShip({"post=\"raw\"", "exp=0.9", "sun=3.8", "amb=0", "hemi=0"}, true);
    const double filled = meanShip({"post=\"raw\"", "exp=0.9", "sun=3.8", "amb=0.2", "hemi=0.4"}, true);
    const double brighter = meanShip({"post=\"raw\"", "exp=1.8", "sun=3.8", "amb=0", "hemi=0"}, true);
    ASSERT_GE(dark, 0.0) << "the hull is in view";
    RecordProperty("meanHullSrgb", std::to_string(dark) + " / fills " + std::to_string(filled) +
                                       " / exp 1.8 " + std::to_string(brighter));
    EXPECT_GT(filled, dark + 5.0) << "more amb and hemi lift the shadowed hull (sRGB code values)";
    EXPECT_GT(brighter, dark + 5.0) << "a higher exp brightens the image";
    const double sceneDark = meanShip({"post=\"raw\"", "exp=0.9", "sun=3.8", "amb=0", "hemi=0"}, false);
    const double sceneBright = meanShip({"post=\"raw\"", "exp=1.8", "sun=3.8", "amb=0", "hemi=0"}, false);
    EXPECT_EQ(sceneDark, sceneBright) << "exp is the camera's: the scene's light is unchanged";
}

TEST_F(GlTest, OrbitSmaaAndSsaaRunWithoutDegradation) {
    for (const AntiAliasing mode : {AntiAliasing::Smaa, AntiAliasing::Ssaa}) {
        auto scene = makeScene(2.0f, {});
        Settings s = scene->defaultSettings();
        s.aa.mode = mode;
        s.aa.level = 1;
        std::vector<std::string> warnings;
        const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
            if (level >= LogLevel::Warning) {
                warnings.emplace_back(message);
            }
        });
        Pipeline pipeline({.settings = s});
        Frame f;
        for (std::uint64_t i = 0; i < 2; ++i) {
            f = renderFrame(*scene, pipeline, i);
        }
        setLogSink(previous);
        const PipelineStatus status = pipeline.status();
        EXPECT_EQ(status.path, ColorPath::Hdr);
        EXPECT_TRUE(status.skipped.empty()) << "a pass was skipped: " << status.skipped.front().pass;
        EXPECT_TRUE(status.inputErrors.empty());
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        if (mode == AntiAliasing::Smaa) {
            EXPECT_NE(std::find(status.ran.begin(), status.ran.end(), "smaa"), status.ran.end());
        } else {
            EXPECT_EQ(pipeline.subframeCount(), 2) << "the scene renders 2^level sub-frames";
        }
    }
}

TEST_F(GlTest, OrbitShipShadowMapDarkensTheSunOnly) {
    // With the sun on, the ship shadows parts of itself; with only the fills and the IBL, the shadow map
    // changes nothing at all.
    // At 11 s the camera looks across the ship towards the sun: the hull's and arrays' shadows are in view.
    const auto render = [](const char* sun, const char* shadow) {
        auto scene = makeScene(11.0f, {"post=\"raw\"", sun, shadow});
        return renderFrame(*scene);
    };
    const Frame lit = render("sun=3", "shadow.enabled=true");
    const Frame unshadowed = render("sun=3", "shadow.enabled=false");
    long darker = 0;
    long brighter = 0;
    for (std::size_t i = 0; i < lit.ids.size(); ++i) {
        if (!isShip(lit.ids[i])) {
            continue;
        }
        const float* a = lit.color.rgba.data() + 4 * i;
        const float* b = unshadowed.color.rgba.data() + 4 * i;
        const float ya = luma709({a[0], a[1], a[2]});
        const float yb = luma709({b[0], b[1], b[2]});
        darker += ya < 0.8f * yb ? 1 : 0;
        brighter += ya > yb * 1.001f + 1e-4f ? 1 : 0;
    }
    RecordProperty("shadowedShipPixels", std::to_string(darker));
    EXPECT_GT(darker, 20) << "ship pixels the ship's own shadow darkens";
    EXPECT_EQ(brighter, 0) << "a shadow never adds light";
    const Frame fillOnly = render("sun=0", "shadow.enabled=true");
    const Frame fillOnlyOff = render("sun=0", "shadow.enabled=false");
    EXPECT_EQ(fillOnly.color.rgba, fillOnlyOff.color.rgba) << "fills and IBL are not shadowed by the map";
}

// The scene hands its ship shadow map to the pipeline: volumetric light's shadow-map mode marches it (no
// input error, no warning) and adds light, an image other than the screen-space rays'. Without the map
// (shadows off) the same settings give the screen rays' image bit for bit, so the first half can fail.
TEST_F(GlTest, OrbitHandsItsShadowMapToVolumetricLight) {
    struct Run {
        Frame frame;
        PipelineStatus status;
        std::vector<std::string> warnings;
    };
    const auto render = [](const char* shadow, bool volumetric, VolumetricLightMode mode) {
        auto scene = makeScene(11.0f, {"post=\"raw\"", shadow});
        Settings s = scene->defaultSettings();
        s.volumetricLight.enabled = volumetric;
        s.volumetricLight.mode = mode;
        s.volumetricLight.scattering = 0.2f;
        Run run;
        const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
            if (level >= LogLevel::Warning) {
                run.warnings.emplace_back(message);
            }
        });
        Pipeline pipeline({.settings = s});
        run.frame = renderFrame(*scene, pipeline);
        setLogSink(previous);
        run.status = pipeline.status();
        return run;
    };
    const Run off = render("shadow.enabled=true", false, VolumetricLightMode::ShadowMap);
    const Run marched = render("shadow.enabled=true", true, VolumetricLightMode::ShadowMap);
    EXPECT_TRUE(marched.warnings.empty()) << marched.warnings.front();
    EXPECT_TRUE(marched.status.inputErrors.empty());
    EXPECT_NE(std::find(marched.status.ran.begin(), marched.status.ran.end(), "volumetric light"),
              marched.status.ran.end());
    double added = 0.0;
    long brighter = 0;
    for (std::size_t i = 0; i < off.frame.display.rgba.size(); i += 4) {
        const double d = double(marched.frame.display.rgba[i + 1]) - double(off.frame.display.rgba[i + 1]);
        added += d;
        brighter += d > 0.0 ? 1 : 0;
    }
    RecordProperty("pixelsTheMarchBrightens", std::to_string(brighter));
    EXPECT_GT(added, 0.0) << "in-scattering adds light";
    EXPECT_GT(brighter, long(off.frame.ids.size() / 10)) << "along most view rays";
    const Run screen = render("shadow.enabled=true", true, VolumetricLightMode::Screen);
    EXPECT_NE(marched.frame.display.rgba, screen.frame.display.rgba) << "the map was marched";

    const Run noMap = render("shadow.enabled=false", true, VolumetricLightMode::ShadowMap);
    const Run noMapScreen = render("shadow.enabled=false", true, VolumetricLightMode::Screen);
    EXPECT_EQ(noMap.frame.display.rgba, noMapScreen.frame.display.rgba) << "no map: the screen rays";
}

TEST_F(GlTest, OrbitMotionVectorsFollowTheCameraAndTheShipsOwnSpin) {
    // A moving script (speed 1) at frame 10: each ship pixel's motion must equal the reprojection of its
    // surface point through the previous ship transform and camera.
    auto scene = std::make_unique<OrbitScene>();
    applySceneOverrides(*scene, std::vector<std::string>{"speed=20", "iblSize=32"});
    scene->resize({kWidth, kHeight});
    Pipeline pipeline({.settings = scene->defaultSettings()});
    std::vector<double> telemetry;
    const FrameTime time{.dt = kDt, .frameIndex = 10};
    const FrameInputs in = scene->render(time, pipeline, telemetry);
    const ImageF motion = readTextureF(*in.motion);
    const std::vector<float> depth = readDepthTexture(*in.depth);
    const std::vector<std::uint32_t> ids = readTextureU32(*in.objectId, 1);
    const double t = scene->scriptTime(time);
    const double prev = t - 20.0 * double(kDt);
    const glm::mat4 toPrev = orbit::shipTransform(prev) * glm::inverse(orbit::shipTransform(t));
    const Camera& camera = *in.camera;
    const glm::mat4 invViewProj = glm::inverse(camera.viewProjection());
    double worst = 0.0;
    long n = 0;
    double spin = 0.0;
    for (int y = 2; y < kHeight - 2; ++y) {
        for (int x = 2; x < kWidth - 2; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + std::size_t(x);
            bool interior = isShip(ids[i]);
            for (int d = -1; d <= 1 && interior; d += 2) {
                interior = ids[i + std::size_t(d)] == ids[i] && ids[i + std::size_t(d) * kWidth] == ids[i];
            }
            if (!interior) {
                continue;
            }
            // The pixel centre at the unjittered projection (jitter is off without TAA), window depth.
            const glm::vec2 ndc((float(x) + 0.5f) / kWidth * 2.0f - 1.0f,
                                1.0f - (float(y) + 0.5f) / kHeight * 2.0f);
            const float z = depth[i] * 2.0f - 1.0f;
            glm::vec4 world = invViewProj * glm::vec4(ndc, z, 1.0f);
            world /= world.w;
            const glm::vec4 before = camera.prevViewProjection * (toPrev * world);
            const glm::vec2 expected = 0.5f * (ndc - glm::vec2(before) / before.w);
            const glm::vec4 staticBefore = camera.prevViewProjection * world;
            spin = std::max(spin, double(glm::length(glm::vec2(before) / before.w -
                                                     glm::vec2(staticBefore) / staticBefore.w)));
            const float* m = motion.at(x, y);
            worst = std::max(worst, double(glm::length(glm::vec2(m[0], m[1]) - expected)) * kWidth);
            ++n;
        }
    }
    ASSERT_GT(n, 100);
    EXPECT_GT(spin * 0.5 * kWidth, 0.05) << "the ship's spin moves its pixels by a measurable amount";
    EXPECT_LT(worst, 0.05) << "pixels: motion against the reprojection";
}

TEST_F(GlTest, OrbitViewerDragHoldsTheScriptedViewAndOrbitsTheShip) {
    auto scene = makeScene(3.0f, {});
    Pipeline pipeline({.settings = scene->defaultSettings()});
    std::vector<double> telemetry;
    const FrameInputs before = scene->render({.dt = kDt, .frameIndex = 0}, pipeline, telemetry);
    const glm::vec3 scripted = glm::vec3(glm::inverse(before.camera->view)[3]);
    pipeline.execute(before, {.dt = kDt, .frameIndex = 0});
    ASSERT_NE(scene->interactiveCamera(), nullptr);
    scene->interactiveCamera()->orbit(0.5f, 0.0f);
    scene->interactiveCamera()->zoom(0.5f);
    EXPECT_TRUE(scene->settings().fixedCamera);
    EXPECT_NEAR(glm::length(scene->settings().eye), 0.5f * glm::length(scripted), 1e-3f)
        << "zoomed in by half";
    EXPECT_NEAR(scene->settings().eye.y, 0.5f * scripted.y, 1e-3f) << "a turn about +y keeps the height";
    const FrameInputs after = scene->render({.dt = kDt, .frameIndex = 1}, pipeline, telemetry);
    const glm::vec3 eye = glm::vec3(glm::inverse(after.camera->view)[3]);
    EXPECT_LT(glm::length(eye - scene->settings().eye), 1e-3f) << "the next frame is seen from the held eye";
    pipeline.execute(after, {.dt = kDt, .frameIndex = 1});
}

TEST_F(GlTest, OrbitShadersCompileWithoutWarnings) {
    const struct {
        GLenum stage;
        const char* name;
    } shaders[] = {{GL_VERTEX_SHADER, "scenes/orbit/orbit_mesh.vert.glsl"},
                   {GL_FRAGMENT_SHADER, "scenes/orbit/orbit_mesh.frag.glsl"},
                   {GL_FRAGMENT_SHADER, "scenes/orbit/orbit_background.frag.glsl"}};
    for (const auto& s : shaders) {
        const std::string source =
            preprocessShader(s.name, orbit::iblShaderDefines(orbit::ShadowMap::shaderDefines()));
        const GLuint shader = glCreateShader(s.stage);
        const char* text = source.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        GLint length = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        EXPECT_EQ(ok, GL_TRUE) << s.name;
        EXPECT_LE(length, 1) << s.name << ": " << log;
    }
}

} // namespace photopic::test
