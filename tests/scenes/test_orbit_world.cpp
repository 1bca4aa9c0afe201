// The orbit scene's CPU side: the planet's occlusion of the sun (a penumbra between full light and the
// umbra), the script (sun, eclipse, camera, ship orientation) and the ship built in code (valid geometry,
// distinct materials, colour textures flagged sRGB and data textures linear).

#include "scenes/orbit/OrbitShip.h"
#include "scenes/orbit/OrbitWorld.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace photopic::orbit {

TEST(OrbitWorld, SunVisibilityHasAnUmbraAPenumbraAndFullLight) {
    const Planet planet{{0.0f, 0.0f, -1000.0f}, 100.0f};
    const glm::vec3 towards(0.0f, 0.0f, -1.0f);
    EXPECT_EQ(sunVisibility(planet, glm::vec3(0.0f), towards), 0.0f) << "the sun straight behind the centre";
    EXPECT_EQ(sunVisibility(planet, glm::vec3(0.0f), -towards), 1.0f) << "the planet behind the point";
    // The penumbra is 2 x 1000 x kSunAngularRadius = 40 m wide around the limb, centred on it.
    EXPECT_EQ(sunVisibility(planet, glm::vec3(79.0f, 0.0f, 0.0f), towards), 0.0f);
    EXPECT_NEAR(sunVisibility(planet, glm::vec3(100.0f, 0.0f, 0.0f), towards), 0.5f, 0.02f);
    EXPECT_EQ(sunVisibility(planet, glm::vec3(121.0f, 0.0f, 0.0f), towards), 1.0f);
    float previous = 0.0f;
    for (float x = 70.0f; x <= 130.0f; x += 1.0f) {
        const float v = sunVisibility(planet, glm::vec3(x, 0.0f, 0.0f), towards);
        EXPECT_GE(v, previous) << "monotone across the penumbra at x = " << x;
        previous = v;
    }
}

TEST(OrbitWorld, TheScriptEclipsesTheShipAndBringsTheSunBack) {
    const auto visible = [](double t) { return sunVisibility(kEarth, glm::vec3(0.0f), sunDirectionAt(t)); };
    EXPECT_EQ(visible(0.0), 1.0f);
    EXPECT_EQ(visible(3.5), 1.0f);
    EXPECT_EQ(visible(6.0), 0.0f);
    EXPECT_EQ(visible(kScriptSeconds), 1.0f);
    double start = -1.0;
    double end = -1.0;
    for (double t = 0.0; t <= kScriptSeconds; t += 0.01) {
        if (visible(t) < 0.5f && start < 0.0) {
            start = t;
        }
        if (visible(t) < 0.5f) {
            end = t;
        }
    }
    EXPECT_NEAR(start, 4.1, 0.3) << "the ship enters the shadow";
    EXPECT_NEAR(end, 8.1, 0.3) << "and leaves it";
}

TEST(OrbitWorld, TheSunAlwaysLightsTheHullsSideAndTheCameraFramesTheShip) {
    for (double t = 0.0; t <= kScriptSeconds; t += 0.5) {
        const glm::vec3 axis =
            glm::normalize(glm::vec3(shipTransform(t) * glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)));
        EXPECT_LT(std::abs(glm::dot(axis, sunDirectionAt(t))), 0.05f) << "t = " << t;
        const Camera c = orbitCamera(t, t, 14.0f, 160, 90);
        EXPECT_EQ(invalidCameraReason(c), nullptr);
        const glm::vec4 centre = c.viewProjection() * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        EXPECT_LT(glm::length(glm::vec2(centre) / centre.w), 1e-4f)
            << "the ship at the image centre, t = " << t;
    }
}

TEST(OrbitShip, IsValidGeometryWithDistinctMaterialsAndTaggedTextures) {
    const Model ship = buildShip();
    ASSERT_EQ(ship.meshes.size(), std::size_t(ShipPart::Count));
    EXPECT_GE(ship.materials.size(), 6u);
    std::set<std::string> names;
    for (const Material& m : ship.materials) {
        names.insert(m.name);
        for (const int t : {m.baseColorTexture, m.emissiveTexture}) {
            if (t >= 0) {
                EXPECT_TRUE(ship.textures[std::size_t(t)].srgb) << m.name << ": colour textures are sRGB";
            }
        }
        for (const int t : {m.normalTexture, m.metallicRoughnessTexture, m.occlusionTexture}) {
            if (t >= 0) {
                EXPECT_FALSE(ship.textures[std::size_t(t)].srgb) << m.name << ": data textures are linear";
            }
        }
    }
    EXPECT_EQ(names.size(), ship.materials.size());
    bool metal = false;
    bool dielectric = false;
    bool emissive = false;
    for (const Material& m : ship.materials) {
        metal = metal || m.metallicFactor == 1.0f;
        dielectric = dielectric || m.metallicFactor == 0.0f;
        emissive = emissive || m.emissiveTexture >= 0;
    }
    EXPECT_TRUE(metal && dielectric && emissive);
    for (const MeshInstance& mesh : ship.meshes) {
        for (const Primitive& p : mesh.primitives) {
            ASSERT_EQ(p.indices.size() % 3, 0u) << mesh.name;
            for (const std::uint32_t i : p.indices) {
                ASSERT_LT(i, p.vertices.size()) << mesh.name;
            }
            for (const Vertex& v : p.vertices) {
                ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f) << mesh.name;
                ASSERT_NEAR(std::abs(v.tangent.w), 1.0f, 0.0f) << mesh.name;
            }
            // Counter-clockwise front faces: the geometric normal agrees with the vertex normals.
            long agree = 0;
            for (std::size_t k = 0; k < p.indices.size(); k += 3) {
                const Vertex& a = p.vertices[p.indices[k]];
                const Vertex& b = p.vertices[p.indices[k + 1]];
                const Vertex& c = p.vertices[p.indices[k + 2]];
                const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
                agree += glm::dot(n, a.normal + b.normal + c.normal) >= 0.0f ? 1 : 0;
            }
            EXPECT_EQ(agree, long(p.indices.size() / 3))
                << mesh.name << ": triangles wound against their normals";
        }
    }
    // Thin features: the truss rods are a few centimetres across a ship about 27 m wide.
    EXPECT_GT(ship.bounds.max.x - ship.bounds.min.x, 25.0f);
}

} // namespace photopic::orbit
