#include "scenes/tabletop/TabletopScene.h"

#include "gl/ShaderLibrary.h"
#include "scenes/SceneSettings.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photopic {

namespace {

struct Rect {
    float x0, y0, x1, y1;
};

// The building: outer walls on [300, 1500] x [500, 1500], 24 units thick, split into a hall (east) and two
// rooms (west). The door to the field is in the east wall at y 940..1060.
constexpr Rect kBuilding{288.0f, 488.0f, 1512.0f, 1512.0f};
constexpr std::array<Rect, 10> kWalls{{
    {288.0f, 488.0f, 1512.0f, 512.0f},    // north
    {288.0f, 1488.0f, 1512.0f, 1512.0f},  // south
    {288.0f, 488.0f, 312.0f, 1512.0f},    // west
    {1488.0f, 488.0f, 1512.0f, 940.0f},   // east, north of the door
    {1488.0f, 1060.0f, 1512.0f, 1512.0f}, // east, south of the door
    {888.0f, 500.0f, 912.0f, 700.0f},     // hall | rooms, doors at y 700..800 and 1200..1300
    {888.0f, 800.0f, 912.0f, 1200.0f},
    {888.0f, 1300.0f, 912.0f, 1500.0f},
    {300.0f, 988.0f, 550.0f, 1012.0f}, // north room | south room, door at x 550..650
    {650.0f, 988.0f, 900.0f, 1012.0f},
}};
constexpr Rect kHall{900.0f, 500.0f, 1500.0f, 1500.0f};
constexpr Rect kNorthRoom{300.0f, 500.0f, 900.0f, 1000.0f};
constexpr Rect kSouthRoom{300.0f, 1000.0f, 900.0f, 1500.0f};

struct Torch {
    glm::vec2 pos;
    Rect room;
};
constexpr std::array<Torch, 6> kTorches{{
    {{1440.0f, 860.0f}, kHall}, // by the door: the player stands in its pool after stepping back in
    {{980.0f, 580.0f}, kHall},
    {{1020.0f, 1410.0f}, kHall},
    {{420.0f, 620.0f}, kNorthRoom},
    {{420.0f, 1380.0f}, kSouthRoom},
    {{800.0f, 1120.0f}, kSouthRoom},
}};
constexpr float kTorchCore = 60.0f;   ///< world units: inverse-square core radius
constexpr float kTorchRange = 700.0f; ///< world units: the light reaches zero here
constexpr float kFlameLuminance = 12.0f;

struct Token {
    std::uint32_t id;
    glm::vec2 pos; ///< the player's is replaced every frame
    glm::vec3 albedo;
};
constexpr float kTokenRadius = 40.0f;
constexpr std::array<Token, 6> kTokens{{
    {TabletopScene::kPlayerId, {0.0f, 0.0f}, {0.12f, 0.25f, 0.8f}},
    {2, {620.0f, 760.0f}, {0.2f, 0.6f, 0.25f}},
    {3, {700.0f, 1250.0f}, {0.5f, 0.2f, 0.6f}},
    {4, {2450.0f, 700.0f}, {0.7f, 0.15f, 0.1f}},
    {5, {2650.0f, 1300.0f}, {0.7f, 0.15f, 0.1f}},
    {6, {1900.0f, 1550.0f}, {0.8f, 0.45f, 0.1f}},
}};

/// The player's walk: (time s, x, y) keyframes, linear between them. Out through the door (x = 1512, the roof
/// edge) at ~3.9 s, a stroll on the field, back in at ~11.6 s and a stop right inside the door (so the light
/// under the token holds still while exposure settles), then to the middle of the hall and back to the start.
struct Key {
    double t, x, y;
};
constexpr std::array<Key, 10> kWalk{{
    {0.0, 1050.0, 1000.0},
    {1.5, 1050.0, 1000.0},
    {4.0, 1530.0, 1000.0},
    {6.5, 2050.0, 1000.0},
    {8.5, 2050.0, 1000.0},
    {11.0, 1700.0, 1000.0},
    {11.8, 1470.0, 1000.0},
    {15.0, 1470.0, 1000.0},
    {17.0, 1100.0, 1100.0},
    {22.0, 1100.0, 1100.0},
}};

constexpr int kMaskTexelsPerUnit = 10; ///< world units per mask texel
constexpr float kNightSunFraction = 0.03f;

OutdoorsMask makeRoofMask() {
    const int w = int(TabletopScene::kMapRect.width) / kMaskTexelsPerUnit;
    const int h = int(TabletopScene::kMapRect.height) / kMaskTexelsPerUnit;
    std::vector<std::uint8_t> texels(std::size_t(w) * std::size_t(h));
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            // Texel centre in mask UV, then world with V flipped: row 0 is the bottom of the map.
            const float u = (float(i) + 0.5f) / float(w);
            const float v = (float(j) + 0.5f) / float(h);
            const float x = TabletopScene::kMapRect.x + u * TabletopScene::kMapRect.width;
            const float y = TabletopScene::kMapRect.y + (1.0f - v) * TabletopScene::kMapRect.height;
            const bool roofed =
                x >= kBuilding.x0 && x <= kBuilding.x1 && y >= kBuilding.y0 && y <= kBuilding.y1;
            texels[std::size_t(j) * std::size_t(w) + std::size_t(i)] = roofed ? 0 : 255;
        }
    }
    return OutdoorsMask(w, h, std::move(texels), TabletopScene::kMapRect);
}

void setArray4(const Program& p, const char* name, const std::vector<float>& values) {
    const GLint location = glGetUniformLocation(p.id(), name);
    if (location >= 0 && !values.empty()) {
        glProgramUniform4fv(p.id(), location, GLsizei(values.size() / 4), values.data());
    }
}

} // namespace

TabletopScene::TabletopScene()
    : mProgram(makeComputeProgram("scenes/tabletop/tabletop.comp.glsl"))
    , mMask(makeRoofMask()) {
    mMaskTexture = Texture({.extent = {mMask.width(), mMask.height()},
                            .format = GL_R8,
                            .minFilter = GL_LINEAR,
                            .magFilter = GL_LINEAR,
                            .debugName = "tabletop outdoors mask"});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 of the mask is v = 0, as GL's row 0: uploaded as is.
    glTextureSubImage2D(mMaskTexture.id(), 0, 0, 0, mMask.width(), mMask.height(), GL_RED, GL_UNSIGNED_BYTE,
                        mMask.texels().data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    mSubjects.reserve(kTokens.size());
}

Settings TabletopScene::defaultSettings() const {
    Settings s;
    s.tonemapping.mode = ToneMapper::AcesFitted;
    // The eye follows the light under the player token (subject metering on the GPU), key 0.18,
    // x0.25..x4 (-2..+2 EV), tauBrighten 1 s, tauDarken 0.3 s.
    s.autoExposure.enabled = true;
    s.autoExposure.metering = MeteringMode::Subject;
    s.autoExposure.adaptation = AdaptationMode::Exponential;
    s.autoExposure.keyValue = 0.18f;
    s.autoExposure.minEV = -2.0f;
    s.autoExposure.maxEV = 2.0f;
    s.autoExposure.tauBrighten = 1.0f;
    s.autoExposure.tauDarken = 0.3f;
    s.subjects.probe.hz = 10.0f;
    s.subjects.probe.taps = 5;
    return s;
}

std::vector<SettingsIssue> TabletopScene::applyOverride(std::string_view assignment) {
    return applySceneOverride(mSettings, name(), assignment);
}

std::string TabletopScene::settingsJson() const {
    return sceneSettingsJson(mSettings);
}

void TabletopScene::resize(Extent extent) {
    if (mColor.valid() && mColor.extent() == extent) {
        return;
    }
    mColor = Texture({.extent = extent, .format = GL_RGBA16F, .debugName = "tabletop scene colour"});
}

std::vector<std::string> TabletopScene::telemetryColumns() const {
    return {"subject", "world_x", "world_y", "screen_u", "screen_v", "outdoors"};
}

glm::vec2 TabletopScene::playerWorldAt(double seconds, double loopSeconds) {
    // The loop closes by walking from the last key back to the first over the remaining time.
    const double period = std::max(loopSeconds, kWalk.back().t + 1.0);
    const double t = std::fmod(std::max(seconds, 0.0), period);
    for (std::size_t i = 1; i < kWalk.size(); ++i) {
        if (t < kWalk[i].t) {
            const Key& a = kWalk[i - 1];
            const Key& b = kWalk[i];
            const double f = (t - a.t) / (b.t - a.t);
            return {float(a.x + (b.x - a.x) * f), float(a.y + (b.y - a.y) * f)};
        }
    }
    const Key& a = kWalk.back();
    const Key& b = kWalk.front();
    const double f = (t - a.t) / (period - a.t);
    return {float(a.x + (b.x - a.x) * f), float(a.y + (b.y - a.y) * f)};
}

float TabletopScene::torchFlicker(int index, double seconds, float amplitude) {
    // Three incommensurate sines per torch, phases by the golden ratio: smooth, never periodic in the demo.
    const double phase = 2.0 * std::numbers::pi * 0.618033988749895 * double(index + 1);
    const double w = 2.0 * std::numbers::pi * seconds;
    const double n = 0.55 * std::sin(1.3 * w + phase) + 0.3 * std::sin(3.7 * w + 2.1 * phase) +
                     0.15 * std::sin(7.9 * w + 3.3 * phase);
    return float(1.0 + double(amplitude) * n);
}

namespace {

constexpr std::uint32_t kPlayerId = TabletopScene::kPlayerId;
constexpr SceneRect kMapRect = TabletopScene::kMapRect;

/// The view's centre: on the player, clamped to the map.
glm::vec2 viewCentre(glm::vec2 player, glm::vec2 viewSize) {
    glm::vec2 centre = player;
    centre.x =
        std::clamp(centre.x, kMapRect.x + 0.5f * viewSize.x,
                   std::max(kMapRect.x + 0.5f * viewSize.x, kMapRect.x + kMapRect.width - 0.5f * viewSize.x));
    centre.y = std::clamp(
        centre.y, kMapRect.y + 0.5f * viewSize.y,
        std::max(kMapRect.y + 0.5f * viewSize.y, kMapRect.y + kMapRect.height - 0.5f * viewSize.y));
    return centre;
}

/// The shader's tokens (x, y, radius, player?) and colours, four floats each.
struct TokenArrays {
    std::vector<float> tokens;
    std::vector<float> colors;
};

/// Subjects: every token; the player is controlled and the user's character (the selection rule picks the
/// controlled one first).
TokenArrays placeTokens(glm::vec2 player, glm::vec2 viewMin, glm::vec2 viewSize,
                        std::vector<Subject>& subjects) {
    subjects.clear();
    TokenArrays out;
    for (const Token& token : kTokens) {
        const glm::vec2 pos = token.id == kPlayerId ? player : token.pos;
        Subject s;
        s.id = token.id;
        s.world = pos;
        s.screenUv = (pos - viewMin) / viewSize; // image UV, v down (world y runs down too)
        s.controlled = token.id == kPlayerId;
        s.ownCharacter = token.id == kPlayerId;
        subjects.push_back(s);
        out.tokens.insert(out.tokens.end(),
                          {pos.x, pos.y, kTokenRadius, token.id == kPlayerId ? 1.0f : 0.0f});
        out.colors.insert(out.colors.end(), {token.albedo.r, token.albedo.g, token.albedo.b, 1.0f});
    }
    return out;
}

/// The walls and the torches at time `t`, as the shader's uniforms.
void setLightUniforms(const Program& program, const TabletopSceneSettings& settings, double t) {
    std::vector<float> walls;
    for (const Rect& r : kWalls) {
        walls.insert(walls.end(), {r.x0, r.y0, r.x1, r.y1});
    }
    std::vector<float> lightPos, lightColor, lightRoom;
    // Warm torch light (~1900 K), normalised to unit luma so torchIntensity is the luma of the irradiance.
    const glm::vec3 warm = glm::vec3(1.0f, 0.56f, 0.22f) / (0.2126f + 0.7152f * 0.56f + 0.0722f * 0.22f);
    for (std::size_t i = 0; i < kTorches.size(); ++i) {
        const Torch& torch = kTorches[i];
        const float k = settings.torchIntensity * TabletopScene::torchFlicker(int(i), t, settings.flicker);
        lightPos.insert(lightPos.end(), {torch.pos.x, torch.pos.y, kTorchCore, kTorchRange});
        lightColor.insert(lightColor.end(), {warm.r * k, warm.g * k, warm.b * k, kFlameLuminance * k});
        // A torch lights its room and the inner half of the walls around it.
        lightRoom.insert(lightRoom.end(), {torch.room.x0 - 12.0f, torch.room.y0 - 12.0f,
                                           torch.room.x1 + 12.0f, torch.room.y1 + 12.0f});
    }
    setUniform(program, "uWallCount", int(kWalls.size()));
    setArray4(program, "uWalls", walls);
    setUniform(program, "uLightCount", int(kTorches.size()));
    setArray4(program, "uLightPos", lightPos);
    setArray4(program, "uLightColor", lightColor);
    setArray4(program, "uLightRoom", lightRoom);
}

} // namespace

FrameInputs TabletopScene::render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) {
    // Time is frameIndex * dt, never a clock: frame N is identical on every run.
    const double t = double(time.frameIndex) * double(time.dt);
    const Extent e = mColor.extent();
    const glm::vec2 player = playerWorldAt(t, mSettings.loopSeconds);
    // The camera follows the player.
    const glm::vec2 viewSize(mSettings.viewHeight * float(e.width) / float(e.height), mSettings.viewHeight);
    const glm::vec2 centre = viewCentre(player, viewSize);
    const glm::vec2 viewMin = centre - 0.5f * viewSize;
    const TokenArrays tokens = placeTokens(player, viewMin, viewSize, mSubjects);
    const float sunScale = 1.0f - (1.0f - kNightSunFraction) * mSettings.darkness;
    const glm::vec3 sun = mSettings.sunIlluminance * sunScale * glm::vec3(1.0f, 0.97f, 0.9f);

    DebugGroup group("tabletop scene");
    setUniform(mProgram, "uViewMin", viewMin.x, viewMin.y);
    setUniform(mProgram, "uViewSize", viewSize.x, viewSize.y);
    setUniform(mProgram, "uSceneRect", kMapRect.x, kMapRect.y, kMapRect.width, kMapRect.height);
    setUniform(mProgram, "uSun", sun.r, sun.g, sun.b);
    setUniform(mProgram, "uAmbient", 0.004f, 0.0035f, 0.003f);
    setLightUniforms(mProgram, mSettings, t);
    setUniform(mProgram, "uTokenCount", int(kTokens.size()));
    setArray4(mProgram, "uTokens", tokens.tokens);
    setArray4(mProgram, "uTokenColor", tokens.colors);
    mProgram.use();
    glBindTextureUnit(0, mMaskTexture.id());
    glBindImageTexture(0, mColor.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glDispatchCompute(GLuint((e.width + 7) / 8), GLuint((e.height + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // The tokens go to the pipeline (as subjects: it probes them and its `subject` metering follows
    // the player); the roof mask answers "outdoors?" for them.
    pipeline.setOutdoorsMask(&mMask);
    pipeline.setSubjects(mSubjects, centre);
    const SubjectSelection sel = selectSubject(mSubjects, SubjectFallback::None);
    const Subject& s = mSubjects[sel.index];
    telemetry = {double(s.id),         double(s.world.x),
                 double(s.world.y),    double(s.screenUv.x),
                 double(s.screenUv.y), double(pipeline.outdoorsAtWorld(s.world.x, s.world.y))};
    return {.color = &mColor};
}

std::unique_ptr<Scene> makeTabletopScene() {
    return std::make_unique<TabletopScene>();
}

} // namespace photopic
