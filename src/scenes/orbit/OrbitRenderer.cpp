#include "scenes/orbit/OrbitRenderer.h"

#include "gl/ShaderLibrary.h"
#include "scenes/SceneCamera.h"
#include "scenes/orbit/OrbitWorld.h"

#include <cmath>
#include <cstddef>
#include <numbers>

namespace photopic::orbit {

namespace {

/// std140 mirror of orbit_frame.h.glsl's OrbitFrame.
struct GpuFrame {
    GpuSceneCamera camera;
    glm::vec4 cameraPos;
    glm::vec4 sunDirection;
    glm::vec4 sunIlluminance;
    glm::vec4 ambient;
    glm::vec4 hemiSky;
    glm::vec4 hemiGround;
    glm::vec4 hemiUp;
    glm::vec4 earth;
    glm::vec4 mars;
    glm::vec4 planetFx;
    glm::ivec4 flags;
    glm::vec4 aoPower;
};
static_assert(sizeof(GpuFrame) == 6 * 64 + 13 * 16);
static_assert(offsetof(GpuFrame, cameraPos) == 400 && offsetof(GpuFrame, flags) == 560);

/// std140 mirror of orbit_draw.h.glsl's OrbitDraw.
struct GpuDraw {
    glm::mat4 model;
    glm::mat4 prevModel;
    glm::mat4 normalMatrix;
    glm::vec4 baseColorFactor;
    glm::vec4 emissiveFactor;
    glm::vec4 surface;
    glm::vec4 env;
};
static_assert(sizeof(GpuDraw) == 3 * 64 + 4 * 16);

// The hemisphere fill's colours per unit of `hemi`: the planet's side gives bluish earthshine, the far side
// the faint sky of space. Their mean is about 1, so `hemi` reads as an irradiance.
constexpr glm::vec3 kHemiGround{1.35f, 1.45f, 1.7f};
constexpr glm::vec3 kHemiSky{0.55f, 0.55f, 0.6f};

photopic::Texture onePixel(GLenum format, const std::uint8_t rgba[4], std::string_view name) {
    photopic::Texture t({.extent = {1, 1}, .format = format, .debugName = name});
    glTextureSubImage2D(t.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return t;
}

/// The frame block of a draw on a target of extent `e`.
GpuFrame frameBlock(const OrbitRenderer::DrawInfo& info, Extent e) {
    const Camera& camera = *info.camera;
    const OrbitLights& lights = info.lights;

    GpuFrame f{};
    f.camera = sceneCameraBlock(camera, info.jitter, e);
    f.cameraPos = glm::vec4(glm::vec3(f.camera.invView[3]), camera.verticalFov / float(e.height));
    f.sunDirection = glm::vec4(glm::normalize(lights.sunDirection), std::cos(kSunAngularRadius));
    f.sunIlluminance = glm::vec4(glm::vec3(lights.sun),
                                 1.0f / (std::numbers::pi_v<float> * kSunAngularRadius * kSunAngularRadius));
    f.ambient = glm::vec4(glm::vec3(lights.ambient), 0.0f);
    f.hemiSky = glm::vec4(lights.hemi * kHemiSky, 0.0f);
    f.hemiGround = glm::vec4(lights.hemi * kHemiGround, 0.0f);
    f.hemiUp = glm::vec4(-glm::normalize(kEarth.centre), 0.0f);
    f.earth = glm::vec4(kEarth.centre, kEarth.radius);
    f.mars = glm::vec4(kMars.centre, kMars.radius);
    f.planetFx = {lights.atmosphere, lights.glow, float(lights.time), lights.nebula};
    f.flags = {info.ambientOcclusion != nullptr ? 1 : 0, info.contactShadows != nullptr ? 1 : 0,
               info.shadow != nullptr ? 1 : 0, 0};
    f.aoPower = glm::vec4(info.ambientOcclusionPower, 0.0f, 0.0f, 0.0f);
    return f;
}

} // namespace

OrbitRenderer::OrbitRenderer()
    : mMeshProgram(makeGraphicsProgram("scenes/orbit/orbit_mesh.vert.glsl",
                                       "scenes/orbit/orbit_mesh.frag.glsl",
                                       iblShaderDefines(ShadowMap::shaderDefines())))
    , mBackground(makeGraphicsProgram("passes/common/fullscreen.vert.glsl",
                                      "scenes/orbit/orbit_background.frag.glsl", iblShaderDefines()))
    , mEmptyVao(VertexArray::create("orbit background"))
    , mFrame({.size = sizeof(GpuFrame), .debugName = "orbit frame"})
    , mDraw({.size = sizeof(GpuDraw), .debugName = "orbit draw"}) {
    const std::uint8_t white[4] = {255, 255, 255, 255};
    const std::uint8_t flat[4] = {128, 128, 255, 255};
    mWhiteSrgb = onePixel(GL_SRGB8_ALPHA8, white, "orbit white (sRGB)");
    mWhiteLinear = onePixel(GL_RGBA8, white, "orbit white (linear)");
    mFlatNormal = onePixel(GL_RGBA8, flat, "orbit flat normal");
}

void OrbitRenderer::resize(Extent extent) {
    mTargets.resize(extent, "orbit");
}

void OrbitRenderer::setModel(const Model& model, const glm::mat4& placement) {
    mMeshes = std::make_unique<OrbitMeshes>(model);
    mIblBaselines.assign(model.materials.size(), 1.0f);
    mPlacement = placement;
    mModelBounds = ShadowBounds::aroundBox(model.bounds.min, model.bounds.max);
    mPlacementScale = glm::length(glm::vec3(placement[0]));
    mShadowValid = false;
}

void OrbitRenderer::setEnvironment(const ImageF& equirect, const IblOptions& options) {
    mIbl = std::make_unique<Ibl>(equirect, options);
}

namespace {

bool sameShadowSettings(const ShadowSettings& a, const ShadowSettings& b) {
    return a.enabled == b.enabled && a.resolution == b.resolution && a.constantBias == b.constantBias &&
           a.normalBias == b.normalBias && a.slopeBias == b.slopeBias && a.softness == b.softness &&
           a.samples == b.samples;
}

} // namespace

void OrbitRenderer::drawCasters(const ShadowCasterPass& pass, const glm::mat4& model) const {
    glBindVertexArray(mMeshes->vertexArray().id());
    pass.setModel(model);
    for (const MeshDraw& d : mMeshes->draws()) {
        glDrawElementsBaseVertex(
            GL_TRIANGLES, GLsizei(d.indexCount), GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(std::uintptr_t(d.firstIndex) * sizeof(std::uint32_t)),
            d.baseVertex);
    }
}

void OrbitRenderer::renderShadowMap(const DrawInfo& info) {
    const glm::mat4 model = info.shipTransform * mPlacement;
    if (mShadowValid && mShadowSun == info.lights.sunDirection && mShadowModel == model &&
        sameShadowSettings(mShadowSettings, *info.shadow)) {
        return;
    }
    // The sphere around the model's own bounds keeps its radius as the ship turns, so the map's texel size
    // stays fixed (texel snapping needs that).
    const ShadowBounds bounds{glm::vec3(model * glm::vec4(mModelBounds.center, 1.0f)),
                              mModelBounds.radius * mPlacementScale};
    mShadowMap.render({.sunDirection = info.lights.sunDirection,
                       .bounds = bounds,
                       .settings = info.shadow,
                       .drawCasters = [&](const ShadowCasterPass& pass) { drawCasters(pass, model); }});
    mShadowValid = true;
    mShadowSun = info.lights.sunDirection;
    mShadowModel = model;
    mShadowSettings = *info.shadow;
}

void OrbitRenderer::draw(const DrawInfo& info) {
    // No program is current at a clear: NVIDIA's driver checks the current program against the state at a
    // clear as at a draw, and recompiles its vertex shader when that state (the framebuffer, the vertex
    // array) differs from the one it was drawn with; a program left current by the last draw would be
    // recompiled for a clear it takes no part in.
    glUseProgram(0);
    if (mMeshes && info.shadow != nullptr) {
        renderShadowMap(info);
    }
    const GpuFrame f = frameBlock(info, mTargets.extent());
    mFrame.update(&f, sizeof(f));

    DebugGroup group("orbit scene");
    mTargets.bindAndClear();
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, mFrame.id());
    if (mIbl) {
        // Stored, never accumulated: the same value always gives the same frame.
        mIbl->setIntensity(info.lights.ibl);
        mIbl->bind();
    } else {
        mNoIbl.bind();
    }
    glDisable(GL_BLEND);

    // Space and the planets everywhere, writing their depth; the ship over them with the depth test.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    mBackground.use();
    glBindVertexArray(mEmptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);

    glDepthFunc(GL_LESS);
    if (mMeshes) {
        drawMeshes(info);
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(0); // the same at the host's next clear
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

void OrbitRenderer::drawMeshes(const DrawInfo& info) {
    const glm::mat4 model = info.shipTransform * mPlacement;
    const glm::mat4 prevModel = info.prevShipTransform * mPlacement;
    const glm::mat4 normalMatrix = glm::mat4(glm::transpose(glm::inverse(glm::mat3(model))));
    glBindTextureUnit(5, info.ambientOcclusion != nullptr ? info.ambientOcclusion->id() : mWhiteLinear.id());
    glBindTextureUnit(6, info.contactShadows != nullptr ? info.contactShadows->id() : mWhiteLinear.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, mDraw.id());
    mShadowMap.bind();
    mMeshProgram.use();
    glBindVertexArray(mMeshes->vertexArray().id());
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    const auto bind = [&](GLuint unit, int texture, const photopic::Texture& fallback) {
        const photopic::Texture* t = mMeshes->texture(texture);
        glBindTextureUnit(unit, (t != nullptr ? *t : fallback).id());
    };
    for (const MeshDraw& d : mMeshes->draws()) {
        const Material& m = mMeshes->materials()[std::size_t(d.material)];
        GpuDraw g{};
        g.model = model;
        g.prevModel = prevModel;
        g.normalMatrix = normalMatrix;
        g.baseColorFactor = m.baseColorFactor;
        g.emissiveFactor = glm::vec4(m.emissiveFactor, m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.0f);
        g.surface = {m.metallicFactor, m.roughnessFactor, m.normalTexture >= 0 ? m.normalScale : 0.0f,
                     m.occlusionTexture >= 0 ? m.occlusionStrength : 0.0f};
        // The material's stored baseline; the global intensity is OrbitIblBlock's. Neither is ever folded
        // into the other.
        g.env = {mIbl ? mIblBaselines[std::size_t(d.material)] : 0.0f,
                 float(ids::kFirstShip + unsigned(d.instance)), m.doubleSided ? 1.0f : 0.0f, 0.0f};
        mDraw.update(&g, sizeof(g));
        bind(0, m.baseColorTexture, mWhiteSrgb);
        bind(1, m.metallicRoughnessTexture, mWhiteLinear);
        bind(2, m.normalTexture, mFlatNormal);
        bind(3, m.occlusionTexture, mWhiteLinear);
        bind(4, m.emissiveTexture, mWhiteSrgb);
        if (m.doubleSided) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
        }
        glDrawElementsBaseVertex(
            GL_TRIANGLES, GLsizei(d.indexCount), GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(std::uintptr_t(d.firstIndex) * sizeof(std::uint32_t)),
            d.baseVertex);
    }
}

} // namespace photopic::orbit
