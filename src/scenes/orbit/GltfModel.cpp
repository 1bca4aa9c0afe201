#include "scenes/orbit/GltfModel.h"

#include "scenes/orbit/GltfJson.h"

#include "core/ShownText.h"
#include "io/ImageIO.h"

// tinygltf parses (JSON through the system nlohmann-json). Images are neither read nor decoded by it: the
// loader reads the files it names and decodes with stb_image (libstb) itself, after checking their size.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <stb_image.h>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <utility>

namespace photopic::orbit {

namespace fs = std::filesystem;

namespace {

constexpr const char* kIssueNames[] = {
#define PHOTOPIC_X(name, text) #name,
    PHOTOPIC_MODEL_ISSUES(PHOTOPIC_X)
#undef PHOTOPIC_X
};

std::string errorMessage(const fs::path& file, std::string_view where, std::string_view problem) {
    // The path as given, quoted as the image readers quote theirs: two models of one name in different
    // folders stay apart.
    std::string message = fmt::format("\"{}\": ", file.string());
    if (!where.empty()) {
        message.append(where).append(": ");
    }
    return message.append(problem);
}

} // namespace

std::string_view modelIssueName(ModelIssue issue) {
    return kIssueNames[static_cast<int>(issue)];
}

ModelError::ModelError(const fs::path& file, ModelIssue issue, std::string_view where,
                       std::string_view problem)
    : std::runtime_error(errorMessage(file, where, problem))
    , mIssue(issue)
    , mWhere(where) {}

std::size_t Model::primitiveCount() const {
    std::size_t n = 0;
    for (const MeshInstance& mesh : meshes) {
        n += mesh.primitives.size();
    }
    return n;
}

std::size_t Model::vertexCount() const {
    std::size_t n = 0;
    for (const MeshInstance& mesh : meshes) {
        for (const Primitive& p : mesh.primitives) {
            n += p.vertices.size();
        }
    }
    return n;
}

std::size_t Model::triangleCount() const {
    std::size_t n = 0;
    for (const MeshInstance& mesh : meshes) {
        for (const Primitive& p : mesh.primitives) {
            n += p.indices.size() / 3;
        }
    }
    return n;
}

namespace {

using Bytes = std::vector<std::uint8_t>;

std::string path(std::string_view array, std::size_t index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

/// Reads a whole regular file of at most `maxBytes`; the error names the model file and the JSON path.
Bytes readFile(const fs::path& file, const fs::path& model, const std::string& where,
               std::uint64_t maxBytes) {
    // The message opens with the model's path; a file the model refers to (a buffer, an image) is named too.
    const std::string named = file == model ? std::string() : fmt::format("\"{}\" ", file.string());
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (!fs::exists(status)) {
        throw ModelError(model, ModelIssue::MissingFile, where, fmt::format("file {}not found", named));
    }
    if (!fs::is_regular_file(status)) {
        throw ModelError(model, ModelIssue::Unreadable, where, named + "is not a regular file");
    }
    const std::uint64_t size = fs::file_size(file, ec);
    if (ec || size > maxBytes) {
        throw ModelError(
            model, ec ? ModelIssue::Unreadable : ModelIssue::TooLarge, where,
            named + (ec ? ec.message() : fmt::format("{} bytes, over the limit of {}", size, maxBytes)));
    }
    Bytes bytes(size);
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
        throw ModelError(model, ModelIssue::Unreadable, where, named + "cannot be read");
    }
    return bytes;
}

bool isDataUri(const std::string& uri) {
    return uri.starts_with("data:");
}

/// The fewest bytes an encoded image of this size can take: a PNG's rows as its header says they are stored
/// (pngMinimumEncodedBytes), anything else its samples at a byte each over deflate's largest expansion
/// (1032:1), which no JPEG reaches either (at best about 2 bits an 8x8 block).
std::uint64_t minimumEncodedBytes(std::span<const std::uint8_t> encoded, int width, int height,
                                  int channels) {
    constexpr std::uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (encoded.size() >= 26 && std::memcmp(encoded.data(), kPngSignature, 8) == 0 &&
        std::memcmp(encoded.data() + 12, "IHDR", 4) == 0) {
        return pngMinimumEncodedBytes(std::uint32_t(width), std::uint32_t(height), encoded[25], encoded[24]);
    }
    return std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(channels) / 1032;
}

/// Whether `file` (canonical: symbolic links resolved) lies inside `folder` (canonical too).
bool liesInside(const fs::path& file, const fs::path& folder) {
    const auto [folderEnd, fileAt] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
    // A trailing separator leaves an empty last element in `folder`: it matches anything.
    return folderEnd == folder.end() || (std::next(folderEnd) == folder.end() && folderEnd->empty());
}

/// `file` with every symbolic link and "." or ".." resolved (the parts that do not exist yet kept as
/// written).
fs::path canonicalPath(const fs::path& file) {
    std::error_code ec;
    fs::path out = fs::weakly_canonical(fs::absolute(file, ec), ec);
    return ec ? fs::path() : out;
}

/// The one resolver of every file a model names (a buffer's or an image's uri): percent-decoded first, then
/// joined to the model's folder, then every symbolic link and ".." resolved, and the result required to lie
/// inside the model's folder. Absolute paths and other schemes (http:, file:) are refused: a model names its
/// own files, and a viewer should not fetch or read anything else on its behalf.
fs::path resolveUri(const std::string& uri, const fs::path& baseDir, const fs::path& model,
                    const std::string& where) {
    const std::string decoded = tinygltf::dlib::urldecode(uri);
    const auto colon = decoded.find(':');
    if (decoded.empty() || decoded.front() == '/' || decoded.find('\0') != std::string::npos ||
        (colon != std::string::npos && colon < decoded.find('/'))) {
        throw ModelError(model, ModelIssue::Unsupported, where,
                         "URI \"" + shownText(uri) + "\" is not a relative file reference or a data: URI");
    }
    if (baseDir.empty()) {
        throw ModelError(model, ModelIssue::MissingFile, where,
                         "file \"" + shownText(decoded) +
                             "\" not found (a model read from memory is self-contained)");
    }
    const fs::path folder = canonicalPath(baseDir);
    const fs::path file = canonicalPath(baseDir / decoded);
    if (folder.empty() || file.empty() || !liesInside(file, folder)) {
        throw ModelError(model, ModelIssue::Unsupported, where,
                         "URI \"" + shownText(uri) + "\" names a file outside the model's folder " +
                             baseDir.string());
    }
    return file;
}

/// The JSON chunk of a GLB (after its header checks); tinygltf checks the rest of the container.
std::span<const std::uint8_t> glbJson(std::span<const std::uint8_t> bytes, const fs::path& model) {
    const auto u32 = [&](std::size_t offset) {
        std::uint32_t v = 0;
        std::memcpy(&v, bytes.data() + offset, 4);
        return v;
    };
    const auto fail = [&](const std::string& problem) {
        throw ModelError(model, ModelIssue::ParseError, "", "not a valid GLB: " + problem);
    };
    if (bytes.size() < 20) {
        fail("shorter than its 20-byte header");
    }
    if (u32(4) != 2) {
        fail("container version " + std::to_string(u32(4)) + " (only 2 is read)");
    }
    const std::uint64_t jsonLength = u32(12);
    if (u32(8) > bytes.size() || jsonLength > bytes.size() - 20 || u32(16) != 0x4E4F534Au) {
        fail("the header's lengths or the JSON chunk's type do not match the file");
    }
    return bytes.subspan(20, jsonLength);
}

// tinygltf's file system, restricted to regular files within the size limit inside the model's folder
// (every uri passed resolveUri before tinygltf looks; this holds its own path building to the same rule).
struct FsContext {
    std::uint64_t maxBytes = 0;
    fs::path folder; ///< canonical; empty for a model from memory, which may read no file
};
bool fsInside(const std::string& file, void* user) {
    const auto* context = static_cast<FsContext*>(user);
    const fs::path canonical = canonicalPath(file);
    return !context->folder.empty() && !canonical.empty() && liesInside(canonical, context->folder);
}
bool fsFileExists(const std::string& file, void* user) {
    std::error_code ec;
    return fsInside(file, user) && fs::is_regular_file(file, ec);
}
std::string fsExpandPath(const std::string& file, void*) {
    return file;
}
bool fsReadFile(std::vector<unsigned char>* out, std::string* err, const std::string& file, void* user) {
    if (!fsInside(file, user)) {
        *err = "\"" + shownText(file) + "\" lies outside the model's folder";
        return false;
    }
    try {
        *out = readFile(file, file, "", static_cast<FsContext*>(user)->maxBytes);
        return true;
    } catch (const ModelError& e) {
        *err = e.what();
        return false;
    }
}
bool fsWriteFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err = "writing is not allowed";
    return false;
}

/// Keeps an embedded image's encoded bytes (data: URI or buffer view): decoding waits until a material uses
/// the image, and its size has been checked.
bool keepEncodedImage(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + size);
    return true;
}

/// tinygltf's multi-line error text as one line.
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
        text.pop_back();
    }
    std::replace(text.begin(), text.end(), '\n', ';');
    return text;
}

enum class Component { Float, UnsignedByte, UnsignedShort, UnsignedInt, Other };

Component componentOf(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return Component::Float;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return Component::UnsignedByte;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return Component::UnsignedShort;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return Component::UnsignedInt;
    default:
        return Component::Other;
    }
}

std::size_t componentBytes(Component c) {
    switch (c) {
    case Component::UnsignedByte:
        return 1;
    case Component::UnsignedShort:
        return 2;
    default:
        return 4;
    }
}

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    default:
        return "unknown";
    }
}

/// What a use of an accessor accepts.
struct AccessorUse {
    const char* name;        ///< "POSITION", "indices"
    int type;                ///< TINYGLTF_TYPE_*
    bool indices = false;    ///< unsigned byte/short/int, not normalised
    bool normalized = false; ///< float, or normalised unsigned byte/short (texture coordinates)
};

constexpr AccessorUse kPosition{"POSITION", TINYGLTF_TYPE_VEC3};
constexpr AccessorUse kNormal{"NORMAL", TINYGLTF_TYPE_VEC3};
constexpr AccessorUse kTangent{"TANGENT", TINYGLTF_TYPE_VEC4};
constexpr AccessorUse kTexCoord{"TEXCOORD_0", TINYGLTF_TYPE_VEC2, false, true};
constexpr AccessorUse kIndices{"indices", TINYGLTF_TYPE_SCALAR, true};

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

/// glTF's triangle strips and fans as lists, in the specification's vertex order.
std::vector<std::uint32_t> triangulate(const std::vector<std::uint32_t>& in, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES || in.size() < 3) {
        return mode == TINYGLTF_MODE_TRIANGLES ? in : std::vector<std::uint32_t>{};
    }
    std::vector<std::uint32_t> out;
    out.reserve((in.size() - 2) * 3);
    for (std::size_t i = 0; i + 2 < in.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            out.insert(out.end(), {in[i], in[i + 1 + i % 2], in[i + 2 - i % 2]});
        } else {
            out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
        }
    }
    return out;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// A unit vector; a zero-length (degenerate) one becomes +y, since a renderer needs some unit normal. Scaled
/// by its largest component first: squaring a component near the float range's ends underflows to a
/// denormal or overflows, and the length computed from it is then wrong.
glm::vec3 unitOrUp(const glm::vec3& v) {
    const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0.0f) || !std::isfinite(largest)) {
        return glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return glm::normalize(v / largest);
}

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

void Builder::reserve(std::uint64_t vertices, std::uint64_t indices, std::uint64_t bytes,
                      const std::string& where) {
    mVertices += vertices;
    mIndices += indices;
    mBytes += bytes;
    if (mVertices > mLimits.maxVertices) {
        fail(ModelIssue::TooLarge, where, "more than " + std::to_string(mLimits.maxVertices) + " vertices");
    }
    if (mIndices > mLimits.maxIndices) {
        fail(ModelIssue::TooLarge, where, "more than " + std::to_string(mLimits.maxIndices) + " indices");
    }
    if (mBytes > mLimits.maxBytes) {
        fail(ModelIssue::TooLarge, where,
             "more than " + std::to_string(mLimits.maxBytes) + " bytes of output");
    }
}

// ---- Node graph -----------------------------------------------------------------------------------------

/// Each node's parent (-1 for none); a node listed as a child twice, or by two nodes, is an error.
std::vector<int> Builder::parents() const {
    std::vector<int> parent(mGltf.nodes.size(), -1);
    for (std::size_t n = 0; n < mGltf.nodes.size(); ++n) {
        const auto& children = mGltf.nodes[n].children;
        for (std::size_t c = 0; c < children.size(); ++c) {
            const std::string where = path("nodes", n) + "." + path("children", c);
            checkIndex(children[c], parent.size(), where, "node");
            int& p = parent[std::size_t(children[c])];
            if (p != -1) {
                fail(ModelIssue::BadNodeGraph, where,
                     "node " + std::to_string(children[c]) + " already has parent " + std::to_string(p) +
                         " (a node has at most one parent)");
            }
            p = int(n);
        }
    }
    return parent;
}

/// With one parent each, a cycle is a walk up the parents that comes back to a node on the same walk.
void Builder::checkAcyclic(const std::vector<int>& parent) const {
    enum : std::uint8_t { Unseen, OnWalk, Done };
    std::vector<std::uint8_t> state(parent.size(), Unseen);
    std::vector<int> walk;
    for (std::size_t start = 0; start < parent.size(); ++start) {
        walk.clear();
        for (int n = int(start); n != -1 && state[std::size_t(n)] != Done; n = parent[std::size_t(n)]) {
            if (state[std::size_t(n)] == OnWalk) {
                fail(ModelIssue::BadNodeGraph, path("nodes", std::size_t(n)),
                     "node " + std::to_string(n) + " is its own ancestor (a cycle through children)");
            }
            state[std::size_t(n)] = OnWalk;
            walk.push_back(n);
        }
        for (int n : walk) {
            state[std::size_t(n)] = Done;
        }
    }
}

/// The root nodes drawn: the chosen scene's (the file's "scene", else the first), or every parentless
/// node when the file has no scenes.
std::vector<int> Builder::sceneRoots(const std::vector<int>& parent) const {
    std::vector<int> roots;
    if (mGltf.scenes.empty()) {
        if (mGltf.defaultScene >= 0) {
            checkIndex(mGltf.defaultScene, 0, "scene", "scene");
        }
        for (std::size_t n = 0; n < parent.size(); ++n) {
            if (parent[n] == -1) {
                roots.push_back(int(n));
            }
        }
        return roots;
    }
    const int scene = std::max(mGltf.defaultScene, 0);
    checkIndex(scene, mGltf.scenes.size(), "scene", "scene");
    std::vector<bool> listed(parent.size(), false);
    for (std::size_t i = 0; i < mGltf.scenes[std::size_t(scene)].nodes.size(); ++i) {
        const int n = mGltf.scenes[std::size_t(scene)].nodes[i];
        const std::string where = path("scenes", std::size_t(scene)) + "." + path("nodes", i);
        checkIndex(n, parent.size(), where, "node");
        if (parent[std::size_t(n)] != -1 || listed[std::size_t(n)]) {
            fail(ModelIssue::BadNodeGraph, where,
                 "node " + std::to_string(n) + " is not a root (it has a parent or is listed twice)");
        }
        listed[std::size_t(n)] = true;
        roots.push_back(n);
    }
    return roots;
}

glm::mat4 Builder::localTransform(int node) const {
    const tinygltf::Node& n = mGltf.nodes[std::size_t(node)];
    const auto allFinite = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(float(x)); });
    };
    if (!allFinite(n.matrix) || !allFinite(n.translation) || !allFinite(n.rotation) || !allFinite(n.scale)) {
        fail(ModelIssue::NonFinite, path("nodes", std::size_t(node)), "transform is not finite");
    }
    if (n.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) {
            glm::value_ptr(m)[i] = float(n.matrix[std::size_t(i)]); // column-major in both
        }
        return m;
    }
    glm::mat4 m(1.0f);
    if (n.translation.size() == 3) {
        m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (n.rotation.size() == 4) {
        const glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]),
                          float(n.rotation[2]));
        if (!(glm::length(q) > 0.0f)) {
            fail(ModelIssue::NonFinite, path("nodes", std::size_t(node)) + ".rotation", "zero quaternion");
        }
        m *= glm::mat4_cast(glm::normalize(q));
    }
    if (n.scale.size() == 3) {
        m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
    }
    return m;
}

/// Depth first with an explicit stack: a hostile file's chain of a million nodes must not overflow the
/// call stack.
void Builder::addInstances(const std::vector<int>& roots, Model& model) {
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        stack.emplace_back(*it, glm::mat4(1.0f));
    }
    while (!stack.empty()) {
        const auto [node, parentWorld] = stack.back();
        stack.pop_back();
        Placement placement;
        placement.world = parentWorld * localTransform(node);
        const glm::mat3 linear(placement.world);
        const float det = glm::determinant(linear);
        if (!std::isfinite(det)) {
            fail(ModelIssue::NonFinite, path("nodes", std::size_t(node)), "world transform is not finite");
        }
        // A singular transform (a zero scale, used to hide a part) flattens the mesh to nothing visible.
        if (det != 0.0f && mGltf.nodes[std::size_t(node)].mesh >= 0) {
            placement.normalMatrix = glm::transpose(glm::inverse(linear));
            placement.mirrored = det < 0.0f;
            addInstance(node, placement, model);
        }
        const auto& children = mGltf.nodes[std::size_t(node)].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it) {
            stack.emplace_back(*it, placement.world);
        }
    }
}

void Builder::addInstance(int node, const Placement& placement, Model& model) {
    const tinygltf::Node& n = mGltf.nodes[std::size_t(node)];
    checkIndex(n.mesh, mGltf.meshes.size(), path("nodes", std::size_t(node)) + ".mesh", "mesh");
    const tinygltf::Mesh& mesh = mGltf.meshes[std::size_t(n.mesh)];
    MeshInstance instance;
    instance.name = n.name.empty() ? mesh.name : n.name;
    instance.node = node;
    instance.mesh = n.mesh;
    for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
        const std::string where = path("meshes", std::size_t(n.mesh)) + "." + path("primitives", i);
        Primitive primitive = buildPrimitive(mesh.primitives[i], placement, where);
        if (primitive.indices.empty()) {
            continue;
        }
        for (const Vertex& v : primitive.vertices) {
            instance.bounds.add(v.position);
        }
        instance.primitives.push_back(std::move(primitive));
    }
    if (!instance.primitives.empty()) {
        model.bounds.add(instance.bounds);
        model.meshes.push_back(std::move(instance));
    }
}

// ---- Accessors and primitives ---------------------------------------------------------------------------

AccessorView Builder::view(int accessor, const AccessorUse& use, const std::string& where) const {
    checkIndex(accessor, mGltf.accessors.size(), where, (std::string(use.name) + " accessor").c_str());
    const tinygltf::Accessor& a = mGltf.accessors[std::size_t(accessor)];
    AccessorView v;
    v.where = path("accessors", std::size_t(accessor)) + " (" + use.name + ")";
    v.kind = componentOf(a.componentType);
    v.normalized = a.normalized;
    v.count = a.count;
    const bool floatOk = !use.indices && !a.normalized && v.kind == Component::Float;
    const bool unormOk = use.normalized && a.normalized &&
                         (v.kind == Component::UnsignedByte || v.kind == Component::UnsignedShort);
    const bool indexOk =
        use.indices && !a.normalized && v.kind != Component::Other && v.kind != Component::Float;
    if (a.type != use.type || !(floatOk || unormOk || indexOk)) {
        fail(ModelIssue::BadAccessor, v.where,
             std::string(typeName(a.type)) + " of component type " + std::to_string(a.componentType) +
                 (a.normalized ? " (normalized)" : "") + " does not fit " + use.name + " (expected " +
                 typeName(use.type) + (use.indices ? " of unsigned integers)" : " of floats)"));
    }
    if (a.sparse.isSparse) {
        fail(ModelIssue::Unsupported, v.where, "sparse accessors are not read");
    }
    if (a.count == 0) {
        fail(ModelIssue::BadAccessor, v.where, "count is 0");
    }
    v.components = use.type == TINYGLTF_TYPE_SCALAR ? 1 : use.type;
    if (a.bufferView >= 0) {
        locate(a, v);
    }
    return v; // without a buffer view: all zeros
}

void Builder::locate(const tinygltf::Accessor& a, AccessorView& v) const {
    const std::uint64_t elementBytes = std::uint64_t(v.components) * componentBytes(v.kind);
    checkIndex(a.bufferView, mGltf.bufferViews.size(), v.where + ".bufferView", "buffer view");
    const tinygltf::BufferView& bv = mGltf.bufferViews[std::size_t(a.bufferView)];
    const std::string viewWhere = path("bufferViews", std::size_t(a.bufferView));
    checkIndex(bv.buffer, mGltf.buffers.size(), viewWhere + ".buffer", "buffer");
    const Bytes& buffer = mGltf.buffers[std::size_t(bv.buffer)].data;
    if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset) {
        fail(ModelIssue::OutOfBounds, viewWhere,
             "past the end of its buffer (" + std::to_string(buffer.size()) + " bytes)");
    }
    v.stride = bv.byteStride == 0 ? std::size_t(elementBytes) : bv.byteStride;
    if (v.stride < elementBytes) {
        fail(ModelIssue::BadAccessor, v.where,
             "byteStride " + std::to_string(v.stride) + " is smaller than an element");
    }
    // offset + (count - 1) * stride + element <= view length, with every step checked for overflow.
    std::uint64_t end = 0;
    if (__builtin_mul_overflow(std::uint64_t(a.count - 1), std::uint64_t(v.stride), &end) ||
        __builtin_add_overflow(end, std::uint64_t(a.byteOffset), &end) ||
        __builtin_add_overflow(end, elementBytes, &end) || end > bv.byteLength) {
        fail(ModelIssue::OutOfBounds, v.where,
             std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) + " (stride " +
                 std::to_string(v.stride) + ") run past the " + std::to_string(bv.byteLength) + " bytes of " +
                 viewWhere);
    }
    v.data = buffer.data() + bv.byteOffset + a.byteOffset;
}

std::vector<std::uint32_t> Builder::readIndices(const tinygltf::Primitive& p, std::size_t vertexCount,
                                                const std::string& where) const {
    if (p.indices < 0) {
        std::vector<std::uint32_t> indices(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            indices[i] = std::uint32_t(i);
        }
        return indices;
    }
    const AccessorView v = view(p.indices, kIndices, where + ".indices");
    if (v.count > mLimits.maxIndices) {
        fail(ModelIssue::TooLarge, v.where, std::to_string(v.count) + " indices, over the limit");
    }
    std::vector<std::uint32_t> indices(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        indices[i] = v.index(i);
        if (indices[i] >= vertexCount) {
            fail(ModelIssue::BadIndex, v.where,
                 "element " + std::to_string(i) + ": index " + std::to_string(indices[i]) + " past the " +
                     std::to_string(vertexCount) + " vertices");
        }
    }
    return indices;
}

Primitive Builder::buildPrimitive(const tinygltf::Primitive& p, const Placement& placement,
                                  const std::string& where) {
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        fail(ModelIssue::Unsupported, where + ".mode",
             "mode " + std::to_string(mode) +
                 " (points and lines are not drawn; triangles, strips and fans are)");
    }
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) {
        fail(ModelIssue::BadAccessor, where + ".attributes", "no POSITION");
    }
    const AccessorView positions = view(position->second, kPosition, where + ".attributes.POSITION");
    if (positions.count > mLimits.maxVertices) {
        fail(ModelIssue::TooLarge, positions.where,
             std::to_string(positions.count) + " vertices, over the limit");
    }
    Primitive out;
    std::vector<std::uint32_t> indices = readIndices(p, positions.count, where);
    if (mode != TINYGLTF_MODE_TRIANGLES && indices.size() > mLimits.maxIndices / 3 + 2) {
        fail(ModelIssue::TooLarge, where,
             std::to_string(indices.size()) + " strip or fan indices, over the limit");
    }
    out.indices = triangulate(indices, mode);
    if (mode == TINYGLTF_MODE_TRIANGLES && out.indices.size() % 3 != 0) {
        fail(ModelIssue::BadAccessor, where,
             std::to_string(out.indices.size()) + " indices, not a multiple of 3");
    }
    if (p.material >= 0) {
        checkIndex(p.material, mGltf.materials.size(), where + ".material", "material");
        out.material = p.material;
    } else {
        out.material = int(mGltf.materials.size()); // the default material, appended after the file's
        mNeedsDefaultMaterial = true;
    }
    out.flatNormals = p.attributes.find("NORMAL") == p.attributes.end();
    const std::uint64_t vertexCount = out.flatNormals ? out.indices.size() : positions.count;
    reserve(vertexCount, out.indices.size(), vertexCount * sizeof(Vertex) + out.indices.size() * 4, where);
    fillVertices(p, positions, placement, where, out);
    if (placement.mirrored) {
        for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3) {
            std::swap(out.indices[t + 1], out.indices[t + 2]);
        }
    }
    if (out.flatNormals) {
        makeFlatNormals(out);
    }
    return out;
}

void Builder::fillVertices(const tinygltf::Primitive& p, const AccessorView& positions,
                           const Placement& placement, const std::string& where, Primitive& out) const {
    const auto optional = [&](const char* name, const AccessorUse& use) -> std::optional<AccessorView> {
        const auto it = p.attributes.find(name);
        if (it == p.attributes.end()) {
            return std::nullopt;
        }
        AccessorView v = view(it->second, use, where + ".attributes." + name);
        if (v.count != positions.count) {
            fail(ModelIssue::BadAccessor, v.where,
                 "count " + std::to_string(v.count) + " differs from POSITION's " +
                     std::to_string(positions.count));
        }
        return v;
    };
    const auto normals = optional("NORMAL", kNormal);
    const auto texCoords = optional("TEXCOORD_0", kTexCoord);
    // Without normals the specification has tangents ignored: they belong to the normals the file lacks.
    const auto tangents = normals ? optional("TANGENT", kTangent) : std::nullopt;
    out.hasTexCoords = texCoords.has_value();
    out.hasTangents = tangents.has_value();
    const auto read = [&](const AccessorView& v, std::size_t i, int n) {
        glm::vec4 r(0.0f);
        for (int c = 0; c < n; ++c) {
            r[c] = v.value(i, c);
            if (!std::isfinite(r[c])) {
                fail(ModelIssue::NonFinite, v.where, "element " + std::to_string(i) + " is not finite");
            }
        }
        return r;
    };
    out.vertices.resize(positions.count);
    for (std::size_t i = 0; i < positions.count; ++i) {
        Vertex& v = out.vertices[i];
        v.position = glm::vec3(placement.world * glm::vec4(glm::vec3(read(positions, i, 3)), 1.0f));
        if (!finite(v.position)) {
            fail(ModelIssue::NonFinite, positions.where,
                 "element " + std::to_string(i) + " is not finite in world space");
        }
        if (normals) {
            v.normal = unitOrUp(placement.normalMatrix * glm::vec3(read(*normals, i, 3)));
        }
        if (texCoords) {
            v.texCoord = glm::vec2(read(*texCoords, i, 2));
        }
        if (tangents) {
            const glm::vec4 t = read(*tangents, i, 4);
            const float handedness = (t.w < 0.0f) != placement.mirrored ? -1.0f : 1.0f;
            v.tangent = glm::vec4(unitOrUp(glm::mat3(placement.world) * glm::vec3(t)), handedness);
        }
    }
}

/// Per-face normals: every triangle gets its own three vertices (the specification's flat normals).
void Builder::makeFlatNormals(Primitive& out) const {
    std::vector<Vertex> flat(out.indices.size());
    for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3) {
        const Vertex& a = out.vertices[out.indices[t]];
        const Vertex& b = out.vertices[out.indices[t + 1]];
        const Vertex& c = out.vertices[out.indices[t + 2]];
        const glm::vec3 normal = unitOrUp(glm::cross(b.position - a.position, c.position - a.position));
        for (std::size_t k = 0; k < 3; ++k) {
            flat[t + k] = out.vertices[out.indices[t + k]];
            flat[t + k].normal = normal;
            out.indices[t + k] = std::uint32_t(t + k);
        }
    }
    out.vertices = std::move(flat);
}

// ---- Materials, textures, images ------------------------------------------------------------------------

float finiteFactor(double value, const ModelError& error, float lo, float hi) {
    if (!std::isfinite(value)) {
        throw error;
    }
    return std::clamp(float(value), lo, hi);
}

Material Builder::convertMaterial(std::size_t index, Model& model) {
    const tinygltf::Material& m = mGltf.materials[index];
    const std::string where = path("materials", index);
    const ModelError nonFinite(mFile, ModelIssue::NonFinite, where, "a factor is not finite");
    const float big = std::numeric_limits<float>::max();
    Material out;
    out.name = m.name;
    const auto& pbr = m.pbrMetallicRoughness;
    for (int c = 0; c < 4; ++c) {
        out.baseColorFactor[c] = finiteFactor(pbr.baseColorFactor.at(std::size_t(c)), nonFinite, 0.0f, 1.0f);
    }
    for (int c = 0; c < 3; ++c) {
        out.emissiveFactor[c] = finiteFactor(m.emissiveFactor.at(std::size_t(c)), nonFinite, 0.0f, big);
    }
    out.metallicFactor = finiteFactor(pbr.metallicFactor, nonFinite, 0.0f, 1.0f);
    out.roughnessFactor = finiteFactor(pbr.roughnessFactor, nonFinite, 0.0f, 1.0f);
    out.normalScale = finiteFactor(m.normalTexture.scale, nonFinite, -big, big);
    out.occlusionStrength = finiteFactor(m.occlusionTexture.strength, nonFinite, 0.0f, 1.0f);
    out.alphaCutoff = finiteFactor(m.alphaCutoff, nonFinite, 0.0f, big);
    out.doubleSided = m.doubleSided;
    if (m.alphaMode == "MASK" || m.alphaMode == "BLEND" || m.alphaMode == "OPAQUE") {
        out.alphaMode = m.alphaMode == "MASK"    ? AlphaMode::Mask
                        : m.alphaMode == "BLEND" ? AlphaMode::Blend
                                                 : AlphaMode::Opaque;
    } else {
        fail(ModelIssue::WrongType, where + ".alphaMode",
             "\"" + m.alphaMode + "\" is not OPAQUE, MASK or BLEND");
    }
    const std::string pbrWhere = where + ".pbrMetallicRoughness";
    // Colour is stored sRGB-encoded, data (normals, metallic-roughness, occlusion) linear.
    const auto& base = pbr.baseColorTexture;
    const auto& orm = pbr.metallicRoughnessTexture;
    const auto& normal = m.normalTexture;
    const auto& occlusion = m.occlusionTexture;
    const auto& emissive = m.emissiveTexture;
    out.baseColorTexture = textureUse(base.index, base.texCoord, true, pbrWhere + ".baseColorTexture", model);
    out.metallicRoughnessTexture =
        textureUse(orm.index, orm.texCoord, false, pbrWhere + ".metallicRoughnessTexture", model);
    out.normalTexture = textureUse(normal.index, normal.texCoord, false, where + ".normalTexture", model);
    out.occlusionTexture =
        textureUse(occlusion.index, occlusion.texCoord, false, where + ".occlusionTexture", model);
    out.emissiveTexture =
        textureUse(emissive.index, emissive.texCoord, true, where + ".emissiveTexture", model);
    return out;
}

int Builder::textureUse(int index, int texCoord, bool srgb, const std::string& where, Model& model) {
    if (index < 0) {
        return -1;
    }
    checkIndex(index, mGltf.textures.size(), where + ".index", "texture");
    if (texCoord != 0) {
        fail(ModelIssue::Unsupported, where + ".texCoord",
             "TEXCOORD_" + std::to_string(texCoord) + " (only TEXCOORD_0 is read)");
    }
    const auto key = std::make_pair(index, srgb);
    if (const auto it = mTextureUses.find(key); it != mTextureUses.end()) {
        return it->second;
    }
    const tinygltf::Texture& t = mGltf.textures[std::size_t(index)];
    const std::string textureWhere = path("textures", std::size_t(index));
    if (t.source < 0) {
        fail(ModelIssue::Unsupported, textureWhere,
             "no source image (an extension's image format is not read)");
    }
    ModelTexture texture;
    texture.srgb = srgb;
    texture.image = decodeImage(t.source, textureWhere + ".source", model);
    if (t.sampler >= 0) {
        checkIndex(t.sampler, mGltf.samplers.size(), textureWhere + ".sampler", "sampler");
        const tinygltf::Sampler& s = mGltf.samplers[std::size_t(t.sampler)];
        texture.sampler = {.magFilter = std::max(s.magFilter, 0),
                           .minFilter = std::max(s.minFilter, 0),
                           .wrapS = s.wrapS,
                           .wrapT = s.wrapT};
    }
    model.textures.push_back(texture);
    mTextureUses.emplace(key, int(model.textures.size() - 1));
    return int(model.textures.size() - 1);
}

int Builder::decodeImage(int image, const std::string& where, Model& model) {
    checkIndex(image, mGltf.images.size(), where, "image");
    if (const auto it = mImages.find(image); it != mImages.end()) {
        return it->second;
    }
    const tinygltf::Image& source = mGltf.images[std::size_t(image)];
    const std::string imageWhere = path("images", std::size_t(image));
    Bytes file;
    if (!source.uri.empty() && !isDataUri(source.uri)) {
        file = readFile(resolveUri(source.uri, mBaseDir, mFile, imageWhere + ".uri"), mFile,
                        imageWhere + ".uri", mLimits.maxFileBytes);
    }
    const Bytes& encoded = file.empty() ? source.image : file;
    int width = 0;
    int height = 0;
    int channels = 0;
    if (encoded.empty() || encoded.size() > std::size_t(INT_MAX) ||
        !stbi_info_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels)) {
        fail(ModelIssue::BadImage, imageWhere,
             std::string("cannot be decoded: ") + (encoded.empty() ? "no data" : stbi_failure_reason()));
    }
    if (width > mLimits.maxImageSide || height > mLimits.maxImageSide) {
        fail(ModelIssue::TooLarge, imageWhere,
             std::to_string(width) + " x " + std::to_string(height) + " pixels, over the limit of " +
                 std::to_string(mLimits.maxImageSide));
    }
    const std::uint64_t pixelCount = std::uint64_t(width) * std::uint64_t(height);
    if (pixelCount > mLimits.maxImagePixels) {
        fail(ModelIssue::TooLarge, imageWhere,
             fmt::format("{} x {} pixels, over the limit of {} pixels", width, height,
                         mLimits.maxImagePixels));
    }
    // Checked before decoding, from the header: an image whose stored samples could not come from this
    // many bytes is a decompression bomb or lies about its size.
    if (const std::uint64_t needed = minimumEncodedBytes(encoded, width, height, channels);
        encoded.size() < needed) {
        fail(ModelIssue::BadImage, imageWhere,
             fmt::format("{} bytes cannot hold the {} x {} image its header declares (at least {} needed)",
                         encoded.size(), width, height, needed));
    }
    reserve(0, 0, std::uint64_t(width) * std::uint64_t(height) * 4, imageWhere);
    stbi_uc* pixels =
        stbi_load_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels, 4);
    if (!pixels) {
        fail(ModelIssue::BadImage, imageWhere, std::string("cannot be decoded: ") + stbi_failure_reason());
    }
    TextureImage out;
    out.name = source.name.empty() ? source.uri.substr(0, 64) : source.name;
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels, pixels + std::size_t(width) * std::size_t(height) * 4);
    stbi_image_free(pixels);
    model.images.push_back(std::move(out));
    mImages.emplace(image, int(model.images.size() - 1));
    return int(model.images.size() - 1);
}

Model Builder::build() {
    for (const std::string& extension : mGltf.extensionsRequired) {
        fail(ModelIssue::Unsupported, "extensionsRequired", "extension " + extension + " is not supported");
    }
    const std::vector<int> parent = parents();
    checkAcyclic(parent);
    Model model;
    addInstances(sceneRoots(parent), model);
    if (model.meshes.empty()) {
        fail(ModelIssue::NoGeometry, "",
             mGltf.meshes.empty() ? "no meshes" : "no triangles in the scene's nodes");
    }
    for (std::size_t m = 0; m < mGltf.materials.size(); ++m) {
        model.materials.push_back(convertMaterial(m, model));
    }
    if (mNeedsDefaultMaterial) {
        model.materials.push_back(Material{.name = "default"});
    }
    return model;
}

/// Every external buffer must be there before tinygltf looks: its own message names neither the buffer nor
/// the model, and it would fall back to the current directory.
void checkBufferFiles(const nlohmann::json& root, const fs::path& model, const fs::path& baseDir) {
    const auto buffers = root.find("buffers");
    if (buffers == root.end()) {
        return;
    }
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const auto uri = (*buffers)[i].find("uri");
        if (uri != (*buffers)[i].end() && !isDataUri(uri->get<std::string>())) {
            const std::string where = path("buffers", i) + ".uri";
            const fs::path file = resolveUri(uri->get<std::string>(), baseDir, model, where);
            std::error_code ec;
            if (!fs::is_regular_file(file, ec)) {
                throw ModelError(model, ModelIssue::MissingFile, where,
                                 "file \"" + file.string() + "\" not found");
            }
        }
    }
}

tinygltf::Model parseWithTinygltf(std::span<const std::uint8_t> bytes, bool binary, const fs::path& name,
                                  const fs::path& baseDir, const ModelLimits& limits) {
    FsContext context{.maxBytes = limits.maxFileBytes,
                      .folder = baseDir.empty() ? fs::path() : canonicalPath(baseDir)};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({fsFileExists, fsExpandPath, fsReadFile, fsWriteFile, &context});
    loader.SetImageLoader(keepEncodedImage, nullptr);
    tinygltf::Model gltf;
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        const std::string base = baseDir.string();
        ok = binary
                 ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), unsigned(bytes.size()), base)
                 : loader.LoadASCIIFromString(&gltf, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                              unsigned(bytes.size()), base);
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (!ok || !err.empty()) {
        throw ModelError(name, ModelIssue::ParseError, "",
                         "tinygltf: " + oneLine(err.empty() ? "failed" : err));
    }
    return gltf;
}

} // namespace

Model loadModelFromMemory(std::span<const std::uint8_t> bytes, const fs::path& name, const fs::path& baseDir,
                          const ModelLimits& limits) {
    if (bytes.size() > limits.maxFileBytes || bytes.size() > std::size_t(INT_MAX)) {
        throw ModelError(name, ModelIssue::TooLarge, "",
                         std::to_string(bytes.size()) + " bytes, over the limit");
    }
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const nlohmann::json root =
        detail::parseGltfJson(binary ? glbJson(bytes, name) : bytes, name, limits.maxJsonDepth);
    detail::checkGltfJson(root, name);
    checkBufferFiles(root, name, baseDir);
    tinygltf::Model gltf = parseWithTinygltf(bytes, binary, name, baseDir, limits);
    return Builder(name, limits, gltf, baseDir).build();
}

Model loadModel(const fs::path& file, const ModelLimits& limits) {
    const Bytes bytes = readFile(file, file, "", limits.maxFileBytes);
    fs::path baseDir = file.parent_path();
    if (baseDir.empty()) {
        baseDir = ".";
    }
    return loadModelFromMemory(bytes, file, baseDir, limits);
}

} // namespace photopic::orbit
