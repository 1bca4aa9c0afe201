// The installed interface as a host uses it: include/photopic/photopic.h and libphotopic.so only (this binary
// links nothing else of Photopic), the host's own GL access (libepoxy here), its own textures and
// framebuffers. The output is delivered where the host asks, whatever GL state the host leaves on, and the
// host's state is as it left it afterwards.

#include <photopic/photopic.h>

#include "common/HostGlState.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace photopic::test {
namespace {

constexpr int kW = 48, kH = 32;

std::unique_ptr<HeadlessGlContext> gContext;
std::string gUnavailable;

/// A host's HDR texture: a ramp with a bright light, RGBA16F like a typical scene target.
GlName makeHdrTexture() {
    std::vector<float> pixels(kW * kH * 4);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            float* p = &pixels[(y * kW + x) * 4];
            const float v = 0.02f + 2.0f * float(x) / float(kW);
            const bool light = (x - 30) * (x - 30) + (y - 10) * (y - 10) < 9;
            p[0] = light ? 40.0f : v;
            p[1] = v * float(y) / float(kH);
            p[2] = 0.3f * v;
            p[3] = 1.0f;
        }
    }
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, GL_RGBA16F, kW, kH);
    glTextureSubImage2D(t, 0, 0, 0, kW, kH, GL_RGBA, GL_FLOAT, pixels.data());
    return t;
}

GlName makeTexture(GLenum format, int w = kW, int h = kH) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, format, w, h);
    return t;
}

std::vector<std::uint8_t> readBytes(GlName texture, int w = kW, int h = kH) {
    std::vector<std::uint8_t> out(std::size_t(w) * h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(out.size()), out.data());
    return out;
}

std::vector<float> readFloats(GlName texture) {
    std::vector<float> out(std::size_t(kW) * kH * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
    return out;
}

/// Every frame of these settings is the same: no adaptation, no dither, no temporal effect.
constexpr const char* kSettings = R"({"version": 1, "postEffects": {
    "autoExposure": {"enabled": false}, "output": {"dither": false}, "aa": {"mode": "fxaa"}}})";

class PublicApi : public ::testing::Test {
protected:
    void SetUp() override {
        if (!gContext) {
            GTEST_SKIP() << "no OpenGL 4.5 context: " << gUnavailable;
        }
        while (glGetError() != GL_NO_ERROR) {
        }
        hdr = makeHdrTexture();
    }
    void TearDown() override {
        if (gContext) {
            glDeleteTextures(1, &hdr);
            EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "the test left a GL error";
        }
    }
    [[nodiscard]] Frame frame() const { return {.color = hdr, .dt = 1.0f / 60.0f, .frameIndex = 7}; }

    GlName hdr = 0;
};

/// A framebuffer of the host's with one colour texture.
struct HostTarget {
    GLuint texture = 0, framebuffer = 0;
    HostTarget(GLenum format, int w, int h) {
        texture = makeTexture(format, w, h);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
    }
    ~HostTarget() {
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteTextures(1, &texture);
    }
    HostTarget(const HostTarget&) = delete;
    HostTarget& operator=(const HostTarget&) = delete;
};

TEST_F(PublicApi, ConstructsFromEmptyBracesAndReportsItsVersion) {
    PostProcessor post({});
    EXPECT_STREQ(versionString(), PHOTOPIC_EXPECTED_VERSION);
    EXPECT_NE(post.settingsJson().find("\"postEffects\""), std::string::npos);
    const GlName out = post.execute(frame());
    EXPECT_NE(out, 0u);
    EXPECT_TRUE(post.status().inputErrors.empty());
}

TEST_F(PublicApi, DrawsIntoTheHostsFramebufferWhateverStateTheHostLeavesOn) {
    PostProcessor post({.settingsJson = kSettings});
    const std::vector<std::uint8_t> reference = readBytes(post.execute(frame()));
    const HostTarget target(GL_RGBA8, kW, kH);
    const HostObjects host;
    auto runUnder = [&](const std::vector<const HostState*>& states) {
        SCOPED_TRACE(states.size() == 1 ? states.front()->name : "every host state at once");
        glClearNamedFramebufferfv(target.framebuffer, GL_COLOR, 0, std::array<float, 4>{0, 0, 0, 0}.data());
        host.bind();
        for (const HostState* s : states) {
            s->set();
        }
        post.execute(frame(), FramebufferTarget{.framebuffer = target.framebuffer});
        for (const std::string& problem : host.changedBindings()) {
            ADD_FAILURE() << problem;
        }
        for (const HostState* s : states) {
            EXPECT_TRUE(s->stillSet()) << s->name << " was not restored";
        }
        defaultState();
        EXPECT_EQ(readBytes(target.texture), reference) << "the delivered image differs";
        EXPECT_TRUE(post.status().inputErrors.empty());
    };
    std::vector<const HostState*> all;
    for (const HostState& s : hostStates()) {
        runUnder({&s});
        all.push_back(&s);
    }
    runUnder(all);
}

TEST_F(PublicApi, ScalesIntoAViewportRectangleAndLeavesTheRestAlone) {
    PostProcessor post({.settingsJson = kSettings});
    constexpr int kTargetW = 100, kTargetH = 80;
    const HostTarget target(GL_RGBA8, kTargetW, kTargetH);
    const std::array<float, 4> blue{0, 0, 1, 1};
    glClearNamedFramebufferfv(target.framebuffer, GL_COLOR, 0, blue.data());
    post.execute(
        frame(),
        FramebufferTarget{.framebuffer = target.framebuffer, .x = 10, .y = 20, .width = 60, .height = 40});
    const std::vector<std::uint8_t> out = readBytes(target.texture, kTargetW, kTargetH);
    auto at = [&](int x, int y) { return &out[(std::size_t(y) * kTargetW + x) * 4]; };
    int untouched = 0, written = 0;
    for (int y = 0; y < kTargetH; ++y) {
        for (int x = 0; x < kTargetW; ++x) {
            const bool inside = x >= 10 && x < 70 && y >= 20 && y < 60;
            const bool isBlue = at(x, y)[0] == 0 && at(x, y)[1] == 0 && at(x, y)[2] == 255;
            untouched += !inside && isBlue;
            written += inside && !isBlue;
        }
    }
    EXPECT_EQ(untouched, kTargetW * kTargetH - 60 * 40) << "a pixel outside the rectangle was written";
    EXPECT_EQ(written, 60 * 40) << "a pixel inside the rectangle kept the host's clear colour";
}

TEST_F(PublicApi, WritesDisplayBytesIntoRgba8AndSrgbTexturesAndLinearHdrIntoFloatOnes) {
    PostProcessor post({.settingsJson = kSettings});
    const std::vector<std::uint8_t> display = readBytes(post.execute(frame()));
    for (const GLenum format : {GLenum(GL_RGBA8), GLenum(GL_SRGB8_ALPHA8)}) {
        const GlName target = makeTexture(format);
        post.execute(frame(), TextureTarget{target});
        EXPECT_EQ(readBytes(target), display) << "format 0x" << std::hex << format;
        glDeleteTextures(1, &target);
    }

    const std::vector<float> linear = readFloats(post.execute(frame(), Output::LinearHdr));
    // Linear HDR: exposed scene-referred values, not display values; the light stays far above 1.
    EXPECT_GT(*std::max_element(linear.begin(), linear.end()), 4.0f);
    for (const GLenum format : {GLenum(GL_RGBA32F), GLenum(GL_RGBA16F)}) {
        const GlName target = makeTexture(format);
        post.execute(frame(), TextureTarget{target}, Output::LinearHdr);
        const std::vector<float> got = readFloats(target);
        double worst = 0;
        for (std::size_t i = 0; i < got.size(); ++i) {
            worst = std::max(worst, std::abs(double(got[i]) - linear[i]) / std::max(1.0, double(linear[i])));
        }
        // RGBA16F keeps 11 significant bits: 2^-11 relative.
        EXPECT_LT(worst, format == GL_RGBA32F ? 1e-6 : 1e-3) << "format 0x" << std::hex << format;
        glDeleteTextures(1, &target);
    }
}

TEST_F(PublicApi, BadNamesAreReportedNotFatal) {
    PostProcessor post({.settingsJson = kSettings});
    Frame bad = frame();
    bad.color = 123456;
    EXPECT_NE(post.execute(bad), 0u);
    Status status = post.status();
    ASSERT_FALSE(status.inputErrors.empty());
    EXPECT_NE(status.inputErrors.front().find("color: 123456"), std::string::npos)
        << status.inputErrors.front();

    post.execute(frame(), FramebufferTarget{.framebuffer = 98765});
    status = post.status();
    ASSERT_EQ(status.inputErrors.size(), 1u);
    EXPECT_NE(status.inputErrors.front().find("98765"), std::string::npos) << status.inputErrors.front();

    const GlName depthTarget = makeTexture(GL_DEPTH_COMPONENT32F);
    post.execute(frame(), TextureTarget{depthTarget});
    status = post.status();
    ASSERT_EQ(status.inputErrors.size(), 1u);
    EXPECT_NE(status.inputErrors.front().find("cannot be rendered to"), std::string::npos)
        << status.inputErrors.front();
    glDeleteTextures(1, &depthTarget);
    while (glGetError() != GL_NO_ERROR) { // the library's probes of bad names may raise errors of their own
    }
}

// The sun's shadow map through the public API: a depth texture of its own size with its matrix and
// illuminance is taken (no input error) and, with volumetric light in auto mode, marched (the image differs
// from the screen-space rays', which add nothing with the sun behind the camera); a colour texture in its
// place is refused by name.
/// A camera at the origin looking down -z with a GL perspective projection of kW x kH.
HostCamera perspectiveCamera() {
    HostCamera camera;
    const float f = 1.0f / std::tan(0.5f * camera.verticalFov), n = camera.nearPlane, far = camera.farPlane;
    camera.projection = {
        f * float(kH) / float(kW), 0, 0, 0, 0, f, 0, 0, 0, 0, (far + n) / (n - far), -1, 0, 0,
        2 * far * n / (n - far),   0};
    camera.prevViewProjection = camera.projection;
    return camera;
}

TEST_F(PublicApi, TakesTheSunShadowMap) {
    const GlName depth = makeTexture(GL_R32F);
    const float five = 5.0f;
    glClearTexImage(depth, 0, GL_RED, GL_FLOAT, &five);
    const GlName map = makeTexture(GL_DEPTH_COMPONENT32F, 64, 64);
    const float half = 0.5f;
    glClearTexImage(map, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &half);
    const HostCamera camera = perspectiveCamera();
    Frame withMap = frame();
    withMap.depth = depth;
    withMap.depthEncoding = DepthEncoding::LinearView;
    withMap.camera = &camera;
    withMap.sunDirection = std::array<float, 3>{0.0f, 0.0f, 1.0f};
    withMap.sunShadow = {.depth = map,
                         .worldToClip = {0.1f, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 1},
                         .illuminance = {50.0f, 50.0f, 50.0f}};
    const auto run = [&](const char* mode, const Frame& f) {
        PostProcessor post({.settingsJson = std::string(R"({"version": 1, "postEffects": {
            "autoExposure": {"enabled": false}, "output": {"dither": false}, "aa": {"mode": "fxaa"},
            "volumetricLight": {"enabled": true, "mode": ")") +
                                            mode + R"("}}})"});
        const std::vector<std::uint8_t> bytes = readBytes(post.execute(f));
        return std::make_pair(bytes, post.status().inputErrors);
    };
    const auto [marched, marchedErrors] = run("auto", withMap);
    const auto [screen, screenErrors] = run("screen", withMap);
    EXPECT_TRUE(marchedErrors.empty());
    EXPECT_TRUE(screenErrors.empty());
    EXPECT_NE(marched, screen);
    Frame colourMap = withMap;
    colourMap.sunShadow.depth = hdr;
    const auto [refused, refusedErrors] = run("auto", colourMap);
    ASSERT_EQ(refusedErrors.size(), 1u);
    EXPECT_NE(refusedErrors.front().find("sunShadow.depth"), std::string::npos) << refusedErrors.front();
    EXPECT_EQ(refused, screen);
    glDeleteTextures(1, &depth);
    glDeleteTextures(1, &map);
}

// inputsRead(): the inputs the settings' passes read, before any frame. A host that then hands over only
// those gets the same images.
TEST_F(PublicApi, SaysWhichInputsThePassesReadAndTheOthersChangeNothing) {
    const FrameInputSet offered{.depth = true, .normals = true, .motion = true, .camera = true};
    PostProcessor plain({.settingsJson = kSettings});
    EXPECT_EQ(plain.inputsRead(offered), FrameInputSet{}) << "the 2D chain reads no 3D input";

    PostProcessor taa({.settingsJson = kSettings});
    taa.setSetting("aa.mode=taa");
    const FrameInputSet read = taa.inputsRead(offered);
    EXPECT_TRUE(read.motion && read.depth && read.camera);
    EXPECT_FALSE(read.normals);
    EXPECT_FALSE(taa.inputsRead({.depth = true, .camera = true}).motion) << "only what is offered";
    EXPECT_TRUE(taa.inputsRead({.depth = true, .camera = true}).depth) << "motion from depth and the camera";

    PostProcessor lit({.settingsJson = kSettings});
    lit.setSetting("ssao.enabled=true");
    lit.setSetting("ssao.apply=lighting");
    EXPECT_EQ(lit.inputsRead(offered), FrameInputSet{}) << "lighting-stage AO, but no lighting stage";
    EXPECT_TRUE(lit.inputsRead(offered, true).depth);
    EXPECT_TRUE(lit.inputsRead(offered, true).normals);

    // Three TAA frames with every input and with only those read.
    const GlName depth = makeTexture(GL_R32F);
    const float five = 5.0f;
    glClearTexImage(depth, 0, GL_RED, GL_FLOAT, &five);
    const GlName normals = makeTexture(GL_RGBA16F);
    const float facing[4] = {0.0f, 0.0f, 1.0f, 0.0f};
    glClearTexImage(normals, 0, GL_RGBA, GL_FLOAT, facing);
    const GlName motion = makeTexture(GL_RG16F);
    const float drift[2] = {0.01f, 0.0f};
    glClearTexImage(motion, 0, GL_RG, GL_FLOAT, drift);
    const HostCamera camera = perspectiveCamera();
    Frame all = frame();
    all.depth = depth;
    all.depthEncoding = DepthEncoding::LinearView;
    all.normals = normals;
    all.motion = motion;
    all.camera = &camera;
    Frame lean = all;
    lean.normals = read.normals ? normals : 0;
    PostProcessor taaLean({.settingsJson = kSettings});
    taaLean.setSetting("aa.mode=taa");
    for (std::uint64_t i = 0; i < 3; ++i) {
        all.frameIndex = lean.frameIndex = i;
        (void)taa.beginFrame(i, all.dt, &camera);
        (void)taaLean.beginFrame(i, all.dt, &camera);
        EXPECT_EQ(readBytes(taa.execute(all)), readBytes(taaLean.execute(lean))) << "frame " << i;
    }
    EXPECT_EQ(taa.status().skipped, taaLean.status().skipped);
    const GlName textures[] = {depth, normals, motion};
    glDeleteTextures(3, textures);
}

TEST_F(PublicApi, SettingsErrorsNameTheKeyAndChangeNothing) {
    PostProcessor post({.settingsJson = kSettings});
    const std::string before = post.settingsJson();
    try {
        post.setSetting("bloom.intensity=-3");
        ADD_FAILURE() << "a negative bloom intensity was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bloom.intensity"), std::string::npos) << e.what();
    }
    try {
        post.setSettingsJson(R"({"version": 1, "postEffects": {"bloom": {"radiuss": 0.5}}})");
        ADD_FAILURE() << "an unknown key was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("radiuss"), std::string::npos) << e.what();
    }
    EXPECT_EQ(post.settingsJson(), before);
    post.setSetting("tonemapping.mode=agx");
    EXPECT_NE(post.settingsJson().find("\"agx\""), std::string::npos);
    EXPECT_THROW(PostProcessor({.settingsJson = "{not json"}), Error);

    post.setSettingsJson(R"({"version": 1, "preset": "neutral"})");
    EXPECT_NE(post.settingsJson().find("\"bloom\": {\n      \"enabled\": false"), std::string::npos)
        << "the neutral preset turns bloom off";
    try {
        post.setSettingsJson(R"({"version": 1, "preset": "glossy"})");
        ADD_FAILURE() << "an unknown preset was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("glossy"), std::string::npos) << e.what();
    }
}

TEST_F(PublicApi, JitterFollowsTheTemporalSettingsAndMovesTheProjection) {
    PostProcessor post({.settingsJson = R"({"version": 1, "postEffects": {"aa": {"mode": "taa"}}})"});
    HostCamera camera;
    const std::array<float, 2> jitter = post.beginFrame(1, 1.0f / 60.0f, &camera);
    EXPECT_TRUE(jitter[0] != 0.0f || jitter[1] != 0.0f);
    EXPECT_LE(std::abs(jitter[0]), 0.5f);
    EXPECT_LE(std::abs(jitter[1]), 0.5f);
    const Matrix4 moved = PostProcessor::jitteredProjection(kIdentity, {0.5f, 0.0f}, 100, 50);
    EXPECT_FLOAT_EQ(moved[12], 0.01f); // an orthographic matrix moves by 2 * 0.5 / 100 in clip x
}

} // namespace
} // namespace photopic::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (!::testing::GTEST_FLAG(list_tests)) {
        try {
            photopic::test::gContext = std::make_unique<photopic::HeadlessGlContext>();
        } catch (const photopic::Error& e) {
            photopic::test::gUnavailable = e.what();
        }
    }
    const int result = RUN_ALL_TESTS();
    photopic::test::gContext.reset();
    return result;
}
