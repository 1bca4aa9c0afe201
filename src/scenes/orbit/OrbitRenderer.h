#pragma once
// The orbit scene's forward HDR renderer. One full-screen pass ray-casts the planets and draws space (stars,
// nebula, the sun's disc, the limb glow: orbit_background.frag.glsl), then the ship's meshes are drawn over
// it with the depth test (orbit_mesh.*.glsl), both into the frame's MRT outputs: colour (RGBA16F, scene-
// referred), depth (DEPTH_COMPONENT32F, standard GL depth), view-space normals (RGBA16F), motion (RG16F, UV
// current minus previous with jitter removed: the camera's and the ship's own motion), object ids (R32UI,
// 0 for space) and the material (RGBA16F: F0, roughness).

#include "core/Camera.h"
#include "core/Image.h"
#include "gl/Objects.h"
#include "scenes/SceneTargets.h"
#include "scenes/orbit/OrbitIbl.h"
#include "scenes/orbit/OrbitMeshes.h"
#include "scenes/orbit/OrbitShadowMap.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace photopic::orbit {

/// The lights and the space effects of a frame, in scene-linear units.
struct OrbitLights {
    glm::vec3 sunDirection{0.0f, 1.0f, 0.0f}; ///< unit, towards the sun
    float sun = 3.0f;                         ///< the sun's illuminance at normal incidence
    float ambient = 0.03f;                    ///< uniform fill irradiance
    float hemi = 0.08f;      ///< hemisphere fill irradiance (earthshine from the planet's side)
    float ibl = 1.0f;        ///< global image-based-light intensity: multiplies each material's baseline
    float atmosphere = 1.0f; ///< the planets' rim on their discs, [0, 1] of its bounded maximum
    float glow = 1.0f;       ///< the limb glow outside the discs, the same
    float nebula = 1.0f;     ///< the nebula's strength
    double time = 0.0;       ///< s, script time (cloud drift)
};

class OrbitRenderer {
public:
    /// Needs a current GL 4.5 context (compiles the shaders).
    OrbitRenderer();

    void resize(Extent extent);
    /// Uploads `model` (the ship or a glTF file) and places it: world = placement * model position.
    /// Every material's image-based-light baseline starts at 1.
    void setModel(const Model& model, const glm::mat4& placement);
    /// Builds the image-based light (OrbitIbl.h: prefiltered specular cube, SH9 irradiance, split-sum
    /// table) from an equirectangular HDR environment. Until it is called there is no image-based light.
    void setEnvironment(const ImageF& equirect, const IblOptions& options = {});
    [[nodiscard]] const Ibl* ibl() const { return mIbl.get(); }

    struct DrawInfo {
        const Camera* camera = nullptr; ///< unjittered projection
        glm::vec2 jitter{0.0f};         ///< pixels (Pipeline::beginFrame)
        glm::mat4 shipTransform{1.0f};  ///< now, applied after the placement
        glm::mat4 prevShipTransform{1.0f};
        OrbitLights lights;
        const photopic::Texture* ambientOcclusion = nullptr; ///< R visibility; multiplies indirect light only
        float ambientOcclusionPower = 1.0f;
        const photopic::Texture* contactShadows = nullptr; ///< R visibility; multiplies the sun only
        /// The ship's sun shadow map (multiplies the sun only); null: no shadow map
        const ShadowSettings* shadow = nullptr;
    };
    void draw(const DrawInfo& info);

    /// The stored image-based-light baseline of material `index` (what ibl multiplies; never rewritten by
    /// the intensity, so changing it back and forth cannot drift).
    [[nodiscard]] float iblBaseline(int material) const { return mIblBaselines.at(std::size_t(material)); }
    [[nodiscard]] const OrbitMeshes& meshes() const { return *mMeshes; }
    /// The ship's sun shadow map as the last draw left it; null when shadows are off or none was drawn.
    [[nodiscard]] const ShadowMap* sunShadowMap() const {
        return mShadowValid && mShadowSettings.enabled ? &mShadowMap : nullptr;
    }

    [[nodiscard]] const photopic::Texture& color() const { return mTargets.color(); }
    [[nodiscard]] const photopic::Texture& depth() const { return mTargets.depth(); }
    [[nodiscard]] const photopic::Texture& normals() const { return mTargets.normals(); }
    [[nodiscard]] const photopic::Texture& motion() const { return mTargets.motion(); }
    [[nodiscard]] const photopic::Texture& objectId() const { return mTargets.objectId(); }
    [[nodiscard]] const photopic::Texture& material() const { return mTargets.material(); }

private:
    void drawMeshes(const DrawInfo& info);
    /// Renders the ship's shadow map when the sun, the ship's placement or the settings changed since the
    /// last frame (sub-frames and the lighting stage's second draw reuse it).
    void renderShadowMap(const DrawInfo& info);
    void drawCasters(const ShadowCasterPass& pass, const glm::mat4& model) const;

    Program mMeshProgram;
    Program mBackground;
    VertexArray mEmptyVao;
    Buffer mFrame;
    Buffer mDraw;
    std::unique_ptr<OrbitMeshes> mMeshes;
    std::vector<float> mIblBaselines;
    glm::mat4 mPlacement{1.0f};
    ShadowBounds mModelBounds;    ///< the model's bounding sphere before placement
    float mPlacementScale = 1.0f; ///< the placement's uniform scale
    ShadowMap mShadowMap;
    bool mShadowValid = false; ///< the map holds the state below
    glm::vec3 mShadowSun{0.0f};
    glm::mat4 mShadowModel{0.0f};
    ShadowSettings mShadowSettings;
    std::unique_ptr<Ibl> mIbl;
    IblStandIn mNoIbl; ///< bound in its place while there is no environment
    // 1x1 stand-ins for absent material textures: white colour (sRGB), white data, flat normal.
    photopic::Texture mWhiteSrgb;
    photopic::Texture mWhiteLinear;
    photopic::Texture mFlatNormal;
    SceneTargets mTargets;
};

} // namespace photopic::orbit
