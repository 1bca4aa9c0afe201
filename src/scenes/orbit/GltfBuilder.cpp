// The glTF Builder (GltfBuilder.h): the node graph (parents, cycles, the scene's roots, transforms), the mesh
// instances placed by it, the output budget, and the whole build.
#include "scenes/orbit/GltfBuilder.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace photopic::orbit::detail {

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

} // namespace photopic::orbit::detail
