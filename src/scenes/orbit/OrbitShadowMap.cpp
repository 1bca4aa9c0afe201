#include "scenes/orbit/OrbitShadowMap.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace photopic::orbit {

namespace {

/// Uniform locations of the depth and visibility programs (orbit_shadow_depth.vert.glsl).
constexpr GLint kViewProjectionLocation = 1;
/// The bias's cap on tan(angle between normal and sun): past about 83 degrees the slope bias stops growing,
/// and the receiver-plane depth gradient is limited to the same slope.
constexpr float kMaxTan = 8.0f;
/// Reference up for the light basis, and the sun's |y| past which +z is used instead (8 degrees from the
/// vertical), so the basis never degenerates.
constexpr float kVerticalSun = 0.990f;

/// The state render() and drawVisibility() change, put back when they return.
class SavedDrawState {
public:
    SavedDrawState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mFramebuffer);
        glGetIntegerv(GL_VIEWPORT, mViewport);
        glGetIntegerv(GL_CURRENT_PROGRAM, &mProgram);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &mVertexArray);
        glGetIntegerv(GL_DEPTH_FUNC, &mDepthFunc);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &mDepthMask);
        mDepthTest = glIsEnabled(GL_DEPTH_TEST);
        mCullFace = glIsEnabled(GL_CULL_FACE);
        mScissorTest = glIsEnabled(GL_SCISSOR_TEST);
    }
    ~SavedDrawState() {
        // A name that was deleted while bound goes away once it is unbound here; binding it again would
        // be an error, so it comes back as 0, as if it had been unbound by its owner.
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, alive(mFramebuffer, glIsFramebuffer));
        glViewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
        glUseProgram(alive(mProgram, glIsProgram));
        glBindVertexArray(alive(mVertexArray, glIsVertexArray));
        glDepthFunc(GLenum(mDepthFunc));
        glDepthMask(mDepthMask);
        setCapability(GL_DEPTH_TEST, mDepthTest);
        setCapability(GL_CULL_FACE, mCullFace);
        setCapability(GL_SCISSOR_TEST, mScissorTest);
    }
    SavedDrawState(const SavedDrawState&) = delete;
    SavedDrawState& operator=(const SavedDrawState&) = delete;

private:
    template <class IsObject>
    static GLuint alive(GLint name, IsObject isObject) {
        return name != 0 && isObject(GLuint(name)) ? GLuint(name) : 0;
    }
    static void setCapability(GLenum cap, GLboolean on) {
        if (on) {
            glEnable(cap);
        } else {
            glDisable(cap);
        }
    }
    GLint mFramebuffer = 0, mProgram = 0, mVertexArray = 0, mDepthFunc = GL_LESS;
    GLint mViewport[4] = {};
    GLboolean mDepthMask = GL_TRUE, mDepthTest = GL_FALSE, mCullFace = GL_FALSE, mScissorTest = GL_FALSE;
};

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Depth-only draws: depth test on, every face (no culling), no scissor.
void setDepthDrawState() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
}

/// Depth comparison against the stored depth (reference <= stored: lit), as orbit_shadow.h.glsl's
/// sampler2DShadow reads it; outside the map the border's depth 1 compares as lit.
void setDepthCompare(GLuint texture) {
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glTextureParameterfv(texture, GL_TEXTURE_BORDER_COLOR, border);
}

photopic::Texture depthTexture(int size, std::string_view debugName) {
    photopic::Texture t({.extent = {size, size},
                         .format = GL_DEPTH_COMPONENT32F,
                         .minFilter = GL_LINEAR,
                         .magFilter = GL_LINEAR,
                         .wrap = GL_CLAMP_TO_BORDER,
                         .debugName = debugName});
    setDepthCompare(t.id());
    return t;
}

ShaderDefines visibilityDefines() {
    ShaderDefines defines = ShadowMap::shaderDefines();
    defines.emplace_back("ORBIT_SHADOW_WORLD_OUT", "1");
    return defines;
}

} // namespace

const std::array<glm::vec2, kMaxShadowSamples>& shadowPoissonDisc() {
    // Mitchell 1991, "Spectrally optimal sampling for distribution ray tracing": each new point is the one,
    // of 32 i candidates spread uniformly over the disc, farthest from the points already placed.
    static const std::array<glm::vec2, kMaxShadowSamples> disc = [] {
        std::array<glm::vec2, kMaxShadowSamples> points{};
        std::mt19937 rng(20240611u);
        const auto unit = [&rng] { return float(rng() >> 8) * (1.0f / 16777216.0f); };
        for (int i = 1; i < kMaxShadowSamples; ++i) {
            float best = -1.0f;
            for (int c = 0; c < 32 * i; ++c) {
                const float r = std::sqrt(unit());
                const float phi = 6.2831853f * unit();
                const glm::vec2 candidate(r * std::cos(phi), r * std::sin(phi));
                float nearest = std::numeric_limits<float>::max();
                for (int j = 0; j < i; ++j) {
                    nearest = std::min(nearest, glm::distance(candidate, points[std::size_t(j)]));
                }
                if (nearest > best) {
                    best = nearest;
                    points[std::size_t(i)] = candidate;
                }
            }
        }
        return points;
    }();
    return disc;
}

ShadowBounds ShadowBounds::aroundBox(const glm::vec3& boxMin, const glm::vec3& boxMax) {
    return {0.5f * (boxMin + boxMax), 0.5f * glm::length(boxMax - boxMin)};
}

ShadowProjection fitShadowProjection(const glm::vec3& sunDirection, const ShadowBounds& bounds,
                                     int resolution, bool snap) {
    ShadowProjection p;
    p.toSun = glm::normalize(sunDirection);
    const glm::vec3 reference = std::abs(p.toSun.y) > kVerticalSun ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    p.right = glm::normalize(glm::cross(reference, p.toSun));
    p.up = glm::cross(p.toSun, p.right);
    p.view = glm::mat4(1.0f);
    for (int c = 0; c < 3; ++c) {
        p.view[c][0] = p.right[c];
        p.view[c][1] = p.up[c];
        p.view[c][2] = p.toSun[c];
    }
    // One texel of margin on every side: the snapped centre moves by up to half a texel, and the sphere
    // must stay inside the map. half = res texel / 2 = radius + texel.
    p.texelSize = 2.0f * bounds.radius / float(resolution - 2);
    const float half = bounds.radius + p.texelSize;
    glm::vec3 centre(glm::dot(bounds.center, p.right), glm::dot(bounds.center, p.up),
                     glm::dot(bounds.center, p.toSun));
    if (snap) {
        centre = glm::floor(centre / p.texelSize + 0.5f) * p.texelSize;
    }
    p.gridOrigin = glm::vec2(centre) / p.texelSize - 0.5f * float(resolution);
    if (snap) {
        p.gridOrigin = glm::floor(p.gridOrigin + 0.5f);
    }
    // The light looks down -z (towards -toSun): the near plane is on the sun's side of the sphere.
    const float nearPlane = -(centre.z + half);
    const float farPlane = -(centre.z - half);
    p.depthRange = farPlane - nearPlane;
    p.viewProjection =
        glm::ortho(centre.x - half, centre.x + half, centre.y - half, centre.y + half, nearPlane, farPlane) *
        p.view;
    return p;
}

void ShadowCasterPass::setModel(const glm::mat4& model) const {
    glProgramUniformMatrix4fv(mProgram, kModelMatrixLocation, 1, GL_FALSE, &model[0][0]);
}

ShaderDefines ShadowMap::shaderDefines(GLuint unit, GLuint blockBinding) {
    return {{"ORBIT_SHADOW_TEXTURE_UNIT", std::to_string(unit)},
            {"ORBIT_SHADOW_BLOCK", std::to_string(blockBinding)}};
}

ShadowMap::ShadowMap()
    : mDepthProgram(makeGraphicsProgram("scenes/orbit/orbit_shadow_depth.vert.glsl",
                                        "scenes/orbit/orbit_shadow_depth.frag.glsl"))
    , mVisibilityProgram(makeGraphicsProgram("scenes/orbit/orbit_shadow_depth.vert.glsl",
                                             "scenes/orbit/orbit_shadow_visibility.frag.glsl",
                                             visibilityDefines()))
    , mStandIn(depthTexture(1, "orbit sun shadow map (none yet)"))
    , mBlock("orbit sun shadow") {
    // A program with a shadow sampler must find a depth texture with comparison on its unit at every draw,
    // also before the first map or with shadows off (where the block's enabled flag keeps it unread): a
    // unit with no texture is undefined behaviour (NVIDIA reports it). Depth 1: everything lit.
    const float far = 1.0f;
    glClearTexImage(mStandIn.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
}

void ShadowMap::render(const RenderInfo& info) {
    if (info.settings == nullptr || !info.drawCasters) {
        throw std::invalid_argument("orbit shadow map: no settings or no caster callback");
    }
    if (!finite(info.sunDirection) || glm::length(info.sunDirection) < 1e-6f) {
        throw std::invalid_argument("orbit shadow map: the sun direction is zero or not finite");
    }
    if (!finite(info.bounds.center) || !std::isfinite(info.bounds.radius) || !(info.bounds.radius > 0.0f)) {
        throw std::invalid_argument("orbit shadow map: the caster bounds are empty or not finite (radius " +
                                    std::to_string(info.bounds.radius) + ")");
    }
    const ShadowSettings& s = *info.settings;
    if (!mDepth.valid() || mDepth.extent().width != s.resolution) {
        // Hardware comparison: each fetch is a bilinear 2x2 PCF of (reference <= stored).
        mDepth = depthTexture(s.resolution, "orbit sun shadow map");
        mTarget = Framebuffer({.color = {}, .depth = &mDepth, .debugName = "orbit sun shadow map"});
    }
    mProjection = fitShadowProjection(info.sunDirection, info.bounds, s.resolution, info.snap);

    const ShadowProjection& p = mProjection;
    Block b{};
    const glm::mat4 toUnit =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    b.worldToShadow = toUnit * p.viewProjection;
    b.right = glm::vec4(p.right, p.texelSize);
    b.up = glm::vec4(p.up, 1.0f / p.depthRange);
    b.toSun = glm::vec4(p.toSun, s.enabled ? 1.0f : 0.0f);
    b.bias = glm::vec4(s.constantBias * p.texelSize, s.normalBias * p.texelSize, s.slopeBias * p.texelSize,
                       kMaxTan);
    b.pcf = glm::vec4(s.softness, float(s.samples), 1.0f / float(s.resolution), float(s.resolution));
    b.grid = glm::vec4(p.gridOrigin, 0.0f, 0.0f);
    const auto& disc = shadowPoissonDisc();
    for (std::size_t i = 0; i < disc.size() / 2; ++i) {
        b.disc[i] = glm::vec4(disc[2 * i], disc[2 * i + 1]);
    }
    mBlock.update(b);
    if (!s.enabled) {
        return;
    }

    const SavedDrawState saved;
    DebugGroup group("orbit sun shadow map");
    mTarget.bind();
    setDepthDrawState();
    glUseProgram(0); // a program current at a clear is checked against it (OrbitRenderer::draw says why)
    const float far = 1.0f;
    glClearNamedFramebufferfv(mTarget.id(), GL_DEPTH, 0, &far);
    mDepthProgram.use();
    glProgramUniformMatrix4fv(mDepthProgram.id(), kViewProjectionLocation, 1, GL_FALSE,
                              &p.viewProjection[0][0]);
    const ShadowCasterPass pass(mDepthProgram.id());
    pass.setModel(glm::mat4(1.0f));
    info.drawCasters(pass);
}

void ShadowMap::bind(GLuint unit, GLuint blockBinding) const {
    glBindTextureUnit(unit, mDepth.valid() ? mDepth.id() : mStandIn.id());
    glBindSampler(unit, 0); // a sampler object would override the comparison mode
    mBlock.bind(blockBinding);
}

void ShadowMap::drawVisibility(const glm::mat4& viewProjection, const ShadowCasterDraws& drawCasters) const {
    if (!mDepth.valid()) {
        throw std::logic_error("orbit shadow map: drawVisibility before render");
    }
    const SavedDrawState saved;
    DebugGroup group("orbit sun shadow visibility");
    bind();
    setDepthDrawState();
    mVisibilityProgram.use();
    glProgramUniformMatrix4fv(mVisibilityProgram.id(), kViewProjectionLocation, 1, GL_FALSE,
                              &viewProjection[0][0]);
    const ShadowCasterPass pass(mVisibilityProgram.id());
    pass.setModel(glm::mat4(1.0f));
    drawCasters(pass);
}

} // namespace photopic::orbit
