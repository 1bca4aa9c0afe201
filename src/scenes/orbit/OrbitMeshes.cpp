#include "scenes/orbit/OrbitMeshes.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <string>

namespace photopic::orbit {

namespace {

static_assert(sizeof(Vertex) == 48 && offsetof(Vertex, normal) == 12 && offsetof(Vertex, texCoord) == 24 &&
              offsetof(Vertex, tangent) == 32);

GLenum minFilterOf(int glTF) {
    switch (glTF) {
    case GL_NEAREST:
    case GL_LINEAR:
    case GL_NEAREST_MIPMAP_NEAREST:
    case GL_LINEAR_MIPMAP_NEAREST:
    case GL_NEAREST_MIPMAP_LINEAR:
    case GL_LINEAR_MIPMAP_LINEAR:
        return GLenum(glTF);
    default:
        return GL_LINEAR_MIPMAP_LINEAR; // the file leaves it to the renderer: trilinear
    }
}

GLenum wrapOf(int glTF) {
    return glTF == GL_CLAMP_TO_EDGE || glTF == GL_MIRRORED_REPEAT ? GLenum(glTF) : GLenum(GL_REPEAT);
}

} // namespace

photopic::Texture makeModelTexture(const TextureImage& image, bool srgb, const ModelSampler& sampler,
                                   std::string_view debugName) {
    const int side = std::max(image.width, image.height);
    const int levels = std::bit_width(unsigned(std::max(side, 1)));
    photopic::Texture t(
        {.extent = {image.width, image.height},
         .format = GLenum(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8),
         .levels = levels,
         .minFilter = minFilterOf(sampler.minFilter),
         .magFilter = sampler.magFilter == GL_NEAREST ? GLenum(GL_NEAREST) : GLenum(GL_LINEAR),
         .wrap = GL_REPEAT,
         .debugName = debugName});
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GLint(wrapOf(sampler.wrapS)));
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GLint(wrapOf(sampler.wrapT)));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // sRGB textures are filtered down in linear light (GL 4.5 requires it for sRGB formats).
    glGenerateTextureMipmap(t.id());
    return t;
}

OrbitMeshes::OrbitMeshes(const Model& model)
    : mVao(VertexArray::create("orbit meshes"))
    , mMaterials(model.materials)
    , mInstanceCount(model.meshes.size()) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    vertices.reserve(model.vertexCount());
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
        for (const Primitive& p : model.meshes[i].primitives) {
            mDraws.push_back({.firstIndex = std::uint32_t(indices.size()),
                              .indexCount = std::uint32_t(p.indices.size()),
                              .baseVertex = std::int32_t(vertices.size()),
                              .material = p.material,
                              .instance = int(i)});
            vertices.insert(vertices.end(), p.vertices.begin(), p.vertices.end());
            indices.insert(indices.end(), p.indices.begin(), p.indices.end());
        }
    }
    mVertices = Buffer({.size = std::max<std::size_t>(vertices.size() * sizeof(Vertex), 16),
                        .flags = 0,
                        .data = vertices.empty() ? nullptr : vertices.data(),
                        .debugName = "orbit vertices"});
    mIndices = Buffer({.size = std::max<std::size_t>(indices.size() * sizeof(std::uint32_t), 16),
                       .flags = 0,
                       .data = indices.empty() ? nullptr : indices.data(),
                       .debugName = "orbit indices"});
    const GLuint vao = mVao.id();
    glVertexArrayVertexBuffer(vao, 0, mVertices.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, mIndices.id());
    const struct {
        GLuint location;
        GLint size;
        GLuint offset;
    } attributes[] = {{0, 3, offsetof(Vertex, position)},
                      {1, 3, offsetof(Vertex, normal)},
                      {2, 2, offsetof(Vertex, texCoord)},
                      {3, 4, offsetof(Vertex, tangent)}};
    for (const auto& a : attributes) {
        glEnableVertexArrayAttrib(vao, a.location);
        glVertexArrayAttribFormat(vao, a.location, a.size, GL_FLOAT, GL_FALSE, a.offset);
        glVertexArrayAttribBinding(vao, a.location, 0);
    }
    mTextures.reserve(model.textures.size());
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        const orbit::ModelTexture& t = model.textures[i];
        const TextureImage& image = model.images[std::size_t(t.image)];
        const std::string name = "orbit " + image.name + (t.srgb ? " (sRGB)" : " (linear)");
        mTextures.push_back(makeModelTexture(image, t.srgb, t.sampler, name));
    }
}

const photopic::Texture* OrbitMeshes::texture(int index) const {
    return index >= 0 && std::size_t(index) < mTextures.size() ? &mTextures[std::size_t(index)] : nullptr;
}

} // namespace photopic::orbit
