#include "scenes/orbit/GltfModel.h"

#include "scenes/orbit/GltfBuilder.h"
#include "scenes/orbit/GltfJson.h"

#include "core/ShownText.h"
#include "io/ImageIO.h"

// tinygltf parses (JSON through the system nlohmann-json); its implementation is compiled here, in this one
// translation unit, after GltfBuilder.h has included its declarations with the options it is built with.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>

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

namespace detail {

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

} // namespace detail

namespace {

using detail::Bytes;
using detail::canonicalPath;
using detail::isDataUri;
using detail::liesInside;
using detail::path;
using detail::readFile;
using detail::resolveUri;

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
    return detail::Builder(name, limits, gltf, baseDir).build();
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
