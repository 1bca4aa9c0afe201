#pragma once
// A Model (GltfModel.h: a glTF file or the built-in ship) on the GPU: one interleaved vertex buffer and one
// index buffer for every primitive, a draw range per primitive, and a texture per Model texture with the
// colour space its use asks for: base colour and emissive are colour, stored GL_SRGB8_ALPHA8 so the
// sampler decodes sRGB to linear before filtering; normal, metal-rough and occlusion maps are data, stored
// GL_RGBA8 and read as they are. Every texture has a full mip chain and the glTF sampler's wrap and filters.

#include "gl/Objects.h"
#include "scenes/orbit/GltfModel.h"

#include <cstdint>
#include <vector>

namespace photopic::orbit {

/// One primitive's place in the shared buffers and what it is drawn with.
struct MeshDraw {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    std::int32_t baseVertex = 0;
    int material = 0; ///< into Model::materials
    int instance = 0; ///< into Model::meshes (the object id is derived from it)
};

/// A GL texture for one use of an image (sRGB or linear), mipmapped, with the glTF sampler's settings.
/// `rgba` is width x height x 4 bytes, rows top to bottom (glTF's texture coordinates put v = 0 at the top
/// row, so the rows are uploaded as they are: no flip).
[[nodiscard]] photopic::Texture makeModelTexture(const TextureImage& image, bool srgb,
                                                 const ModelSampler& sampler, std::string_view debugName);

class OrbitMeshes {
public:
    OrbitMeshes() = default;
    /// Needs a current GL context. Copies the model's geometry and textures to the GPU.
    explicit OrbitMeshes(const Model& model);

    [[nodiscard]] const std::vector<MeshDraw>& draws() const { return mDraws; }
    [[nodiscard]] const std::vector<Material>& materials() const { return mMaterials; }
    /// The texture of Model::textures[index]; nullptr for -1.
    [[nodiscard]] const photopic::Texture* texture(int index) const;
    [[nodiscard]] const VertexArray& vertexArray() const { return mVao; }
    [[nodiscard]] std::size_t instanceCount() const { return mInstanceCount; }

private:
    Buffer mVertices;
    Buffer mIndices;
    VertexArray mVao;
    std::vector<photopic::Texture> mTextures;
    std::vector<Material> mMaterials;
    std::vector<MeshDraw> mDraws;
    std::size_t mInstanceCount = 0;
};

} // namespace photopic::orbit
