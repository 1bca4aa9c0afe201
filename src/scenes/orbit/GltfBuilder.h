#pragma once
// Internal to the glTF loader (GltfModel.cpp, which parses): the Builder that turns a parsed tinygltf::Model
// into a Model, its member functions by job in GltfBuilder.cpp (node graph, instances, the whole build),
// GltfPrimitives.cpp (accessors, vertices, indices) and GltfMaterials.cpp (materials, textures, images); and
// the file access it shares with the parser, defined in GltfModel.cpp beside tinygltf's implementation.

#include "scenes/orbit/GltfModel.h"

// Images are neither read nor decoded by tinygltf: the loader reads the files it names and decodes with
// stb_image (libstb) itself, after checking their size. Every includer sees the same declarations.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace photopic::orbit::detail {

namespace fs = std::filesystem;

using Bytes = std::vector<std::uint8_t>;

/// "array[index]": a step of a JSON path, as errors name a value.
std::string path(std::string_view array, std::size_t index);

/// Reads a whole regular file of at most `maxBytes`; the error names the model file and the JSON path.
Bytes readFile(const fs::path& file, const fs::path& model, const std::string& where, std::uint64_t maxBytes);

bool isDataUri(const std::string& uri);

/// The fewest bytes an encoded image of this size can take (GltfModel.cpp says how).
std::uint64_t minimumEncodedBytes(std::span<const std::uint8_t> encoded, int width, int height, int channels);

/// The one resolver of every file a model names (a buffer's or an image's uri), inside the model's folder
/// only (GltfModel.cpp says how).
fs::path resolveUri(const std::string& uri, const fs::path& baseDir, const fs::path& model,
                    const std::string& where);

enum class Component { Float, UnsignedByte, UnsignedShort, UnsignedInt, Other };

inline std::size_t componentBytes(Component c) {
    switch (c) {
    case Component::UnsignedByte:
        return 1;
    case Component::UnsignedShort:
        return 2;
    default:
        return 4;
    }
}

/// What a use of an accessor accepts.
struct AccessorUse {
    const char* name;        ///< "POSITION", "indices"
    int type;                ///< TINYGLTF_TYPE_*
    bool indices = false;    ///< unsigned byte/short/int, not normalised
    bool normalized = false; ///< float, or normalised unsigned byte/short (texture coordinates)
};

/// A checked accessor: every element lies inside its buffer. No data: the specification's all zeros.
struct AccessorView {
    const std::uint8_t* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    Component kind = Component::Float;
    bool normalized = false;
    int components = 1;
    std::string where; ///< "accessors[3] (POSITION)"

    [[nodiscard]] float value(std::size_t element, int c) const {
        if (!data) {
            return 0.0f;
        }
        const std::uint8_t* p = data + element * stride + std::size_t(c) * componentBytes(kind);
        switch (kind) {
        case Component::Float: {
            float v = 0.0f;
            std::memcpy(&v, p, 4);
            return v;
        }
        case Component::UnsignedByte:
            return normalized ? float(*p) / 255.0f : float(*p);
        case Component::UnsignedShort: {
            std::uint16_t v = 0;
            std::memcpy(&v, p, 2);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        default:
            return 0.0f;
        }
    }
    [[nodiscard]] std::uint32_t index(std::size_t element) const {
        if (!data) {
            return 0;
        }
        const std::uint8_t* p = data + element * stride;
        std::uint32_t v = 0;
        std::memcpy(&v, p, componentBytes(kind)); // little-endian, as glTF stores it
        return v;
    }
};

/// A node's world transform, and what follows from it for normals and winding.
struct Placement {
    glm::mat4 world{1.0f};
    glm::mat3 normalMatrix{1.0f}; ///< inverse transpose of the upper 3x3
    bool mirrored = false;        ///< negative determinant: winding and tangent handedness flip
};

/// Turns a parsed tinygltf::Model into a Model, checking every index, range and value on the way.
class Builder {
public:
    Builder(const fs::path& file, const ModelLimits& limits, tinygltf::Model& gltf, const fs::path& baseDir)
        : mFile(file)
        , mBaseDir(baseDir)
        , mLimits(limits)
        , mGltf(gltf) {}

    Model build();

private:
    [[noreturn]] void fail(ModelIssue issue, const std::string& where, const std::string& problem) const {
        throw ModelError(mFile, issue, where, problem);
    }
    void checkIndex(int index, std::size_t count, const std::string& where, const char* what) const {
        if (index < 0 || std::size_t(index) >= count) {
            fail(ModelIssue::BadIndex, where,
                 std::string(what) + " " + std::to_string(index) + " out of range (the file has " +
                     std::to_string(count) + ")");
        }
    }
    void reserve(std::uint64_t vertices, std::uint64_t indices, std::uint64_t bytes,
                 const std::string& where);

    std::vector<int> parents() const;
    void checkAcyclic(const std::vector<int>& parent) const;
    std::vector<int> sceneRoots(const std::vector<int>& parent) const;
    glm::mat4 localTransform(int node) const;
    void addInstances(const std::vector<int>& roots, Model& model);
    void addInstance(int node, const Placement& placement, Model& model);

    AccessorView view(int accessor, const AccessorUse& use, const std::string& where) const;
    void locate(const tinygltf::Accessor& a, AccessorView& v) const;
    std::vector<std::uint32_t> readIndices(const tinygltf::Primitive& p, std::size_t vertexCount,
                                           const std::string& where) const;
    Primitive buildPrimitive(const tinygltf::Primitive& p, const Placement& placement,
                             const std::string& where);
    void fillVertices(const tinygltf::Primitive& p, const AccessorView& positions, const Placement& placement,
                      const std::string& where, Primitive& out) const;
    void makeFlatNormals(Primitive& out) const;

    Material convertMaterial(std::size_t index, Model& model);
    int textureUse(int index, int texCoord, bool srgb, const std::string& where, Model& model);
    int decodeImage(int image, const std::string& where, Model& model);

    const fs::path& mFile;
    fs::path mBaseDir;
    const ModelLimits& mLimits;
    tinygltf::Model& mGltf;
    std::uint64_t mVertices = 0;
    std::uint64_t mIndices = 0;
    std::uint64_t mBytes = 0;
    std::map<std::pair<int, bool>, int> mTextureUses; ///< (glTF texture, sRGB) -> Model::textures
    std::map<int, int> mImages;                       ///< glTF image -> Model::images
    bool mNeedsDefaultMaterial = false;
};

} // namespace photopic::orbit::detail
