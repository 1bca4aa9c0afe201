// The glTF Builder's accessors and primitives (GltfBuilder.h): every accessor checked against its buffer,
// indices read and triangulated, vertices filled and placed, flat normals where a primitive has none.
#include "scenes/orbit/GltfBuilder.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <optional>

namespace photopic::orbit::detail {

namespace {

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

constexpr AccessorUse kPosition{"POSITION", TINYGLTF_TYPE_VEC3};
constexpr AccessorUse kNormal{"NORMAL", TINYGLTF_TYPE_VEC3};
constexpr AccessorUse kTangent{"TANGENT", TINYGLTF_TYPE_VEC4};
constexpr AccessorUse kTexCoord{"TEXCOORD_0", TINYGLTF_TYPE_VEC2, false, true};
constexpr AccessorUse kIndices{"indices", TINYGLTF_TYPE_SCALAR, true};

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

} // namespace

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

} // namespace photopic::orbit::detail
