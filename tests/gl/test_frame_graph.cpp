// The frame architecture on the GPU: optional 3D inputs and the passes that need them, input validation,
// pooled transients (no GL object created in steady state), jitter, depth linearisation and camera motion.

#include "GlTest.h"

#include "core/settings/SettingsJson.h"
#include "gl/TextureIo.h"
#include "passes/HistoryTexture.h"
#include "pipeline/Pipeline.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 32;
constexpr int kH = 18;

ImageF grey(int w, int h, float value) {
    ImageF image(w, h, value);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 1;
    }
    return image;
}

/// A single-channel float texture (R32F) holding `values` (rows top to bottom).
Texture r32f(int w, int h, const std::vector<float>& values, GLenum format = GL_R32F) {
    Texture t({.extent = {w, h}, .format = format, .minFilter = GL_NEAREST, .magFilter = GL_NEAREST});
    std::vector<float> flipped(values.size());
    for (int y = 0; y < h; ++y) {
        std::copy_n(values.begin() + std::ptrdiff_t(y) * w, w,
                    flipped.begin() + std::ptrdiff_t(h - 1 - y) * w);
    }
    const GLenum pixelFormat = format == GL_DEPTH_COMPONENT32F ? GL_DEPTH_COMPONENT : GL_RED;
    glTextureSubImage2D(t.id(), 0, 0, 0, w, h, pixelFormat, GL_FLOAT, flipped.data());
    return t;
}

Camera testCamera() {
    Camera c;
    c.nearPlane = 0.1f;
    c.farPlane = 100.0f;
    c.verticalFov = 1.0f;
    c.projection = perspectiveProjection(c.verticalFov, float(kW) / float(kH), c.nearPlane, c.farPlane);
    c.view = glm::lookAt(glm::vec3(0, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    c.prevViewProjection = c.projection * c.view;
    return c;
}

Settings plain(DebugView view = DebugView::None) {
    Settings s;
    s.output.dither = false;
    s.debug.view = view;
    return s;
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

const SkippedPass* findSkipped(const PipelineStatus& status, std::string_view pass) {
    for (const SkippedPass& s : status.skipped) {
        if (s.pass == pass) {
            return &s;
        }
    }
    return nullptr;
}

} // namespace

TEST_F(GlTest, TwoDFramesRunNoThreeDPassAndSkipNothing) {
    Pipeline pipeline({.settings = plain()});
    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    pipeline.execute({.color = &color}, {});
    const PipelineStatus st = pipeline.status();
    EXPECT_TRUE(st.skipped.empty());
    EXPECT_TRUE(st.inputErrors.empty());
    EXPECT_TRUE(contains(st.ran, "composite + grade + tonemap"));
    EXPECT_FALSE(contains(st.ran, "linear depth"));
    EXPECT_FALSE(contains(st.ran, "camera motion"));
    EXPECT_FALSE(contains(st.ran, "debug view"));
}

TEST_F(GlTest, TheSanitizePassRunsOnlyWhenAPassReadsTheRawScene) {
    // Metering, bloom and tone mapping sanitise what they read: the default chain reads the host's colour.
    ImageF image = grey(kW, kH, 0.2f);
    image.at(3, 3)[0] = std::numeric_limits<float>::quiet_NaN();
    image.at(10, 4)[1] = std::numeric_limits<float>::infinity();
    image.at(20, 6)[2] = -5.0f;
    image.at(30, 8)[0] = 1e30f;
    for (int x = 24; x < 28; ++x) { // finite values whose plain sum in a bloom box overflows
        for (int y = 10; y < 14; ++y) {
            image.at(x, y)[1] = 3e38f;
        }
    }
    const Texture color = makeTexture(image, "color");
    Settings s; // bloom on, as `photopic image` runs
    s.autoExposure.enabled = true;
    Pipeline pipeline({.settings = s});
    pipeline.execute({.color = &color}, {});
    EXPECT_FALSE(contains(pipeline.status().ran, "sanitize"));
    EXPECT_TRUE(contains(pipeline.status().ran, "bloom"));
    const ImageF scene = readTextureF(pipeline.sceneReferred());
    for (std::size_t i = 0; i < scene.rgba.size(); ++i) {
        ASSERT_TRUE(std::isfinite(scene.rgba[i]) && scene.rgba[i] >= 0.0f && scene.rgba[i] < 65504.0f) << i;
    }
    EXPECT_TRUE(std::isfinite(pipeline.telemetry().appliedLog2));

    // Lens flare reads the scene without sanitising it: the frame makes the clean copy first.
    s.lensFlare.enabled = true;
    pipeline.setSettings(s);
    pipeline.execute({.color = &color}, {});
    EXPECT_TRUE(contains(pipeline.status().ran, "sanitize"));
}

TEST_F(GlTest, DepthWithoutAConsumerIsNotLinearised) {
    Pipeline pipeline({.settings = plain()});
    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    const Texture depth = r32f(kW, kH, std::vector<float>(kW * kH, 5.0f));
    const Camera camera = testCamera();
    pipeline.execute(
        {.color = &color, .depth = &depth, .depthKind = DepthKind::LinearView, .camera = &camera}, {});
    const PipelineStatus st = pipeline.status();
    EXPECT_TRUE(st.skipped.empty());
    EXPECT_FALSE(contains(st.ran, "linear depth")); // nothing read it this frame
}

TEST_F(GlTest, AMissingInputSkipsExactlyThePassesThatNeedItAndReportsThem) {
    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    Pipeline reference({.settings = plain()});
    const Image8 normal = readTexture8(reference.execute({.color = &color}, {}));

    // The depth view without depth: the debug view is skipped (its input is missing), the normal image shows.
    Pipeline pipeline({.settings = plain(DebugView::Depth)});
    const Image8 shown = readTexture8(pipeline.execute({.color = &color}, {}));
    EXPECT_EQ(shown.rgba, normal.rgba);
    PipelineStatus st = pipeline.status();
    ASSERT_EQ(st.skipped.size(), 1u);
    EXPECT_EQ(st.skipped[0].pass, "debug view");
    EXPECT_EQ(st.skipped[0].missing, (std::vector<std::string>{"camera", "linearDepth"}));

    // Depth but no camera: linear depth cannot be made, so both it and the view are reported.
    const Texture depth = r32f(kW, kH, std::vector<float>(kW * kH, 5.0f));
    pipeline.execute({.color = &color, .depth = &depth, .depthKind = DepthKind::LinearView}, {});
    st = pipeline.status();
    ASSERT_NE(findSkipped(st, "linear depth"), nullptr);
    EXPECT_EQ(findSkipped(st, "linear depth")->missing, (std::vector<std::string>{"camera"}));
    EXPECT_NE(findSkipped(st, "debug view"), nullptr);
    EXPECT_NE(findSkipped(st, "camera motion"), nullptr);

    // With the camera everything runs.
    const Camera camera = testCamera();
    pipeline.execute(
        {.color = &color, .depth = &depth, .depthKind = DepthKind::LinearView, .camera = &camera}, {});
    st = pipeline.status();
    EXPECT_TRUE(st.skipped.empty());
    EXPECT_TRUE(contains(st.ran, "linear depth"));
    EXPECT_TRUE(contains(st.ran, "debug view"));
    EXPECT_FALSE(contains(st.ran, "composite + grade + tonemap")); // the view replaces the image
}

namespace {

struct EffectCase {
    const char* name;
    Settings settings;
    bool lighting = false; ///< the host runs the lighting stage
};

/// The default chain and each effect that reads 3D inputs, alone.
std::vector<EffectCase> effectCases() {
    std::vector<EffectCase> cases{{"default", plain()}};
    const auto add = [&](const char* name, const std::function<void(Settings&)>& change,
                         bool lighting = false) {
        Settings s = plain();
        change(s);
        cases.push_back({name, s, lighting});
    };
    add("ssao", [](Settings& s) {
        s.gtao.enabled = true;
        s.gtao.apply = GtaoApply::Multiply;
    });
    add("taa", [](Settings& s) { s.aa.mode = AntiAliasing::Taa; });
    add("dof", [](Settings& s) { s.dof.enabled = true; });
    add("motion blur", [](Settings& s) { s.motionBlur.enabled = true; });
    add("ssr", [](Settings& s) { s.ssr.enabled = true; });
    add("outline", [](Settings& s) { s.outline.enabled = true; });
    add("volumetric light", [](Settings& s) { s.volumetricLight.enabled = true; });
    add("depth view", [](Settings& s) { s.debug.view = DebugView::Depth; });
    add("normals view", [](Settings& s) { s.debug.view = DebugView::Normals; });
    add(
        "lighting stage", // SSAO and contact shadows for a host that shades with them
        [](Settings& s) {
            s.gtao.enabled = true;
            s.gtao.apply = GtaoApply::Lighting;
            s.contactShadows.enabled = true;
        },
        true);
    return cases;
}

} // namespace

// plannedReads(): before a frame is made, what its passes will read, for every combination of the optional
// inputs a host gives (present or not), on both colour paths: the same as resourcesRead() after the frame.
TEST_F(GlTest, PlannedReadsAreWhatTheFrameReads) {
    const Texture color = makeTexture(grey(kW, kH, 0.5f), "color");
    const Texture depth = r32f(kW, kH, std::vector<float>(kW * kH, 3.0f));
    const Texture normals = makeTexture(grey(kW, kH, 0.5f), "normals", GL_RGBA16F);
    const Texture motion = makeTexture(grey(kW, kH, 0.0f), "motion", GL_RG16F);
    const Camera camera = testCamera();
    constexpr Resource kOptional[] = {Resource::Depth, Resource::Normals, Resource::Motion, Resource::Camera,
                                      Resource::SunDirection};
    std::vector<EffectCase> cases = effectCases();
    EffectCase ldr = cases[2]; // taa, which the LDR path does not run
    ldr.name = "taa, LDR path";
    cases.push_back(ldr);
    for (const EffectCase& c : cases) {
        Pipeline pipeline({.settings = c.settings, .forceLdr = c.name == std::string_view("taa, LDR path")});
        for (unsigned mask = 0; mask < 1u << std::size(kOptional); ++mask) {
            std::bitset<kResourceCount> present;
            for (std::size_t i = 0; i < std::size(kOptional); ++i) {
                present.set(std::size_t(kOptional[i]), (mask >> i & 1u) != 0);
            }
            const auto has = [&](Resource r) { return present.test(std::size_t(r)); };
            FrameInputs in{.color = &color, .depthKind = DepthKind::LinearView};
            in.depth = has(Resource::Depth) ? &depth : nullptr;
            in.normals = has(Resource::Normals) ? &normals : nullptr;
            in.motion = has(Resource::Motion) ? &motion : nullptr;
            in.camera = has(Resource::Camera) ? &camera : nullptr;
            if (has(Resource::SunDirection)) {
                in.sunDirection = glm::vec3(0.3f, 1.0f, 0.2f);
            }
            const std::bitset<kResourceCount> planned = pipeline.plannedReads(present, c.lighting);
            const FrameTime time{.frameIndex = mask};
            if (c.lighting) {
                (void)pipeline.renderLighting(in, time);
            }
            (void)pipeline.execute(in, time);
            EXPECT_EQ(planned, pipeline.resourcesRead()) << c.name << ", inputs " << present;
        }
    }
}

// resourcesRead(): what the passes a frame needed read. The default chain reads none of the 3D layers; a
// host that gives, from the first frame on, only what plannedReads() says its passes read (as the CLI
// decodes only those layers) shows the same images, frame after frame, for each effect that reads some.
TEST_F(GlTest, InputsTheFrameDidNotReadCanBeLeftOut) {
    ImageF checker = grey(kW, kH, 0.05f); // detail for the effects to move, blur and reflect
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if ((x / 3 + y / 3) % 2 == 0)
                std::fill_n(checker.at(x, y), 3, 4.0f);
        }
    }
    const Texture color = makeTexture(checker, "color");
    std::vector<float> distance(kW * kH);
    for (std::size_t i = 0; i < distance.size(); ++i)
        distance[i] = 2.0f + float(i % 7);
    const Texture depth = r32f(kW, kH, distance);
    ImageF facing(kW, kH);
    ImageF moving(kW, kH);
    for (std::size_t i = 0; i < facing.pixelCount(); ++i) { // creases every few columns, a slow drift
        const float angle = 0.6f * float((i % kW) / 4 % 3) - 0.6f;
        facing.rgba[i * 4] = std::sin(angle);
        facing.rgba[i * 4 + 2] = std::cos(angle);
        moving.rgba[i * 4] = 0.01f;
    }
    const Texture normals = makeTexture(facing, "normals", GL_RGBA16F);
    const Texture motion = makeTexture(moving, "motion", GL_RG16F);
    const Camera camera = testCamera();
    const FrameInputs all{.color = &color,
                          .depth = &depth,
                          .depthKind = DepthKind::LinearView,
                          .normals = &normals,
                          .motion = &motion,
                          .camera = &camera};
    const auto layer = [](const std::bitset<kResourceCount>& read, Resource r) {
        return read[std::size_t(r)];
    };
    std::bitset<kResourceCount> present;
    for (const Resource r : {Resource::Depth, Resource::Normals, Resource::Motion, Resource::Camera}) {
        present.set(std::size_t(r));
    }
    for (const EffectCase& c : effectCases()) {
        if (c.lighting) {
            continue; // the lighting stage's outputs are the host's to use
        }
        Pipeline full({.settings = c.settings});
        Pipeline lean({.settings = c.settings});
        const std::bitset<kResourceCount> read = lean.plannedReads(present);
        EXPECT_TRUE(layer(read, Resource::SceneColor)) << c.name;
        if (c.name == std::string_view("default")) {
            EXPECT_FALSE(layer(read, Resource::Depth) || layer(read, Resource::Normals) ||
                         layer(read, Resource::Motion));
        } else {
            EXPECT_TRUE(layer(read, Resource::Depth) || layer(read, Resource::Normals) ||
                        layer(read, Resource::Motion))
                << c.name << " reads no 3D layer";
        }
        FrameInputs used = all;
        used.depth = layer(read, Resource::Depth) ? &depth : nullptr;
        used.normals = layer(read, Resource::Normals) ? &normals : nullptr;
        used.motion = layer(read, Resource::Motion) ? &motion : nullptr;
        for (std::uint64_t frame = 0; frame <= 3; ++frame) {
            const Image8 expected = readTexture8(full.execute(all, {.frameIndex = frame}));
            const Image8 actual = readTexture8(lean.execute(used, {.frameIndex = frame}));
            EXPECT_TRUE(actual.rgba == expected.rgba) << c.name << ", frame " << frame;
            EXPECT_EQ(lean.status().skipped.size(), full.status().skipped.size()) << c.name;
        }
    }
}

TEST_F(GlTest, BadInputsAreReportedNotFatal) {
    Pipeline pipeline({.settings = plain()});
    const Texture& none = pipeline.execute({.color = nullptr}, {});
    EXPECT_EQ(none.extent(), (Extent{1, 1}));
    ASSERT_EQ(pipeline.status().inputErrors.size(), 1u);
    EXPECT_NE(pipeline.status().inputErrors[0].find("color"), std::string::npos);

    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    const Texture smallDepth = r32f(8, 8, std::vector<float>(64, 1.0f));
    const Texture wrongFormat({.extent = {kW, kH}, .format = GL_RGBA8});
    const Texture twoChannelNormals({.extent = {kW, kH}, .format = GL_RG16_SNORM});
    Camera broken = testCamera();
    broken.view[3][0] = std::numeric_limits<float>::quiet_NaN();
    const Texture& out = pipeline.execute({.color = &color,
                                           .depth = &smallDepth,
                                           .depthKind = DepthKind::LinearView,
                                           .normals = &twoChannelNormals,
                                           .motion = &wrongFormat,
                                           .camera = &broken},
                                          {});
    EXPECT_EQ(out.extent(), (Extent{kW, kH}));
    const std::vector<std::string>& errors = pipeline.status().inputErrors;
    ASSERT_EQ(errors.size(), 4u);
    EXPECT_NE(errors[0].find("depth: 8x8 does not match"), std::string::npos) << errors[0];
    // Each format by its name, the ones the input takes listed.
    EXPECT_NE(errors[1].find("normals: format RG16_SNORM is not one the pipeline reads (RGB16F, RGBA16F, "
                             "RGB32F, RGBA32F, RGB10_A2, RGBA16_SNORM, RGBA8_SNORM)"),
              std::string::npos)
        << errors[1];
    EXPECT_NE(errors[2].find("motion: format RGBA8 is not one the pipeline reads (RG16F, RG32F, RGBA16F, "
                             "RGBA32F)"),
              std::string::npos)
        << errors[2];
    EXPECT_NE(errors[3].find("camera.view"), std::string::npos) << errors[3];
}

// Every format a message can name has its name, and one the library does not know reads as its number.
TEST(Formats, NamesBytesAndImageQualifiersComeFromOneTable) {
    EXPECT_EQ(formatName(GL_RG8), "RG8");
    EXPECT_EQ(formatName(GL_RG16_SNORM), "RG16_SNORM");
    EXPECT_EQ(formatName(GL_DEPTH_COMPONENT32), "DEPTH_COMPONENT32");
    EXPECT_EQ(formatName(GL_RGBA32UI), "RGBA32UI");
    EXPECT_EQ(formatName(GL_RGB9_E5), "format 0x8C3D");
    EXPECT_EQ(bytesPerTexel(GL_RGBA16UI), 8);
    EXPECT_EQ(bytesPerTexel(GL_RGB32F), 12);
    EXPECT_EQ(bytesPerTexel(GL_R8_SNORM), 1);
    EXPECT_EQ(imageFormatQualifier(GL_RGB10_A2), "rgb10_a2");
    EXPECT_EQ(imageFormatQualifier(GL_RGB16F), "");
    EXPECT_EQ(imageFormatFromQualifier("rg16_snorm"), GLenum(GL_RG16_SNORM));
    EXPECT_EQ(imageFormatFromQualifier(""), 0u);
    EXPECT_EQ(imageFormatFromQualifier("rgb16f"), 0u);
}

TEST_F(GlTest, SettingsOutOfRangeAreRejectedWhenSet) {
    Pipeline pipeline({.settings = plain()});
    Settings bad = plain();
    bad.bloom.intensity = std::numeric_limits<float>::quiet_NaN();
    bad.autoExposure.tauDarken = -1.0f;
    try {
        pipeline.setSettings(bad);
        FAIL() << "setSettings accepted out-of-range values";
    } catch (const SettingsError& e) {
        EXPECT_EQ(e.issues().size(), 2u) << e.what();
    }
    EXPECT_FALSE(std::isnan(pipeline.settings().bloom.intensity)); // the old settings stay
}

TEST_F(GlTest, SteadyStateFramesCreateNoTextureOrBuffer) {
    Settings s = plain(DebugView::Histogram);
    s.autoExposure.enabled = true;
    s.autoExposure.metering = MeteringMode::Histogram;
    s.fxaa.enabled = true;
    s.lensFlare.enabled = true;
    s.grain.enabled = true;
    s.vignette.enabled = true;
    Pipeline pipeline({.settings = s});
    const Texture color = makeTexture(grey(64, 36, 0.5f), "color");
    const Texture depth = r32f(64, 36, std::vector<float>(64 * 36, 3.0f));
    Camera camera = testCamera();
    const FrameInputs inputs{
        .color = &color, .depth = &depth, .depthKind = DepthKind::LinearView, .camera = &camera};
    pipeline.execute(inputs, {.dt = 1.0f / 30, .frameIndex = 0});
    pipeline.execute(inputs, {.dt = 1.0f / 30, .frameIndex = 1});
    const GlObjectCounts before = glObjectCounts();
    for (std::uint64_t f = 2; f < 102; ++f) {
        pipeline.execute(inputs, {.dt = 1.0f / 30, .frameIndex = f});
        (void)pipeline.telemetry();
    }
    EXPECT_EQ(glObjectCounts(), before) << "textures " << glObjectCounts().textures - before.textures
                                        << ", buffers " << glObjectCounts().buffers - before.buffers;
    // A 3D debug view on the same pipeline: its first frame may create the pooled targets it needs, the
    // frames after it none.
    s.debug.view = DebugView::Motion;
    pipeline.setSettings(s);
    pipeline.execute(inputs, {.dt = 1.0f / 30, .frameIndex = 102});
    const GlObjectCounts withView = glObjectCounts();
    for (std::uint64_t f = 103; f < 120; ++f) {
        pipeline.execute(inputs, {.dt = 1.0f / 30, .frameIndex = f});
    }
    EXPECT_EQ(glObjectCounts(), withView);
}

TEST_F(GlTest, BeginFrameReturnsHaltonJitterWhenJitterIsOn) {
    Settings s = plain();
    Pipeline pipeline({.settings = s});
    EXPECT_EQ(pipeline.beginFrame({.frameIndex = 3}), glm::vec2(0.0f)); // auto, and no temporal pass

    s.temporal.jitter = JitterMode::On;
    s.temporal.jitterCycle = 8;
    pipeline.setSettings(s);
    const float expectedX[8] = {0.5f, 0.25f, 0.75f, 0.125f, 0.625f, 0.375f, 0.875f, 0.0625f};
    const float expectedY[8] = {1.f / 3, 2.f / 3, 1.f / 9, 4.f / 9, 7.f / 9, 2.f / 9, 5.f / 9, 8.f / 9};
    for (std::uint64_t f = 0; f < 16; ++f) {
        const glm::vec2 j = pipeline.beginFrame({.frameIndex = f});
        EXPECT_FLOAT_EQ(j.x, expectedX[f % 8] - 0.5f) << f;
        EXPECT_FLOAT_EQ(j.y, expectedY[f % 8] - 0.5f) << f;
        EXPECT_EQ(pipeline.jitter(), j);
    }
}

TEST_F(GlTest, EveryDepthKindLinearisesToTheSameDistance) {
    const Camera camera = testCamera();
    std::vector<float> linear(kW * kH);
    for (int i = 0; i < kW * kH; ++i) {
        linear[std::size_t(i)] = 0.5f + 0.25f * float(i % 37); // 0.5 .. 9.5
    }
    std::vector<float> standard(linear.size()), reversed(linear.size());
    for (std::size_t i = 0; i < linear.size(); ++i) {
        standard[i] = windowDepthFromLinear(linear[i], camera.nearPlane, camera.farPlane);
        const float n = camera.nearPlane, f = camera.farPlane, z = linear[i];
        reversed[i] = n * (f - z) / (z * (f - n));
    }
    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    struct Case {
        DepthKind kind;
        Texture depth;
        float tolerance; // relative: float32 window depth resolves ~1e-4 of distance at 10 units
    };
    Case cases[] = {{DepthKind::LinearView, r32f(kW, kH, linear), 1e-6f},
                    {DepthKind::Standard, r32f(kW, kH, standard, GL_DEPTH_COMPONENT32F), 2e-3f},
                    {DepthKind::Reversed, r32f(kW, kH, reversed, GL_DEPTH_COMPONENT32F), 1e-5f}};
    for (Case& c : cases) {
        Settings s = plain(DebugView::Depth);
        Pipeline pipeline({.settings = s});
        pipeline.execute({.color = &color, .depth = &c.depth, .depthKind = c.kind, .camera = &camera}, {});
        ASSERT_TRUE(pipeline.status().skipped.empty());
        // The depth view draws log(z/near)/log(far/near); read the linear depth itself through the view's
        // source: every kind must give the same picture.
        const Image8 view = readTexture8(pipeline.execute(
            {.color = &color, .depth = &c.depth, .depthKind = c.kind, .camera = &camera}, {}));
        for (int i = 0; i < kW * kH; i += 7) {
            const float z = linear[std::size_t(i)];
            const float expected = 255.0f * (1.0f - std::log(z / camera.nearPlane) /
                                                        std::log(camera.farPlane / camera.nearPlane));
            const int x = i % kW, y = i / kW;
            EXPECT_NEAR(float(view.at(x, y)[0]), expected, 1.01f) << int(c.kind) << " at " << x << "," << y;
        }
    }
}

TEST_F(GlTest, CameraMotionFromDepthMatchesTheProjectedDisplacement) {
    // A wall 4 units ahead; the camera moved 0.1 units right since the last frame, so the wall moves left
    // on screen by 0.1 / 4 of the half-width per unit of tan(half fov) * aspect.
    Camera camera = testCamera();
    const glm::mat4 prevView =
        glm::lookAt(glm::vec3(-0.1f, 0, 0), glm::vec3(-0.1f, 0, -1), glm::vec3(0, 1, 0));
    camera.prevViewProjection = camera.projection * prevView;
    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    const Texture depth = r32f(kW, kH, std::vector<float>(kW * kH, 4.0f));
    Pipeline pipeline({.settings = plain(DebugView::Motion)});
    const FrameInputs inputs{
        .color = &color, .depth = &depth, .depthKind = DepthKind::LinearView, .camera = &camera};
    pipeline.execute(inputs, {});
    EXPECT_TRUE(contains(pipeline.status().ran, "camera motion"));

    // The reconstructed motion, read from the blackboard's texture through a second, plain pipeline would
    // hide it; compute the expectation and compare with a direct read of the pass's output instead.
    const float aspect = float(kW) / float(kH);
    const float halfWidth = 4.0f * std::tan(0.5f * camera.verticalFov) * aspect; // at the wall
    const float expectedU = -0.1f / (2.0f * halfWidth);                          // UV, current - previous
    // The view shows hue for direction: motion to the left (negative u) is hue 0.5 (cyan), brightness
    // length / 8 px.
    const Image8 view = readTexture8(pipeline.execute(inputs, {}));
    const float pixels = std::abs(expectedU) * kW;
    const float value = std::min(pixels / 8.0f, 1.0f) * 255.0f;
    const std::uint8_t* centre = view.at(kW / 2, kH / 2);
    EXPECT_NEAR(float(centre[0]), 0.0f, 1.5f);  // cyan: no red
    EXPECT_NEAR(float(centre[1]), value, 1.5f); // green and blue at the value
    EXPECT_NEAR(float(centre[2]), value, 1.5f);
}

TEST_F(GlTest, ACutZeroesCameraMotion) {
    Camera camera = testCamera();
    camera.prevViewProjection =
        camera.projection * glm::lookAt(glm::vec3(-1, 0, 0), glm::vec3(-1, 0, -1), glm::vec3(0, 1, 0));
    camera.cut = true;
    const Texture color = makeTexture(grey(kW, kH, 0.2f), "color");
    const Texture depth = r32f(kW, kH, std::vector<float>(kW * kH, 4.0f));
    Pipeline pipeline({.settings = plain(DebugView::Motion)});
    pipeline.beginFrame({}, &camera);
    const Image8 view = readTexture8(pipeline.execute(
        {.color = &color, .depth = &depth, .depthKind = DepthKind::LinearView, .camera = &camera}, {}));
    for (std::size_t i = 0; i < view.rgba.size(); i += 4) {
        ASSERT_EQ(view.rgba[i + 1], 0) << "motion after a cut";
    }
}

} // namespace photopic::test

namespace photopic::test {

TEST_F(GlTest, HistoryTexturePingPongsAndForgetsWhenInvalidated) {
    HistoryTexture history;
    history.ensure({8, 4}, GL_RGBA16F, "test history");
    EXPECT_EQ(history.previous(), nullptr); // nothing to reuse on the first frame
    const GLuint first = history.current().id();
    history.advance();
    ASSERT_NE(history.previous(), nullptr);
    EXPECT_EQ(history.previous()->id(), first);
    EXPECT_NE(history.current().id(), first);
    history.invalidate(); // a cut, a reset
    EXPECT_EQ(history.previous(), nullptr);
    history.advance();
    history.ensure({8, 4}, GL_RGBA16F, "test history"); // same size: kept
    EXPECT_NE(history.previous(), nullptr);
    history.ensure({16, 4}, GL_RGBA16F, "test history"); // resize: remade, nothing to reuse
    EXPECT_EQ(history.previous(), nullptr);
    EXPECT_EQ(history.current().extent(), (Extent{16, 4}));
}

} // namespace photopic::test
