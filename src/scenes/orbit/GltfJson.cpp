#include "scenes/orbit/GltfJson.h"

#include "core/JsonText.h"

#include <algorithm>
#include <climits>
#include <string>

namespace photopic::orbit::detail {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string typeName(const json& value) {
    switch (value.type()) {
    case json::value_t::null:
        return "null";
    case json::value_t::object:
        return "an object";
    case json::value_t::array:
        return "an array";
    case json::value_t::string:
        return "a string";
    case json::value_t::boolean:
        return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
        return "an integer";
    case json::value_t::number_float:
        return "a number";
    default:
        return "an unexpected value";
    }
}

std::string at(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
}
std::string at(const std::string& path, std::size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

/// Checks values member by member; the first mismatch throws with its JSON path.
class Checker {
public:
    explicit Checker(const fs::path& file)
        : mFile(file) {}

    [[noreturn]] void fail(ModelIssue issue, const std::string& where, const std::string& problem) const {
        throw ModelError(mFile, issue, where, problem);
    }

    /// The member, or nullptr when absent (or required and absent: a WrongType error).
    const json* member(const json& object, const char* key, const std::string& path, bool required) const {
        const auto it = object.find(key);
        if (it != object.end()) {
            return &*it;
        }
        if (required) {
            fail(ModelIssue::WrongType, at(path, key), "required but missing");
        }
        return nullptr;
    }

    void expect(bool ok, const json& value, const std::string& where, const char* wanted) const {
        if (!ok) {
            fail(ModelIssue::WrongType, where,
                 std::string("expected ") + wanted + ", found " + typeName(value));
        }
    }

    /// An array index or other count tinygltf stores as int: a non-negative integer up to INT_MAX.
    void index(const json& object, const char* key, const std::string& path, bool required = false) const {
        if (const json* v = member(object, key, path, required)) {
            expect(v->is_number_unsigned(), *v, at(path, key), "a non-negative integer");
            if (v->get<std::uint64_t>() > std::uint64_t(INT_MAX)) {
                fail(ModelIssue::BadIndex, at(path, key), "index " + v->dump() + " is too large");
            }
        }
    }
    /// A byte count or offset (tinygltf stores these as size_t).
    void size(const json& object, const char* key, const std::string& path, bool required = false) const {
        if (const json* v = member(object, key, path, required)) {
            expect(v->is_number_unsigned(), *v, at(path, key), "a non-negative integer");
        }
    }
    void number(const json& object, const char* key, const std::string& path) const {
        if (const json* v = member(object, key, path, false)) {
            expect(v->is_number(), *v, at(path, key), "a number");
        }
    }
    void boolean(const json& object, const char* key, const std::string& path) const {
        if (const json* v = member(object, key, path, false)) {
            expect(v->is_boolean(), *v, at(path, key), "a boolean");
        }
    }
    void string(const json& object, const char* key, const std::string& path, bool required = false) const {
        if (const json* v = member(object, key, path, required)) {
            expect(v->is_string(), *v, at(path, key), "a string");
        }
    }
    /// An array of `count` numbers (any non-zero length when count is 0).
    void numbers(const json& object, const char* key, const std::string& path, std::size_t count) const {
        const json* v = member(object, key, path, false);
        if (!v) {
            return;
        }
        expect(v->is_array() && !v->empty() && (count == 0 || v->size() == count), *v, at(path, key),
               count == 0 ? "an array of numbers"
                          : ("an array of " + std::to_string(count) + " numbers").c_str());
        for (std::size_t i = 0; i < v->size(); ++i) {
            expect((*v)[i].is_number(), (*v)[i], at(at(path, key), i), "a number");
        }
    }
    void indices(const json& object, const char* key, const std::string& path) const {
        const json* v = member(object, key, path, false);
        if (!v) {
            return;
        }
        expect(v->is_array(), *v, at(path, key), "an array of indices");
        for (std::size_t i = 0; i < v->size(); ++i) {
            expect((*v)[i].is_number_unsigned(), (*v)[i], at(at(path, key), i), "a non-negative integer");
            if ((*v)[i].get<std::uint64_t>() > std::uint64_t(INT_MAX)) {
                fail(ModelIssue::BadIndex, at(at(path, key), i), "index " + (*v)[i].dump() + " is too large");
            }
        }
    }
    const json* object(const json& parent, const char* key, const std::string& path,
                       bool required = false) const {
        const json* v = member(parent, key, path, required);
        if (v) {
            expect(v->is_object(), *v, at(path, key), "an object");
        }
        return v;
    }
    /// A top-level array whose elements must all be objects; `check` is called on each.
    template <typename Check>
    void objects(const json& root, const char* key, Check check) const {
        const json* v = member(root, key, "", false);
        if (!v) {
            return;
        }
        expect(v->is_array(), *v, key, "an array");
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string path = at(std::string(key), i);
            expect((*v)[i].is_object(), (*v)[i], path, "an object");
            check((*v)[i], path);
        }
    }

private:
    const fs::path& mFile;
};

void checkTextureInfo(const Checker& c, const json& parent, const char* key, const std::string& path) {
    if (const json* info = c.object(parent, key, path)) {
        const std::string p = at(path, key);
        c.index(*info, "texCoord", p);
        c.number(*info, "scale", p);
        c.number(*info, "strength", p);
        c.index(*info, "index", p, true);
    }
}

void checkMaterial(const Checker& c, const json& m, const std::string& path) {
    if (const json* pbr = c.object(m, "pbrMetallicRoughness", path)) {
        const std::string p = at(path, "pbrMetallicRoughness");
        c.numbers(*pbr, "baseColorFactor", p, 4);
        c.number(*pbr, "metallicFactor", p);
        c.number(*pbr, "roughnessFactor", p);
        checkTextureInfo(c, *pbr, "baseColorTexture", p);
        checkTextureInfo(c, *pbr, "metallicRoughnessTexture", p);
    }
    checkTextureInfo(c, m, "normalTexture", path);
    checkTextureInfo(c, m, "occlusionTexture", path);
    checkTextureInfo(c, m, "emissiveTexture", path);
    c.numbers(m, "emissiveFactor", path, 3);
    c.string(m, "alphaMode", path);
    c.number(m, "alphaCutoff", path);
    c.boolean(m, "doubleSided", path);
    c.string(m, "name", path);
}

void checkMesh(const Checker& c, const json& mesh, const std::string& path) {
    const json& primitives = *c.member(mesh, "primitives", path, true);
    c.expect(primitives.is_array() && !primitives.empty(), primitives, at(path, "primitives"),
             "a non-empty array");
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        const std::string p = at(at(path, "primitives"), i);
        c.expect(primitives[i].is_object(), primitives[i], p, "an object");
        const json& attributes = *c.object(primitives[i], "attributes", p, true);
        for (const auto& [name, value] : attributes.items()) {
            c.index(attributes, name.c_str(), at(p, "attributes"), true);
        }
        c.index(primitives[i], "indices", p);
        c.index(primitives[i], "material", p);
        c.index(primitives[i], "mode", p);
    }
    c.string(mesh, "name", path);
}

void checkNode(const Checker& c, const json& node, const std::string& path) {
    c.indices(node, "children", path);
    c.index(node, "mesh", path);
    c.numbers(node, "matrix", path, 16);
    c.numbers(node, "translation", path, 3);
    c.numbers(node, "rotation", path, 4);
    c.numbers(node, "scale", path, 3);
    c.string(node, "name", path);
}

void checkAccessor(const Checker& c, const json& a, const std::string& path) {
    c.index(a, "bufferView", path);
    c.size(a, "byteOffset", path);
    c.index(a, "componentType", path, true);
    c.boolean(a, "normalized", path);
    c.size(a, "count", path, true);
    c.string(a, "type", path, true);
    c.object(a, "sparse", path);
}

/// tinygltf hands an image's buffer view to the image decoder before anything checks the view's range, so
/// the ranges are checked here, against the lengths the buffers declare (tinygltf loads exactly that many).
void checkBufferViewRanges(const Checker& c, const json& root) {
    const auto views = root.find("bufferViews");
    if (views == root.end()) {
        return;
    }
    const auto buffers = root.find("buffers");
    const std::size_t bufferCount = buffers == root.end() ? 0 : buffers->size();
    for (std::size_t i = 0; i < views->size(); ++i) {
        const json& view = (*views)[i];
        const std::string path = at(std::string("bufferViews"), i);
        const auto buffer = view["buffer"].get<std::uint64_t>();
        if (buffer >= bufferCount) {
            c.fail(ModelIssue::BadIndex, at(path, "buffer"),
                   "buffer " + std::to_string(buffer) + " out of range (" + std::to_string(bufferCount) +
                       " buffers)");
        }
        const auto offset = view.value("byteOffset", std::uint64_t(0));
        const auto length = view["byteLength"].get<std::uint64_t>();
        const auto available = (*buffers)[buffer]["byteLength"].get<std::uint64_t>();
        if (length == 0 || offset > available || length > available - offset) {
            c.fail(ModelIssue::OutOfBounds, path,
                   "bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                       " past the end of buffer " + std::to_string(buffer) + " (" +
                       std::to_string(available) + " bytes)");
        }
    }
}

void checkImageViews(const Checker& c, const json& root) {
    const auto images = root.find("images");
    if (images == root.end()) {
        return;
    }
    const auto views = root.find("bufferViews");
    const std::size_t viewCount = views == root.end() ? 0 : views->size();
    for (std::size_t i = 0; i < images->size(); ++i) {
        const auto view = (*images)[i].find("bufferView");
        if (view != (*images)[i].end() && view->get<std::uint64_t>() >= viewCount) {
            c.fail(ModelIssue::BadIndex, at(at(std::string("images"), i), "bufferView"),
                   "buffer view " + view->dump() + " out of range (" + std::to_string(viewCount) + " views)");
        }
    }
}

void checkAsset(const Checker& c, const json& root) {
    const json& asset = *c.object(root, "asset", "", true);
    c.string(asset, "version", "asset", true);
    const auto version = asset["version"].get<std::string>();
    if (!version.starts_with("2.")) {
        c.fail(ModelIssue::Unsupported, "asset.version", "glTF " + version + " (only 2.x is read)");
    }
}

} // namespace

json parseGltfJson(std::span<const std::uint8_t> text, const fs::path& file, int maxDepth) {
    // The nesting limit stops a deeply nested file as soon as it is too deep. Duplicate keys are left to the
    // glTF schema's own checks (the last one wins, as in every glTF reader).
    try {
        return parseJsonText({reinterpret_cast<const char*>(text.data()), text.size()},
                             {.maxDepth = maxDepth, .rejectDuplicateKeys = false});
    } catch (const JsonTextError& e) {
        std::string message = e.what();
        if (e.kind == JsonTextError::Kind::TooDeep) {
            throw ModelError(file, ModelIssue::ParseError, "", "JSON " + message);
        }
        // A file that does not even open as a JSON object is not a glTF file at all (an image passed as the
        // model, say): say that first.
        const auto first = std::find_if(text.begin(), text.end(), [](std::uint8_t c) {
            return c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != 0xEF && c != 0xBB && c != 0xBF;
        });
        if (first == text.end() || *first != '{') {
            message =
                "not a glTF 2.0 model (a .gltf file is a JSON object, a .glb file starts with \"glTF\"): " +
                message;
        }
        throw ModelError(file, ModelIssue::ParseError, "", message);
    }
}

void checkGltfJson(const json& root, const fs::path& file) {
    const Checker c(file);
    c.expect(root.is_object(), root, "(root)", "an object");
    checkAsset(c, root);
    c.index(root, "scene", "");
    if (const json* required = c.member(root, "extensionsRequired", "", false)) {
        c.expect(required->is_array(), *required, "extensionsRequired", "an array of names");
        for (std::size_t i = 0; i < required->size(); ++i) {
            c.expect((*required)[i].is_string(), (*required)[i], at(std::string("extensionsRequired"), i),
                     "a string");
        }
    }
    c.objects(root, "scenes", [&](const json& s, const std::string& p) { c.indices(s, "nodes", p); });
    c.objects(root, "nodes", [&](const json& n, const std::string& p) { checkNode(c, n, p); });
    c.objects(root, "meshes", [&](const json& m, const std::string& p) { checkMesh(c, m, p); });
    c.objects(root, "accessors", [&](const json& a, const std::string& p) { checkAccessor(c, a, p); });
    c.objects(root, "bufferViews", [&](const json& v, const std::string& p) {
        c.index(v, "buffer", p, true);
        c.size(v, "byteOffset", p);
        c.size(v, "byteLength", p, true);
        c.size(v, "byteStride", p);
    });
    c.objects(root, "buffers", [&](const json& b, const std::string& p) {
        c.size(b, "byteLength", p, true);
        if (b["byteLength"].get<std::uint64_t>() == 0) {
            c.fail(ModelIssue::OutOfBounds, at(p, "byteLength"), "an empty buffer (the minimum is 1 byte)");
        }
        c.string(b, "uri", p);
    });
    c.objects(root, "materials", [&](const json& m, const std::string& p) { checkMaterial(c, m, p); });
    c.objects(root, "textures", [&](const json& t, const std::string& p) {
        c.index(t, "source", p);
        c.index(t, "sampler", p);
    });
    c.objects(root, "images", [&](const json& i, const std::string& p) {
        c.string(i, "uri", p);
        c.index(i, "bufferView", p);
        c.string(i, "mimeType", p);
    });
    c.objects(root, "samplers", [&](const json& s, const std::string& p) {
        for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"}) {
            c.index(s, key, p);
        }
    });
    checkBufferViewRanges(c, root);
    checkImageViews(c, root);
}

} // namespace photopic::orbit::detail
