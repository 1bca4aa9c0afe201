#pragma once
// A glTF 2.0 model (.gltf with its .bin and images, or .glb) read into what a metallic-roughness renderer
// uploads: triangle lists already placed in world space, one per primitive of every node that draws a mesh,
// the materials, and the images decoded to RGBA8. No GL: the upload is the renderer's.
//
// Parsing is tinygltf's; everything it leaves unchecked is checked here before a byte is read. A file that
// breaks the specification or a limit is a ModelError naming the file, the JSON path and the problem,
// never a crash or undefined behaviour, so a model given on the command line cannot take the program down.
// What is accepted, rejected and limited is listed in docs/architecture.md ("Models (glTF)").

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace photopic::orbit {

/// Why a model was rejected, one code per kind of problem (tests assert on these, not on the text).
#define PHOTOPIC_MODEL_ISSUES(X)                                                                             \
    X(Unreadable, "the file cannot be read")                                                                 \
    X(MissingFile, "a file the model names does not exist")                                                  \
    X(ParseError, "not a glTF 2.0 JSON or GLB file")                                                         \
    X(WrongType, "a JSON value has the wrong type")                                                          \
    X(BadIndex, "an index out of range")                                                                     \
    X(BadAccessor, "an accessor's type or component type does not fit its use")                              \
    X(OutOfBounds, "a byte range past the end of its buffer")                                                \
    X(NonFinite, "a NaN or infinite value")                                                                  \
    X(BadNodeGraph, "a node cycle, or a node with two parents")                                              \
    X(BadImage, "an image that cannot be decoded")                                                           \
    X(Unsupported, "a feature this loader does not handle")                                                  \
    X(TooLarge, "past a size limit")                                                                         \
    X(NoGeometry, "nothing to draw")

enum class ModelIssue {
#define PHOTOPIC_X(name, text) name,
    PHOTOPIC_MODEL_ISSUES(PHOTOPIC_X)
#undef PHOTOPIC_X
};

[[nodiscard]] std::string_view modelIssueName(ModelIssue issue); ///< "BadIndex"

/// what(): "\"FILE\": JSON-PATH: problem", the file's path as given, e.g. "\"models/Box.gltf\": accessors[0]:
/// index 255 past the 24 vertices".
class ModelError : public std::runtime_error {
public:
    ModelError(const std::filesystem::path& file, ModelIssue issue, std::string_view where,
               std::string_view problem);
    [[nodiscard]] ModelIssue issue() const { return mIssue; }
    [[nodiscard]] const std::string& where() const { return mWhere; } ///< JSON path ("" for the file)

private:
    ModelIssue mIssue;
    std::string mWhere;
};

/// Bounds checked before anything is allocated, so a hostile file fails fast instead of exhausting memory.
struct ModelLimits {
    std::uint64_t maxFileBytes = std::uint64_t(1) << 30; ///< bytes, per file read (.gltf/.glb, .bin, image)
    std::uint64_t maxVertices = std::uint64_t(1) << 26;  ///< output vertices, all instances together
    std::uint64_t maxIndices = std::uint64_t(1) << 28;   ///< output indices (3 per triangle), all together
    int maxImageSide = 16384;                            ///< pixels, an image's width or height
    std::uint64_t maxImagePixels = std::uint64_t(1)
                                   << 26;            ///< pixels, an image's width x height (8192 x 8192)
    std::uint64_t maxBytes = std::uint64_t(1) << 31; ///< bytes of output: vertices, indices and pixels
    int maxJsonDepth = 64;                           ///< nesting of JSON arrays and objects
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};
    [[nodiscard]] bool empty() const { return min.x > max.x; }
    void add(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Bounds& b) {
        if (!b.empty()) {
            add(b.min);
            add(b.max);
        }
    }
};

/// One vertex, interleaved as a renderer uploads it (48 bytes).
struct Vertex {
    glm::vec3 position{0.0f}; ///< world space
    glm::vec3 normal{0.0f};   ///< world space, unit length
    glm::vec2 texCoord{0.0f}; ///< TEXCOORD_0 (0 when the primitive has none); v down, as glTF stores it
    glm::vec4 tangent{0.0f};  ///< world-space xyz, w = +-1 handedness; all 0 when the primitive has none
};

/// A triangle list: 3 indices per triangle, counter-clockwise front faces in world space.
struct Primitive {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    int material = 0;          ///< into Model::materials (always valid: the glTF default material is added)
    bool hasTexCoords = false; ///< TEXCOORD_0 was given
    bool hasTangents = false;  ///< TANGENT was given (and normals were, as the specification requires)
    bool flatNormals = false;  ///< NORMAL was absent: per-face normals were made, vertices unshared
};

/// One node that draws a mesh: the mesh's primitives in that node's world transform.
struct MeshInstance {
    std::string name; ///< the node's name, else the mesh's
    int node = -1;    ///< glTF node index
    int mesh = -1;    ///< glTF mesh index
    std::vector<Primitive> primitives;
    Bounds bounds; ///< world space
};

enum class AlphaMode { Opaque, Mask, Blend };

/// glTF's sampler, in its own (OpenGL) enum values; 0 where the file leaves a filter to the renderer.
struct ModelSampler {
    int magFilter = 0;
    int minFilter = 0;
    int wrapS = 10497; ///< REPEAT
    int wrapT = 10497;
};

/// One use of an image: the same image read as colour and as data appears twice, with each flag.
struct ModelTexture {
    int image = -1;    ///< into Model::images
    bool srgb = false; ///< colour (base colour, emissive): decode sRGB; data (normal, ORM): linear
    ModelSampler sampler;
};

/// glTF's metallic-roughness material; texture fields index Model::textures, -1 for none.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f}; ///< linear RGBA
    float metallicFactor = 1.0f;     ///< [0, 1]
    float roughnessFactor = 1.0f;    ///< [0, 1]
    glm::vec3 emissiveFactor{0.0f};  ///< linear RGB
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f; ///< with AlphaMode::Mask
    bool doubleSided = false;
    int baseColorTexture = -1;         ///< sRGB
    int metallicRoughnessTexture = -1; ///< linear: G roughness, B metallic
    int normalTexture = -1;            ///< linear, tangent space
    float normalScale = 1.0f;          ///< scales the normal map's x and y
    int occlusionTexture = -1;         ///< linear, R
    float occlusionStrength = 1.0f;    ///< [0, 1]
    int emissiveTexture = -1;          ///< sRGB
};

struct TextureImage {
    std::string name; ///< the image's name, else its URI
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; ///< width x height x 4, rows top to bottom, as stored (not linearised)
};

struct Model {
    std::vector<MeshInstance> meshes;
    std::vector<Material> materials;
    std::vector<ModelTexture> textures;
    std::vector<TextureImage> images; ///< only those a material uses
    Bounds bounds;                    ///< world space, every vertex (framing)

    [[nodiscard]] std::size_t primitiveCount() const;
    [[nodiscard]] std::size_t vertexCount() const;
    [[nodiscard]] std::size_t triangleCount() const;
};

/// Reads a .gltf or .glb (told apart by the GLB magic, not the extension) and what it names beside it.
[[nodiscard]] Model loadModel(const std::filesystem::path& file, const ModelLimits& limits = {});

/// The same from bytes already in memory; `name` labels errors. Relative URIs resolve against `baseDir`;
/// with an empty `baseDir` the model must be self-contained (GLB chunk or data: URIs).
[[nodiscard]] Model loadModelFromMemory(std::span<const std::uint8_t> bytes,
                                        const std::filesystem::path& name,
                                        const std::filesystem::path& baseDir, const ModelLimits& limits = {});

} // namespace photopic::orbit
