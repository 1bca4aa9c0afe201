#include "scenes/orbit/OrbitShip.h"

#include "core/Hash.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photopic::orbit {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

/// A point of a lathe profile: radius from the z axis and height along it.
struct RZ {
    float r;
    float z;
};

/// Revolves `profile` (one smooth polyline; separate calls give hard edges) about the z axis into `prim`,
/// with `segments` steps around. Normals come from the profile's slope, u runs around (uRepeat times), v
/// along the profile's length (vPerMetre). The tangent follows u and its w makes cross(N, T) w follow v.
void lathe(Primitive& prim, const std::vector<RZ>& profile, int segments, float uRepeat, float vPerMetre,
           glm::vec3 offset = glm::vec3(0.0f)) {
    const std::uint32_t base = std::uint32_t(prim.vertices.size());
    const int n = int(profile.size());
    std::vector<float> along(std::size_t(n), 0.0f);
    for (int i = 1; i < n; ++i) {
        along[std::size_t(i)] =
            along[std::size_t(i - 1)] + std::hypot(profile[std::size_t(i)].r - profile[std::size_t(i - 1)].r,
                                                   profile[std::size_t(i)].z - profile[std::size_t(i - 1)].z);
    }
    for (int i = 0; i < n; ++i) {
        const RZ a = profile[std::size_t(std::max(i - 1, 0))];
        const RZ b = profile[std::size_t(std::min(i + 1, n - 1))];
        // Outward normal of the profile's direction (dr, dz) in the (r, z) plane: (dz, -dr).
        const glm::vec2 nrz = glm::normalize(glm::vec2(b.z - a.z, -(b.r - a.r)));
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2.0f * kPi * float(s) / float(segments);
            const float c = std::cos(phi);
            const float sn = std::sin(phi);
            Vertex v;
            v.position = offset + glm::vec3(profile[std::size_t(i)].r * c, profile[std::size_t(i)].r * sn,
                                            profile[std::size_t(i)].z);
            v.normal = glm::normalize(glm::vec3(nrz.x * c, nrz.x * sn, nrz.y));
            v.texCoord = glm::vec2(uRepeat * float(s) / float(segments), along[std::size_t(i)] * vPerMetre);
            const glm::vec3 t(-sn, c, 0.0f);
            const glm::vec3 dPdv = glm::vec3(b.r - a.r, 0.0f, b.z - a.z); // profile direction, rotated below
            const glm::vec3 dv(dPdv.x * c, dPdv.x * sn, dPdv.z);
            v.tangent = glm::vec4(t, glm::dot(glm::cross(v.normal, t), dv) >= 0.0f ? 1.0f : -1.0f);
            prim.vertices.push_back(v);
        }
    }
    const std::uint32_t ring = std::uint32_t(segments + 1);
    for (int i = 0; i + 1 < n; ++i) {
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = base + std::uint32_t(i) * ring + std::uint32_t(s);
            const std::uint32_t b = a + ring;
            // Counter-clockwise seen from outside: (a, a + 1, b + 1), (a, b + 1, b).
            prim.indices.insert(prim.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
        }
    }
}

/// An axis-aligned box, its faces textured once each (uvPerMetre texels scale).
void box(Primitive& prim, glm::vec3 centre, glm::vec3 half, float uvPerMetre) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = -1; side <= 1; side += 2) {
            glm::vec3 n(0.0f);
            n[axis] = float(side);
            const int ua = (axis + 1) % 3;
            const int va = (axis + 2) % 3;
            glm::vec3 u(0.0f), w(0.0f);
            u[ua] = 1.0f;
            w[va] = 1.0f;
            if (side < 0) {
                std::swap(u, w); // keep u x w == n so the face winds counter-clockwise from outside
            }
            const std::uint32_t base = std::uint32_t(prim.vertices.size());
            for (int k = 0; k < 4; ++k) {
                const float su = (k == 1 || k == 2) ? 1.0f : -1.0f;
                const float sw = (k >= 2) ? 1.0f : -1.0f;
                Vertex v;
                v.position = centre + half * (n + su * u + sw * w);
                v.normal = n;
                const float lu = glm::dot(half, glm::abs(u));
                const float lw = glm::dot(half, glm::abs(w));
                v.texCoord =
                    glm::vec2((su * 0.5f + 0.5f) * 2.0f * lu, (sw * 0.5f + 0.5f) * 2.0f * lw) * uvPerMetre;
                v.tangent = glm::vec4(u, glm::dot(glm::cross(n, u), w) >= 0.0f ? 1.0f : -1.0f);
                prim.vertices.push_back(v);
            }
            prim.indices.insert(prim.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
}

/// A thin rod from `a` to `b` (a capped cylinder of radius r), e.g. a truss member.
void rod(Primitive& prim, glm::vec3 a, glm::vec3 b, float r) {
    Primitive local;
    const float length = glm::length(b - a);
    lathe(local, {{0.0f, 0.0f}, {r, 0.0f}}, 6, 1.0f, 1.0f);
    lathe(local, {{r, 0.0f}, {r, length}}, 6, 1.0f, 1.0f);
    lathe(local, {{r, length}, {0.0f, length}}, 6, 1.0f, 1.0f);
    // Rotate local z onto b - a.
    const glm::vec3 d = (b - a) / length;
    const glm::vec3 helper = std::abs(d.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 x = glm::normalize(glm::cross(helper, d));
    const glm::vec3 y = glm::cross(d, x);
    const glm::mat3 m(x, y, d);
    const std::uint32_t base = std::uint32_t(prim.vertices.size());
    for (Vertex v : local.vertices) {
        v.position = a + m * v.position;
        v.normal = m * v.normal;
        v.tangent = glm::vec4(m * glm::vec3(v.tangent), v.tangent.w);
        prim.vertices.push_back(v);
    }
    for (std::uint32_t i : local.indices) {
        prim.indices.push_back(base + i);
    }
}

/// A circle in the (r, z) plane as a closed profile (a torus when revolved).
std::vector<RZ> circleProfile(float r0, float z0, float a, int steps) {
    std::vector<RZ> p;
    for (int i = 0; i <= steps; ++i) {
        const float t = -kPi + 2.0f * kPi * float(i) / float(steps);
        // Counter-clockwise in (r, z) keeps the normal (dz, -dr) pointing out of the tube.
        p.push_back({r0 + a * std::cos(t), z0 + a * std::sin(t)});
    }
    return p;
}

float hashUnit(std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0) {
    return float(hash32(a * 73856093u ^ b * 19349663u ^ c * 83492791u) & 0xffffffu) / float(0xffffff);
}

TextureImage image(std::string name, int w, int h) {
    TextureImage img;
    img.name = std::move(name);
    img.width = w;
    img.height = h;
    img.rgba.assign(std::size_t(w) * std::size_t(h) * 4, 255);
    return img;
}

void put(TextureImage& img, int x, int y, glm::vec3 v01, float a = 1.0f) {
    std::uint8_t* p = &img.rgba[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
    const glm::vec3 c = glm::clamp(v01, 0.0f, 1.0f) * 255.0f + 0.5f;
    p[0] = std::uint8_t(c.r);
    p[1] = std::uint8_t(c.g);
    p[2] = std::uint8_t(c.b);
    p[3] = std::uint8_t(std::clamp(a, 0.0f, 1.0f) * 255.0f + 0.5f);
}

/// Distance in texels to the nearest seam of a square panel grid of `cell` texels.
float seamDistance(int x, int y, int cell) {
    const auto d = [&](int v) { return float(std::min(v % cell, cell - 1 - v % cell)); };
    return std::min(d(x), d(y));
}

// The hull's panels: 64-texel panels, 2-texel seams. Colour (sRGB): off-white paint, panel to panel tint.
TextureImage hullColour() {
    TextureImage img = image("hull base colour", 256, 256);
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const float tint = 0.9f + 0.1f * hashUnit(std::uint32_t(x / 64), std::uint32_t(y / 64), 1);
            const float seam = seamDistance(x, y, 64) < 1.5f ? 0.55f : 1.0f;
            put(img, x, y, glm::vec3(0.84f, 0.84f, 0.81f) * tint * seam);
        }
    }
    return img;
}

// Data (linear): the seams as grooves (normal), occlusion in them (R), roughness per panel (G), metallic (B).
TextureImage hullNormal() {
    TextureImage img = image("hull normal", 256, 256);
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            glm::vec3 n(0.0f, 0.0f, 1.0f);
            const int mx = x % 64;
            const int my = y % 64;
            // Bevelled edges 3 texels wide lean away from the seam.
            if (mx < 3)
                n.x -= 0.5f;
            if (mx > 60)
                n.x += 0.5f;
            if (my < 3)
                n.y -= 0.5f;
            if (my > 60)
                n.y += 0.5f;
            put(img, x, y, glm::normalize(n) * 0.5f + 0.5f);
        }
    }
    return img;
}

TextureImage hullOrm() {
    TextureImage img = image("hull occlusion-roughness-metallic", 256, 256);
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const float seam = seamDistance(x, y, 64);
            const float occlusion = seam < 1.5f ? 0.5f : (seam < 4.0f ? 0.8f : 1.0f);
            const float roughness = 0.35f + 0.25f * hashUnit(std::uint32_t(x / 64), std::uint32_t(y / 64), 2);
            put(img, x, y, glm::vec3(occlusion, roughness, 0.0f));
        }
    }
    return img;
}

// Gold foil: crinkles as random facets on a 16-texel lattice (data, linear).
TextureImage foilNormal() {
    TextureImage img = image("foil normal", 128, 128);
    for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
            const std::uint32_t cx = std::uint32_t(x / 8);
            const std::uint32_t cy = std::uint32_t(y / 8);
            const float ax = hashUnit(cx, cy, 3) * 2.0f - 1.0f;
            const float ay = hashUnit(cx, cy, 4) * 2.0f - 1.0f;
            put(img, x, y, glm::normalize(glm::vec3(0.45f * ax, 0.45f * ay, 1.0f)) * 0.5f + 0.5f);
        }
    }
    return img;
}

// Solar cells (sRGB): dark blue cells in a silver grid, thin fingers across each cell.
TextureImage solarColour() {
    TextureImage img = image("solar cells", 256, 256);
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const bool grid = x % 32 < 2 || y % 32 < 2;
            const bool finger = y % 8 == 4;
            const glm::vec3 cell = glm::vec3(0.04f, 0.06f, 0.20f) *
                                   (0.9f + 0.2f * hashUnit(std::uint32_t(x / 32), std::uint32_t(y / 32), 5));
            put(img, x, y, grid ? glm::vec3(0.70f) : (finger ? glm::vec3(0.30f) : cell));
        }
    }
    return img;
}

// Window lights (sRGB emissive): warm squares on black.
TextureImage lightsEmissive() {
    TextureImage img = image("window lights", 64, 16);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 64; ++x) {
            const bool lit = x % 16 >= 3 && x % 16 < 13 && y >= 4 && y < 12;
            put(img, x, y, lit ? glm::vec3(1.0f, 0.78f, 0.45f) : glm::vec3(0.0f));
        }
    }
    return img;
}

int addTexture(Model& m, TextureImage img, bool srgb) {
    m.images.push_back(std::move(img));
    ModelTexture t;
    t.image = int(m.images.size()) - 1;
    t.srgb = srgb;
    m.textures.push_back(t);
    return int(m.textures.size()) - 1;
}

int addMaterial(Model& m, Material mat) {
    m.materials.push_back(std::move(mat));
    return int(m.materials.size()) - 1;
}

void addInstance(Model& m, std::string name, Primitive prim) {
    MeshInstance inst;
    inst.name = std::move(name);
    inst.node = int(m.meshes.size());
    inst.mesh = int(m.meshes.size());
    for (const Vertex& v : prim.vertices) {
        inst.bounds.add(v.position);
    }
    prim.hasTexCoords = true;
    prim.hasTangents = true;
    m.bounds.add(inst.bounds);
    inst.primitives.push_back(std::move(prim));
    m.meshes.push_back(std::move(inst));
}

/// The ship's materials, in ShipPart order, with their procedural textures.
struct ShipMaterials {
    Material hull, foil, solar, truss, bell, ring, lights;
};

ShipMaterials shipMaterials(Model& m) {
    ShipMaterials s;
    s.hull = {.name = "hull panels", .metallicFactor = 1.0f, .roughnessFactor = 1.0f};
    s.hull.baseColorTexture = addTexture(m, hullColour(), true);
    s.hull.normalTexture = addTexture(m, hullNormal(), false);
    s.hull.metallicRoughnessTexture = addTexture(m, hullOrm(), false);
    s.hull.occlusionTexture = s.hull.metallicRoughnessTexture; // R of the same data texture
    s.foil = {.name = "gold MLI foil",
              .baseColorFactor = {1.0f, 0.77f, 0.34f, 1.0f},
              .metallicFactor = 1.0f,
              .roughnessFactor = 0.3f};
    s.foil.normalTexture = addTexture(m, foilNormal(), false);
    s.solar = {.name = "solar cells", .metallicFactor = 0.0f, .roughnessFactor = 0.18f, .doubleSided = true};
    s.solar.baseColorTexture = addTexture(m, solarColour(), true);
    s.truss = {.name = "truss",
               .baseColorFactor = {0.55f, 0.55f, 0.56f, 1.0f},
               .metallicFactor = 0.8f,
               .roughnessFactor = 0.45f};
    s.bell = {.name = "engine bell",
              .baseColorFactor = {0.30f, 0.28f, 0.27f, 1.0f},
              .metallicFactor = 1.0f,
              .roughnessFactor = 0.42f,
              .doubleSided = true};
    s.ring = {.name = "docking ring",
              .baseColorFactor = {0.91f, 0.92f, 0.92f, 1.0f},
              .metallicFactor = 1.0f,
              .roughnessFactor = 0.16f};
    s.lights = {.name = "window lights",
                .baseColorFactor = {0.02f, 0.02f, 0.02f, 1.0f},
                .metallicFactor = 0.0f,
                .roughnessFactor = 0.5f,
                .emissiveFactor = {6.0f, 6.0f, 6.0f}};
    s.lights.emissiveTexture = addTexture(m, lightsEmissive(), true);
    return s;
}

/// The hull (a cylinder with a rounded nose) and the foil-wrapped service module behind it. Profiles run
/// counter-clockwise in the (r, z) plane (out along the bottom, up the side, in across the top) so that the
/// revolved normals point out of the solid.
void addHullAndFoil(Model& m, const ShipMaterials& s) {
    Primitive p;
    p.material = addMaterial(m, s.hull);
    lathe(p, {{0.0f, -2.0f}, {1.4f, -2.0f}}, 32, 8.0f, 0.25f);
    lathe(p, {{1.4f, -2.0f}, {1.4f, 3.6f}}, 32, 8.0f, 0.25f);
    lathe(p, {{1.4f, 3.6f}, {1.0f, 4.0f}, {0.0f, 4.0f}}, 32, 8.0f, 0.25f);
    addInstance(m, "hull", std::move(p));

    p = {};
    p.material = addMaterial(m, s.foil);
    lathe(p, {{0.0f, -5.0f}, {1.6f, -5.0f}}, 32, 6.0f, 0.6f);
    lathe(p, {{1.6f, -5.0f}, {1.6f, -2.0f}}, 32, 6.0f, 0.6f);
    lathe(p, {{1.6f, -2.0f}, {0.0f, -2.0f}}, 32, 6.0f, 0.6f);
    addInstance(m, "MLI foil", std::move(p));
}

/// Two solar arrays on booms, their frames and cross members as rods 2 to 6 cm thick.
void addArraysAndTruss(Model& m, const ShipMaterials& s) {
    Primitive p;
    p.material = addMaterial(m, s.solar);
    for (const float side : {-1.0f, 1.0f}) {
        box(p, glm::vec3(side * 8.0f, 0.0f, -3.5f), glm::vec3(5.0f, 0.03f, 1.3f), 0.5f);
    }
    addInstance(m, "solar arrays", std::move(p));

    p = {};
    p.material = addMaterial(m, s.truss);
    for (const float side : {-1.0f, 1.0f}) {
        rod(p, glm::vec3(side * 1.5f, 0.0f, -3.5f), glm::vec3(side * 13.0f, 0.0f, -3.5f), 0.06f);
        for (const float edge : {-1.33f, 1.33f}) {
            rod(p, glm::vec3(side * 3.0f, 0.0f, -3.5f + edge), glm::vec3(side * 13.0f, 0.0f, -3.5f + edge),
                0.025f);
        }
        for (int i = 0; i <= 5; ++i) {
            const float x = side * (3.0f + 2.0f * float(i));
            rod(p, glm::vec3(x, 0.0f, -4.83f), glm::vec3(x, 0.0f, -2.17f), 0.02f);
        }
    }
    addInstance(m, "truss", std::move(p));
}

/// Three engine bells (open, seen inside and out), the docking ring and tunnel, two strips of windows.
void addBellsRingAndLights(Model& m, const ShipMaterials& s) {
    Primitive p;
    p.material = addMaterial(m, s.bell);
    const std::vector<RZ> bellProfile = {{0.62f, -7.0f}, {0.42f, -6.2f}, {0.28f, -5.4f}, {0.25f, -5.0f}};
    for (const glm::vec3 at : {glm::vec3(0.0f), glm::vec3(0.9f, 0.0f, 0.0f), glm::vec3(-0.9f, 0.0f, 0.0f)}) {
        lathe(p, bellProfile, 24, 4.0f, 1.0f, at);
    }
    addInstance(m, "engine bells", std::move(p));

    p = {};
    p.material = addMaterial(m, s.ring);
    lathe(p, circleProfile(0.85f, 4.15f, 0.12f, 12), 32, 8.0f, 2.0f);
    lathe(p, {{0.6f, 4.0f}, {0.6f, 4.35f}}, 32, 8.0f, 2.0f);
    lathe(p, {{0.6f, 4.35f}, {0.0f, 4.35f}}, 32, 8.0f, 2.0f);
    addInstance(m, "docking ring", std::move(p));

    p = {};
    p.material = addMaterial(m, s.lights);
    box(p, glm::vec3(0.0f, 1.41f, 1.5f), glm::vec3(0.25f, 0.02f, 1.0f), 0.5f);
    box(p, glm::vec3(0.0f, -1.41f, 1.5f), glm::vec3(0.25f, 0.02f, 1.0f), 0.5f);
    addInstance(m, "window lights", std::move(p));
}

} // namespace

Model buildShip() {
    Model m;
    const ShipMaterials materials = shipMaterials(m);
    addHullAndFoil(m, materials);
    addArraysAndTruss(m, materials);
    addBellsRingAndLights(m, materials);
    return m;
}

} // namespace photopic::orbit
