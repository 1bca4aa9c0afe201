#include "scenes/testbed/TestbedRenderer.h"

#include "gl/ShaderLibrary.h"
#include "scenes/SceneCamera.h"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>

namespace photopic::testbed {

namespace {

/// std430 mirror of testbed_shading.h.glsl's TestbedPrimitive.
struct GpuPrimitive {
    glm::mat4 toWorld;
    glm::mat4 toObject;
    glm::mat4 prevToWorld;
    glm::vec4 shape;
    glm::vec4 albedo;
    glm::vec4 albedo2;
    glm::vec4 emissive;
    glm::vec4 surface; ///< x: roughness
};
static_assert(sizeof(GpuPrimitive) == 3 * 64 + 5 * 16);

/// std140 mirror of the TestbedFrame block.
struct GpuFrame {
    GpuSceneCamera camera;
    glm::vec4 sunDirection;
    glm::vec4 sunIlluminance;
    glm::vec4 skyZenith;
    glm::vec4 skyHorizon;
    glm::vec4 groundRadiance;
    glm::vec4 ambientSky;
    glm::vec4 ambientGround;
    glm::ivec4 flags;
    glm::vec4 ambientOcclusionPower; ///< x: the exponent on the ambient visibility (ssao.power)
};
static_assert(sizeof(GpuFrame) == 6 * 64 + 10 * 16);
static_assert(offsetof(GpuFrame, sunDirection) == 400 && offsetof(GpuFrame, flags) == 512);

GpuPrimitive toGpu(const Primitive& p) {
    return {p.toWorld,
            p.toObject,
            p.prevToWorld,
            glm::vec4(float(p.shape), p.size),
            glm::vec4(p.material.albedo, p.material.checker),
            glm::vec4(p.material.albedo2, p.material.metallic),
            glm::vec4(p.material.emissive, float(p.id)),
            glm::vec4(p.material.roughness, 0.0f, 0.0f, 0.0f)};
}

} // namespace

TestbedRenderer::TestbedRenderer()
    : mObjects(makeGraphicsProgram("scenes/testbed/testbed_objects.vert.glsl",
                                   "scenes/testbed/testbed_objects.frag.glsl"))
    , mSky(makeGraphicsProgram("passes/common/fullscreen.vert.glsl", "scenes/testbed/testbed_sky.frag.glsl"))
    , mVao(VertexArray::create("testbed"))
    , mPrimitives({.size = sizeof(GpuPrimitive) * kMaxPrimitives, .debugName = "testbed primitives"})
    , mFrame({.size = sizeof(GpuFrame), .debugName = "testbed frame"}) {}

void TestbedRenderer::resize(Extent extent) {
    mTargets.resize(extent, "testbed");
}

namespace {

/// The frame's uniform block: camera, sun, sky and ground, and which of the optional inputs are bound.
GpuFrame frameBlock(const TestbedRenderer::DrawInfo& info, Extent e, const Environment& env) {
    GpuFrame f{};
    f.camera = sceneCameraBlock(*info.camera, info.jitter, e);
    f.sunDirection = glm::vec4(env.sunDirection, std::cos(env.sunAngularRadius));
    f.sunIlluminance =
        glm::vec4(info.sunScale * env.sunIlluminance,
                  1.0f / (std::numbers::pi_v<float> * env.sunAngularRadius * env.sunAngularRadius));
    f.skyZenith = glm::vec4(env.skyZenith, 0.0f);
    f.skyHorizon = glm::vec4(env.skyHorizon, 0.0f);
    f.groundRadiance = glm::vec4(env.groundRadiance, 0.0f);
    f.ambientSky = glm::vec4(env.ambientSky, 0.0f);
    f.ambientGround = glm::vec4(env.ambientGround, 0.0f);
    f.flags = {info.ambientOcclusion != nullptr ? 1 : 0, info.sunVisibility != nullptr ? 1 : 0, 0, 0};
    f.ambientOcclusionPower = glm::vec4(info.ambientOcclusionPower, 0.0f, 0.0f, 0.0f);
    return f;
}

} // namespace

void TestbedRenderer::draw(const DrawInfo& info) {
    const std::vector<Primitive>& prims = *info.primitives;
    if (prims.size() > std::size_t(kMaxPrimitives)) {
        throw std::logic_error("testbed: more primitives than TestbedRenderer::kMaxPrimitives");
    }
    const Extent e = mTargets.extent();

    GpuPrimitive gpu[kMaxPrimitives];
    for (std::size_t i = 0; i < prims.size(); ++i) {
        gpu[i] = toGpu(prims[i]);
    }
    mPrimitives.update(gpu, sizeof(GpuPrimitive) * prims.size());

    const GpuFrame f = frameBlock(info, e, environment());
    mFrame.update(&f, sizeof(f));

    DebugGroup group("testbed scene");
    // No program is current at a clear: NVIDIA's driver checks the current program against the state at a
    // clear as at a draw and recompiles its vertex shader when that state differs from the one it was drawn
    // with (the orbit renderer does the same).
    glUseProgram(0);
    mTargets.bindAndClear();
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, mFrame.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mPrimitives.id());
    glBindVertexArray(mVao.id());
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);

    // The sky everywhere (no depth), then the objects over it with the depth test.
    glDisable(GL_DEPTH_TEST);
    mSky.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    if (info.ambientOcclusion != nullptr) {
        glBindTextureUnit(0, info.ambientOcclusion->id());
    }
    if (info.sunVisibility != nullptr) {
        glBindTextureUnit(1, info.sunVisibility->id());
    }
    mObjects.use();
    glDrawArraysInstanced(GL_TRIANGLES, 0, 36, GLsizei(prims.size()));
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0); // the same at the host's next clear
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

} // namespace photopic::testbed
