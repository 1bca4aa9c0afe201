#pragma once
// The testbed's GL rasteriser: each primitive's bounding box is drawn as a proxy and its fragment shader
// ray-casts the exact shape (testbed_shading.h.glsl), writing colour (RGBA16F, the local shading), depth
// (DEPTH_COMPONENT32F through gl_FragDepth, standard GL depth), view-space normals (RGBA16F), motion
// (RG16F, UV current minus previous, jitter removed), object ids (R32UI, 0 for the sky) and the material
// (RGBA16F: specular weight F0 = mix(0.04, albedo, metallic), roughness; 0 for the sky) as one MRT pass after
// a full-screen sky.

#include "core/Camera.h"
#include "gl/Objects.h"
#include "scenes/SceneTargets.h"
#include "scenes/testbed/TestbedGeometry.h"

#include <vector>

namespace photopic::testbed {

class TestbedRenderer {
public:
    static constexpr int kMaxPrimitives = 64;

    /// Needs a current GL 4.5 context (compiles the shaders).
    TestbedRenderer();

    void resize(Extent extent);

    struct DrawInfo {
        const Camera* camera = nullptr; ///< unjittered projection
        glm::vec2 jitter{0.0f};         ///< pixels, x right, y up (Pipeline::beginFrame)
        const std::vector<Primitive>* primitives = nullptr;
        const Texture* ambientOcclusion = nullptr; ///< R visibility; multiplies the ambient term
        float ambientOcclusionPower = 1.0f;        ///< the ambient term takes pow(visibility, this)
        const Texture* sunVisibility = nullptr;    ///< R visibility; multiplies the sun term
        float sunScale = 1.0f;                     ///< multiplies the sun's illuminance (0: no sun)
    };
    void draw(const DrawInfo& info);

    [[nodiscard]] const Texture& color() const { return mTargets.color(); }
    [[nodiscard]] const Texture& depth() const { return mTargets.depth(); }
    [[nodiscard]] const Texture& normals() const { return mTargets.normals(); }
    [[nodiscard]] const Texture& motion() const { return mTargets.motion(); }
    [[nodiscard]] const Texture& objectId() const { return mTargets.objectId(); }
    [[nodiscard]] const Texture& material() const { return mTargets.material(); }

private:
    Program mObjects;
    Program mSky;
    VertexArray mVao;
    Buffer mPrimitives;
    Buffer mFrame;
    SceneTargets mTargets;
};

} // namespace photopic::testbed
