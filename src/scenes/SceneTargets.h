#pragma once
// The render targets a built-in 3D scene draws into and hands the pipeline as its FrameInputs, in one
// framebuffer: colour 0 RGBA16F (the shaded colour), 1 RGBA16F view-space normals, 2 RG16F motion (UV,
// current minus previous), 3 R32UI object ids (0: none), 4 RGBA16F material (F0, roughness), and
// DEPTH_COMPONENT32F standard depth. Every target but colour is read texel for texel (nearest filtering).

#include "gl/Objects.h"

#include <string_view>

namespace photopic {

class SceneTargets {
public:
    /// Makes the targets at `extent` (nothing when they have it already), named "`name` colour" and so on.
    void resize(Extent extent, std::string_view name);
    /// Binds the framebuffer (viewport included) and clears every target: colours, normals, motion and
    /// material to 0, object ids to 0, depth to the far plane.
    void bindAndClear() const;

    [[nodiscard]] Extent extent() const { return mColor.extent(); }
    [[nodiscard]] const Texture& color() const { return mColor; }
    [[nodiscard]] const Texture& depth() const { return mDepth; }
    [[nodiscard]] const Texture& normals() const { return mNormals; }
    [[nodiscard]] const Texture& motion() const { return mMotion; }
    [[nodiscard]] const Texture& objectId() const { return mObjectId; }
    [[nodiscard]] const Texture& material() const { return mMaterial; }

private:
    Texture mColor;
    Texture mDepth;
    Texture mNormals;
    Texture mMotion;
    Texture mObjectId;
    Texture mMaterial;
    Framebuffer mFramebuffer;
};

} // namespace photopic
