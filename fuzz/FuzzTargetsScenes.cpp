// Entry point for the scenes' file readers: the glTF loader, from bytes in memory.

#include "FuzzTargets.h"

#include "scenes/orbit/GltfModel.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace photopic::fuzz {

namespace {

// Small enough that one input stays fast, large enough for the committed samples to load whole.
constexpr orbit::ModelLimits kModelLimits{.maxVertices = std::uint64_t(1) << 16,
                                          .maxIndices = std::uint64_t(1) << 18,
                                          .maxImageSide = 1024,
                                          .maxBytes = std::uint64_t(64) << 20};

[[noreturn]] void broken(const char* promise) {
    std::fprintf(stderr, "fuzz target: promise broken: %s\n", promise);
    std::abort();
}

/// What a renderer relies on: indices in range, unit normals, finite positions, valid material and texture
/// indices, images of their stated size.
void checkModel(const orbit::Model& model) {
    for (const orbit::MeshInstance& mesh : model.meshes) {
        for (const orbit::Primitive& p : mesh.primitives) {
            if (p.indices.size() % 3 != 0 || p.material < 0 ||
                std::size_t(p.material) >= model.materials.size()) {
                broken("a primitive's index count or material");
            }
            for (std::uint32_t i : p.indices) {
                if (i >= p.vertices.size()) {
                    broken("an index past the vertices");
                }
            }
            for (const orbit::Vertex& v : p.vertices) {
                // Component by component: the length of a finite position far out can overflow.
                const bool finite =
                    std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z);
                if (!finite || std::abs(glm::length(v.normal) - 1.0f) > 1e-3f) {
                    broken("a non-finite position or a normal that is not unit length");
                }
            }
        }
    }
    for (const orbit::ModelTexture& t : model.textures) {
        if (t.image < 0 || std::size_t(t.image) >= model.images.size()) {
            broken("a texture's image index");
        }
    }
    for (const orbit::TextureImage& image : model.images) {
        if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4) {
            broken("an image's size");
        }
    }
}

} // namespace

void gltfModel(const std::uint8_t* data, std::size_t size) {
    try {
        // No base folder: a model from memory must be self-contained, so no input reads a file.
        checkModel(orbit::loadModelFromMemory({data, size}, "fuzz.glb", {}, kModelLimits));
    } catch (const orbit::ModelError&) {
    }
}

} // namespace photopic::fuzz
