// The orbit scene's sun shadow map against a CPU ray cast to the sun. The test draws its own scene, every
// object a caster and a receiver: a 4 m plate whose top is y = 0, a 1 m box standing on it (turned 20
// degrees), a 4 cm pole 1.5 m tall and a 1 cm panel standing on edge (a thin feature).
// ShadowMap::drawVisibility gives each camera pixel's sun visibility and world position; the CPU casts the
// same camera ray and, from the hit, a ray to the sun.
//
// Classification: a pixel counts when the CPU's hit and the rasterised position agree (no silhouette pixel)
// and its surface faces the sun (normal . sun > 0.05). It is shadowed in truth when the ray to the sun hits
// another object (the objects are convex: none shadows itself on a sun-facing face), rendered shadowed when
// the visibility is below 0.5. Its distance from the true shadow boundary, in shadow texels, is how far its
// ray to the sun must move across the light's plane (16 directions) before it changes between hit and miss.

#include "GlTest.h"

#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "scenes/SceneSettings.h"
#include "scenes/orbit/OrbitShadowMap.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace photopic::test {

namespace {

using orbit::ShadowBounds;
using orbit::ShadowMap;
using orbit::ShadowSettings;

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kFacing = 0.05f;
constexpr float kShadowed = 0.5f;
constexpr float kPi = 3.14159265f;

struct Box {
    glm::mat4 model;
    glm::mat4 inverse;
    glm::mat3 normalMatrix;
};

Box makeBox(glm::vec3 center, glm::vec3 size, float yawDegrees) {
    const glm::mat4 m = glm::scale(
        glm::rotate(glm::translate(glm::mat4(1.0f), center), glm::radians(yawDegrees), glm::vec3(0, 1, 0)),
        size);
    return {m, glm::inverse(m), glm::transpose(glm::inverse(glm::mat3(m)))};
}

enum Object { kPlate, kBox, kPole, kPanel };

/// The scene, object by object in `Object` order: unit cubes scaled, turned and placed.
std::vector<Box> sceneBoxes() {
    return {makeBox({0, -0.05f, 0}, {4, 0.1f, 4}, 0), makeBox({0, 0.5f, 0}, {1, 1, 1}, 20),
            makeBox({1.1f, 0.75f, -0.7f}, {0.04f, 1.5f, 0.04f}, 0),
            makeBox({-1.0f, 0.3f, 0.9f}, {0.8f, 0.6f, 0.01f}, 0)};
}

ShadowBounds sceneBounds() {
    return ShadowBounds::aroundBox({-2, -0.1f, -2}, {2, 1.5f, 2});
}

struct Hit {
    float t = 0.0f;
    glm::vec3 normal{0.0f};
    int object = -1;
};

/// Ray against one unit cube in its own space (slab test); the normal of the face it enters.
std::optional<Hit> castBox(const Box& box, glm::vec3 origin, glm::vec3 dir) {
    const glm::vec3 o = glm::vec3(box.inverse * glm::vec4(origin, 1.0f));
    const glm::vec3 d = glm::vec3(box.inverse * glm::vec4(dir, 0.0f));
    float tNear = -1e30f, tFar = 1e30f;
    int axis = 0;
    float sign = 1.0f;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12f) {
            if (std::abs(o[a]) > 0.5f) {
                return std::nullopt;
            }
            continue;
        }
        float t0 = (-0.5f - o[a]) / d[a], t1 = (0.5f - o[a]) / d[a];
        const float enterSign = t0 < t1 ? -1.0f : 1.0f;
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        if (t0 > tNear) {
            tNear = t0;
            axis = a;
            sign = enterSign;
        }
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar || tFar < 0.0f) {
        return std::nullopt;
    }
    glm::vec3 n(0.0f);
    n[axis] = sign;
    return Hit{tNear, glm::normalize(box.normalMatrix * n), 0};
}

std::optional<Hit> castScene(const std::vector<Box>& boxes, glm::vec3 origin, glm::vec3 dir) {
    std::optional<Hit> best;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (auto h = castBox(boxes[i], origin, dir); h && h->t > 0.0f && (!best || h->t < best->t)) {
            best = h;
            best->object = int(i);
        }
    }
    return best;
}

/// Whether the ray from `p` towards the sun hits an object other than `self`.
bool occluded(const std::vector<Box>& boxes, glm::vec3 p, glm::vec3 toSun, int self) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (int(i) == self) {
            continue;
        }
        if (auto h = castBox(boxes[i], p, toSun); h && h->t > 0.0f) {
            return true;
        }
        // A ray that starts inside another object is blocked by it.
        const glm::vec3 local = glm::vec3(boxes[i].inverse * glm::vec4(p, 1.0f));
        if (glm::all(glm::lessThanEqual(glm::abs(local), glm::vec3(0.5f)))) {
            return true;
        }
    }
    return false;
}

/// Texels the ray to the sun from `p` must move across the light's plane before hit and miss swap,
/// capped at `cap` (the nearest of 16 directions, found to a 1/32 texel).
float boundaryDistance(const std::vector<Box>& boxes, glm::vec3 p, int self,
                       const orbit::ShadowProjection& lp, float cap) {
    const bool here = occluded(boxes, p, lp.toSun, self);
    float best = cap;
    for (int k = 0; k < 16; ++k) {
        const float a = 2.0f * kPi * float(k) / 16.0f;
        const glm::vec3 dir = std::cos(a) * lp.right + std::sin(a) * lp.up;
        const auto differs = [&](float texels) {
            return occluded(boxes, p + dir * texels * lp.texelSize, lp.toSun, self) != here;
        };
        for (float s = 0.25f; s < best; s += 0.25f) {
            if (differs(s)) {
                float lo = s - 0.25f, hi = s;
                for (int i = 0; i < 3; ++i) {
                    const float mid = 0.5f * (lo + hi);
                    (differs(mid) ? hi : lo) = mid;
                }
                best = std::min(best, hi);
                break;
            }
        }
    }
    return best;
}

/// The test scene on the GPU: one unit cube drawn once per object with its model matrix.
class GlScene {
public:
    GlScene()
        : mVao(VertexArray::create("shadow test cube")) {
        static const int kCorners[36] = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                         2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
        std::vector<glm::vec3> positions;
        for (int c : kCorners) {
            positions.emplace_back(float(c & 1) - 0.5f, float((c >> 1) & 1) - 0.5f,
                                   float((c >> 2) & 1) - 0.5f);
        }
        mPositions = Buffer({.size = positions.size() * sizeof(glm::vec3),
                             .flags = 0,
                             .data = positions.data(),
                             .debugName = "shadow test cube"});
        glVertexArrayVertexBuffer(mVao.id(), 0, mPositions.id(), 0, sizeof(glm::vec3));
        glEnableVertexArrayAttrib(mVao.id(), 0);
        glVertexArrayAttribFormat(mVao.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(mVao.id(), 0, 0);
    }

    [[nodiscard]] orbit::ShadowCasterDraws draws(const std::vector<Box>& boxes) const {
        return [this, &boxes](const orbit::ShadowCasterPass& pass) {
            glBindVertexArray(mVao.id());
            for (const Box& b : boxes) {
                pass.setModel(b.model);
                glDrawArrays(GL_TRIANGLES, 0, 36);
            }
        };
    }

private:
    VertexArray mVao;
    Buffer mPositions;
};

struct View {
    glm::vec3 eye;
    glm::vec3 target;
    float fovDegrees = 45.0f;

    [[nodiscard]] glm::mat4 viewProjection() const {
        return glm::perspective(glm::radians(fovDegrees), float(kW) / float(kH), 0.05f, 50.0f) *
               glm::lookAt(eye, target, glm::vec3(0, 1, 0));
    }
};

/// One camera image: visibility (R) and world position (xyz, w = 1 where an object was drawn).
struct Frame {
    ImageF visibility;
    ImageF world;
};

class CameraTarget {
public:
    CameraTarget()
        : mVisibility({.extent = {kW, kH}, .format = GL_RGBA32F, .debugName = "shadow test visibility"})
        , mWorld({.extent = {kW, kH}, .format = GL_RGBA32F, .debugName = "shadow test world"})
        , mDepth({.extent = {kW, kH}, .format = GL_DEPTH_COMPONENT32F, .debugName = "shadow test depth"})
        , mTarget({.color = {&mVisibility, &mWorld}, .depth = &mDepth, .debugName = "shadow test camera"}) {}

    Frame draw(const ShadowMap& map, const View& view, const orbit::ShadowCasterDraws& draws) const {
        const float zero[4] = {0, 0, 0, 0};
        const float far = 1.0f;
        glClearNamedFramebufferfv(mTarget.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(mTarget.id(), GL_COLOR, 1, zero);
        glClearNamedFramebufferfv(mTarget.id(), GL_DEPTH, 0, &far);
        mTarget.bind();
        map.drawVisibility(view.viewProjection(), draws);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return {readTextureF(mVisibility), readTextureF(mWorld)};
    }

private:
    Texture mVisibility, mWorld, mDepth;
    Framebuffer mTarget;
};

/// A classified pixel (see the file's opening comment).
struct Pixel {
    int x = 0, y = 0;
    int object = -1;
    glm::vec3 position{0.0f}, normal{0.0f};
    bool truthShadowed = false;
    bool renderedShadowed = false;
    float visibility = 1.0f;
    float edgeTexels = 0.0f; ///< distance from the true boundary, capped
};

/// The pixels of `frame` that count, with their truth; rows top to bottom like the images.
std::vector<Pixel> classify(const std::vector<Box>& boxes, const View& view, const Frame& frame,
                            const orbit::ShadowProjection& lp, float edgeCap) {
    const glm::mat4 inverse = glm::inverse(view.viewProjection());
    std::vector<Pixel> pixels;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float* w = frame.world.rgba.data() + (std::size_t(y) * kW + std::size_t(x)) * 4;
            if (w[3] == 0.0f) {
                continue;
            }
            const float ndcX = (float(x) + 0.5f) / float(kW) * 2.0f - 1.0f;
            const float ndcY = (float(kH - 1 - y) + 0.5f) / float(kH) * 2.0f - 1.0f;
            const glm::vec4 farPoint = inverse * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
            const glm::vec3 dir = glm::normalize(glm::vec3(farPoint) / farPoint.w - view.eye);
            const auto hit = castScene(boxes, view.eye, dir);
            const glm::vec3 gl(w[0], w[1], w[2]);
            if (!hit || glm::distance(view.eye + dir * hit->t, gl) > 1e-3f * (1.0f + hit->t)) {
                continue;
            }
            if (glm::dot(hit->normal, lp.toSun) <= kFacing) {
                continue;
            }
            Pixel p;
            p.x = x;
            p.y = y;
            p.object = hit->object;
            p.position = view.eye + dir * hit->t;
            p.normal = hit->normal;
            p.truthShadowed = occluded(boxes, p.position, lp.toSun, p.object);
            p.visibility = frame.visibility.rgba[(std::size_t(y) * kW + std::size_t(x)) * 4];
            p.renderedShadowed = p.visibility < kShadowed;
            p.edgeTexels = boundaryDistance(boxes, p.position, p.object, lp, edgeCap);
            pixels.push_back(p);
        }
    }
    return pixels;
}

glm::vec3 sunAt(float elevationDegrees, float azimuthDegrees) {
    const float e = glm::radians(elevationDegrees), a = glm::radians(azimuthDegrees);
    return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

/// The box's +x face normal (it is turned 20 degrees about y) and a sun 84 degrees from it, 40 degrees up
/// along the face: the face is lit at a grazing angle (normal . sun = 0.1).
glm::vec3 grazingSun(glm::vec3& faceNormal) {
    faceNormal = glm::normalize(glm::vec3(sceneBoxes()[kBox].normalMatrix * glm::vec3(1, 0, 0)));
    const glm::vec3 along = glm::normalize(glm::cross(faceNormal, glm::vec3(0, 1, 0)));
    const glm::vec3 inFace =
        std::cos(glm::radians(40.0f)) * along + std::sin(glm::radians(40.0f)) * glm::vec3(0, 1, 0);
    return 0.1f * faceNormal + std::sqrt(1.0f - 0.01f) * inFace;
}

ShadowSettings testSettings(int resolution) {
    ShadowSettings s;
    s.resolution = resolution;
    return s;
}

/// The GL side of the tests, made once a context is known to exist.
struct Rig {
    GlScene scene;
    CameraTarget camera;
    ShadowMap map;
};

class OrbitShadowTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (!IsSkipped()) {
            mRig = std::make_unique<Rig>();
        }
    }

    std::vector<Box> mBoxes = sceneBoxes();
    std::unique_ptr<Rig> mRig;

    void renderMap(glm::vec3 toSun, const ShadowSettings& settings, bool snap = true,
                   ShadowBounds bounds = sceneBounds()) {
        mRig->map.render({.sunDirection = toSun,
                          .bounds = bounds,
                          .settings = &settings,
                          .drawCasters = mRig->scene.draws(mBoxes),
                          .snap = snap});
    }
    Frame draw(const View& view) { return mRig->camera.draw(mRig->map, view, mRig->scene.draws(mBoxes)); }
};

} // namespace

TEST(OrbitShadowSettings, BadValuesAreRejectedWithTheirKey) {
    const auto expectIssue = [](const char* assignment, SettingsIssueCode code, const char* path) {
        ShadowSettings s;
        const auto issues = applySceneOverride(s, "orbit.shadow", assignment);
        ASSERT_EQ(issues.size(), 1u) << assignment;
        EXPECT_EQ(issues[0].code, code) << assignment;
        EXPECT_EQ(issues[0].path, path) << assignment;
        EXPECT_EQ(s.resolution, ShadowSettings{}.resolution) << "settings changed despite the issue";
    };
    expectIssue("resolution=1000", SettingsIssueCode::Constraint, "orbit.shadow.resolution");
    expectIssue("resolution=16384", SettingsIssueCode::OutOfRange, "orbit.shadow.resolution");
    expectIssue("samples=0", SettingsIssueCode::OutOfRange, "orbit.shadow.samples");
    expectIssue("softness=-1", SettingsIssueCode::OutOfRange, "orbit.shadow.softness");
    expectIssue("normalBias=17", SettingsIssueCode::OutOfRange, "orbit.shadow.normalBias");
    expectIssue("slopeBias=\"a\"", SettingsIssueCode::WrongType, "orbit.shadow.slopeBias");
    expectIssue("constantBias=1e40", SettingsIssueCode::OutOfRange, "orbit.shadow.constantBias");
    expectIssue("enabled=2", SettingsIssueCode::WrongType, "orbit.shadow.enabled");
    ShadowSettings s;
    EXPECT_TRUE(applySceneOverride(s, "orbit.shadow", "resolution=1024").empty());
    EXPECT_EQ(s.resolution, 1024);
}

TEST(OrbitShadowSettings, PoissonDiscPrefixesAreSpreadOut) {
    const auto& disc = orbit::shadowPoissonDisc();
    EXPECT_EQ(disc[0], glm::vec2(0.0f));
    for (int n : {4, 8, 16, 32}) {
        float nearest = 1e9f;
        for (int i = 0; i < n; ++i) {
            EXPECT_LE(glm::length(disc[std::size_t(i)]), 1.0f);
            for (int j = 0; j < i; ++j) {
                nearest = std::min(nearest, glm::distance(disc[std::size_t(i)], disc[std::size_t(j)]));
            }
        }
        // n points of a disc of radius 1 packed evenly are about 1.9 / sqrt(n) apart; a random set's
        // closest pair is far closer. Half of the even spacing is required of every prefix.
        std::printf("poisson disc: first %d points, closest pair %.3f (even packing ~%.3f)\n", n, nearest,
                    1.9 / std::sqrt(double(n)));
        EXPECT_GT(nearest, 0.5f * 1.9f / std::sqrt(float(n))) << n;
    }
}

TEST_F(OrbitShadowTest, BadInputThrowsNamingIt) {
    const ShadowSettings settings = testSettings(256);
    EXPECT_THROW(renderMap(glm::vec3(0.0f), settings), std::invalid_argument);
    EXPECT_THROW(renderMap(glm::vec3(NAN, 1, 0), settings), std::invalid_argument);
    EXPECT_THROW(renderMap({0, 1, 0}, settings, true, {{0, 0, 0}, 0.0f}), std::invalid_argument);
    EXPECT_THROW(renderMap({0, 1, 0}, settings, true, {{INFINITY, 0, 0}, 1.0f}), std::invalid_argument);
    try {
        renderMap(glm::vec3(0.0f), settings);
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("sun direction"), std::string::npos) << e.what();
    }
}

namespace {

/// What one camera image says against the truth (the counts of the opening comment's classification).
struct Agreement {
    std::size_t pixels = 0;
    int lit = 0, acne = 0;             ///< lit pixels 2+ texels from a boundary; those rendered shadowed
    int litAll = 0, acneAll = 0;       ///< every lit pixel; those rendered shadowed
    int shadowInterior = 0, leaks = 0; ///< shadowed pixels 2+ texels from a boundary; those rendered lit
    int faceLit = 0, faceAcne = 0;     ///< `lit` and `acne` on the face whose normal is given
    int disagree = 0;                  ///< pixels whose rendered class is not the truth's

    [[nodiscard]] double acneFraction() const { return double(acne) / std::max(lit, 1); }
    [[nodiscard]] double disagreement() const {
        return double(disagree) / double(std::max<std::size_t>(pixels, 1));
    }
};

Agreement agreement(const std::vector<Pixel>& pixels, glm::vec3 faceNormal) {
    Agreement a;
    a.pixels = pixels.size();
    for (const Pixel& p : pixels) {
        a.disagree += p.truthShadowed != p.renderedShadowed ? 1 : 0;
        if (!p.truthShadowed) {
            ++a.litAll;
            a.acneAll += p.renderedShadowed ? 1 : 0;
        }
        // Interior: at least 2 texels from the true boundary, beyond the filter's reach (the boundary's place
        // itself is what the contact test measures).
        if (p.edgeTexels < 2.0f) {
            continue;
        }
        if (!p.truthShadowed) {
            ++a.lit;
            a.acne += p.renderedShadowed ? 1 : 0;
            if (p.object == kBox && glm::dot(p.normal, faceNormal) > 0.999f) {
                ++a.faceLit;
                a.faceAcne += p.renderedShadowed ? 1 : 0;
            }
        } else {
            ++a.shadowInterior;
            a.leaks += p.renderedShadowed ? 0 : 1;
        }
    }
    return a;
}

} // namespace

// (a) and (d): no acne on lit faces, including a box face lit at a grazing angle and the plate under a low
// sun; no light leaking into shadows; and the agreement of the whole image with the truth. With every bias at
// 0 the same measure finds acne on about half of the lit pixels.
TEST_F(OrbitShadowTest, LitFacesHaveNoAcneAndTheImageAgreesWithTheTruth) {
    glm::vec3 faceNormal;
    const glm::vec3 grazing = grazingSun(faceNormal);
    struct Case {
        const char* name;
        glm::vec3 toSun;
        View view;
    };
    const Case cases[] = {
        {"high sun", sunAt(50, 25), {{-3.6f, 2.6f, 1.9f}, {-0.4f, 0.0f, -0.2f}}},
        {"low sun (plate lit at 78 degrees)", sunAt(12, 35), {{-4.0f, 2.2f, -0.3f}, {-0.3f, 0.0f, -0.4f}}},
        {"grazing face (84 degrees)",
         grazing,
         {glm::vec3(0, 0.5f, 0) + 3.0f * faceNormal + glm::vec3(0, 1.2f, 0) +
              0.8f * glm::normalize(glm::cross(faceNormal, glm::vec3(0, 1, 0))),
          {0, 0.4f, 0}}},
    };
    const ShadowSettings settings = testSettings(1024);
    const auto measure = [&](const Case& c, const ShadowSettings& s) {
        renderMap(c.toSun, s);
        return agreement(classify(mBoxes, c.view, draw(c.view), mRig->map.projection(), 3.0f), faceNormal);
    };
    for (const Case& c : cases) {
        const Agreement a = measure(c, settings);
        std::printf(
            "%s: %zu pixels; lit interior %d, shadowed %d (%.3f%%); lit overall %d, shadowed %d; shadow "
            "interior %d, lit %d; disagreement %.3f%%; grazing face lit %d, shadowed %d\n",
            c.name, a.pixels, a.lit, a.acne, 100.0 * a.acneFraction(), a.litAll, a.acneAll, a.shadowInterior,
            a.leaks, 100.0 * a.disagreement(), a.faceLit, a.faceAcne);
        EXPECT_GT(a.lit, 2000) << c.name;
        EXPECT_LE(a.acneFraction(), 0.005) << c.name;
        EXPECT_LE(double(a.leaks) / std::max(a.shadowInterior, 1), 0.005) << c.name;
        // Only pixels within the filter's reach of a boundary may disagree: a thin line of the image.
        EXPECT_LE(a.disagreement(), 0.01) << c.name;
        if (&c == &cases[2]) {
            EXPECT_GT(a.faceLit, 300);
            EXPECT_LE(double(a.faceAcne) / std::max(a.faceLit, 1), 0.005);
        }
    }
    ShadowSettings unbiased = settings;
    unbiased.constantBias = unbiased.normalBias = unbiased.slopeBias = 0.0f;
    const Agreement control = measure(cases[0], unbiased);
    std::printf("high sun, every bias 0: lit interior %d, shadowed %d (%.1f%%)\n", control.lit, control.acne,
                100.0 * control.acneFraction());
    EXPECT_GT(control.acneFraction(), 0.1) << "without bias the measure must find acne";
}

namespace {

/// Texels from `p` (on the plate) to the footprint of object `object` on the plate, across the plate.
float footprintDistance(const Box& box, glm::vec3 p, float texelSize) {
    const glm::vec3 local = glm::vec3(box.inverse * glm::vec4(p, 1.0f));
    const glm::vec3 nearest = glm::vec3(box.model * glm::vec4(glm::clamp(local.x, -0.5f, 0.5f), local.y,
                                                              glm::clamp(local.z, -0.5f, 0.5f), 1.0f));
    return glm::length(glm::vec2(p.x - nearest.x, p.z - nearest.z)) / texelSize;
}

struct ContactGap {
    int pixels = 0;    ///< plate pixels in the caster's shadow near its foot
    float gap = 0.0f;  ///< texels: the farthest of them from the foot that is rendered lit (0: none)
    int litPixels = 0; ///< how many are rendered lit
};

} // namespace

// (b): peter-panning at the contact of each caster with the plate: a close camera looks at the plate where
// the caster's shadow leaves its foot (about 0.5 shadow texel per pixel). Plate pixels within 12 texels of
// the foot that are in the caster's shadow, at least 2 texels from the shadow's sides, must be rendered
// shadowed; the farthest of them from the foot that is rendered lit is the gap. A bias that makes the
// shadow let go of the thin panel's foot shows the measurement catches it.
TEST_F(OrbitShadowTest, ShadowsTouchTheirCastersAtTheContact) {
    const auto measure = [&](glm::vec3 toSun, int object, const ShadowSettings& settings) {
        renderMap(toSun, settings);
        const orbit::ShadowProjection& lp = mRig->map.projection();
        const glm::vec3 away = -glm::normalize(glm::vec3(toSun.x, 0.0f, toSun.z));
        const glm::vec3 side = glm::cross(away, glm::vec3(0, 1, 0));
        // The point where the shadow leaves the foot: the foot's centre moved out to its edge along `away`.
        const glm::vec3 foot = glm::vec3(mBoxes[std::size_t(object)].model[3]) * glm::vec3(1, 0, 1);
        float reach = 0.0f;
        while (footprintDistance(mBoxes[std::size_t(object)], foot + away * reach, 1.0f) < 1e-4f) {
            reach += 0.002f;
        }
        const glm::vec3 contact = foot + away * reach;
        const View view{contact + away * 0.22f + side * 0.08f + glm::vec3(0, 0.3f, 0), contact + away * 0.03f,
                        25.0f};
        const Frame frame = draw(view);
        ContactGap result;
        for (const Pixel& p : classify(mBoxes, view, frame, lp, 2.0f)) {
            const float d = footprintDistance(mBoxes[std::size_t(object)], p.position, lp.texelSize);
            if (p.object != kPlate || !p.truthShadowed || p.edgeTexels < 2.0f || d > 12.0f) {
                continue;
            }
            ++result.pixels;
            if (!p.renderedShadowed) {
                ++result.litPixels;
                result.gap = std::max(result.gap, d);
            }
        }
        return result;
    };
    const ShadowSettings settings = testSettings(1024);
    const char* names[] = {"plate", "box", "pole", "panel"};
    for (float elevation : {45.0f, 20.0f}) {
        for (int object : {kBox, kPole, kPanel}) {
            // The panel stands across z: the sun comes at it from +z, the others from +x.
            const glm::vec3 toSun = sunAt(elevation, object == kPanel ? 70.0f : 10.0f);
            const ContactGap g = measure(toSun, object, settings);
            std::printf(
                "contact, sun %.0f degrees up, %s: %d shadowed plate pixels within 12 texels of the foot, "
                "%d rendered lit, gap %.2f texels\n",
                double(elevation), names[object], g.pixels, g.litPixels, double(g.gap));
            EXPECT_GT(g.pixels, 300) << names[object];
            EXPECT_LE(g.gap, 2.0f) << names[object] << " at " << elevation << " degrees";
        }
    }
    ShadowSettings detached = settings;
    detached.constantBias = 16.0f;
    const ContactGap bad = measure(sunAt(45.0f, 70.0f), kPanel, detached);
    std::printf("contact with constantBias 16: panel gap %.2f texels (%d of %d lit)\n", double(bad.gap),
                bad.litPixels, bad.pixels);
    EXPECT_GT(bad.gap, 4.0f) << "a 16-texel bias must lift the thin panel's shadow off its foot";
}

namespace {

/// Mean and largest |a - b| of the visibility over `pixels`, and how many of them.
struct Change {
    double mean = 0.0;
    double max = 0.0;
    std::size_t pixels = 0;
};

void accumulate(Change& c, const std::vector<Pixel>& pixels, const Frame& a, const Frame& b) {
    for (const Pixel& p : pixels) {
        const std::size_t i = (std::size_t(p.y) * kW + std::size_t(p.x)) * 4;
        const double d = std::abs(double(a.visibility.rgba[i]) - double(b.visibility.rgba[i]));
        c.mean += d;
        c.max = std::max(c.max, d);
        ++c.pixels;
    }
}

/// The pixels within `texels` of a shadow boundary.
std::vector<Pixel> edgePixels(std::vector<Pixel> pixels, float texels) {
    std::erase_if(pixels, [&](const Pixel& p) { return p.edgeTexels >= texels; });
    return pixels;
}

} // namespace

// (c): no shimmer. The map is a function of the sun and the caster bounds alone, so a camera orbiting with
// the sun fixed sees the same map every frame: the edge pixels of each frame, shaded with this frame's map
// and with the last frame's, do not change (and the depth is bit-identical). The bounds, though, may move (a
// caller whose bounds follow an animated part, or a ship that drifts): with the centre drifting by a third
// of a texel a frame and the casters and camera still, snapping keeps the edge pixels still, while without
// it the texel grid slides under the casters and the edges crawl.
TEST_F(OrbitShadowTest, ShadowEdgesDoNotShimmer) {
    const glm::vec3 toSun = sunAt(40, 25);
    const ShadowSettings settings = testSettings(512);
    constexpr float kEdge = 4.0f; ///< texels: PCF radius + the bilinear footprint + bias, rounded up
    constexpr int kFrames = 8;

    ShadowMap previous;
    const orbit::ShadowCasterDraws draws = mRig->scene.draws(mBoxes);
    Change orbitChange;
    std::vector<float> firstDepth;
    bool depthSame = true;
    for (int f = 0; f <= kFrames; ++f) {
        const float azimuth = glm::radians(160.0f + 0.5f * float(f));
        const View view{glm::vec3(4.5f * std::cos(azimuth), 2.4f, 4.5f * std::sin(azimuth)), {0, 0.2f, 0}};
        renderMap(toSun, settings);
        const std::vector<float> depth = readDepthTexture(mRig->map.depth());
        if (f == 0) {
            firstDepth = depth;
        } else {
            depthSame = depthSame && depth == firstDepth;
            const Frame now = draw(view);
            const Frame before = mRig->camera.draw(previous, view, draws);
            accumulate(orbitChange,
                       edgePixels(classify(mBoxes, view, now, mRig->map.projection(), kEdge), kEdge), now,
                       before);
        }
        previous.render(
            {.sunDirection = toSun, .bounds = sceneBounds(), .settings = &settings, .drawCasters = draws});
    }
    orbitChange.mean /= double(std::max<std::size_t>(orbitChange.pixels, 1));
    std::printf("camera orbit, 0.5 degrees a frame, %d frames: %zu edge pixels, change of visibility between "
                "frames mean %.4f max %.4f; depth map bit-identical: %s\n",
                kFrames, orbitChange.pixels, orbitChange.mean, orbitChange.max, depthSame ? "yes" : "no");
    EXPECT_TRUE(depthSame);
    EXPECT_GT(orbitChange.pixels, std::size_t(100 * kFrames));
    EXPECT_LE(orbitChange.mean, 0.01);

    const View still{{-3.8f, 2.4f, 1.2f}, {-0.4f, 0.0f, -0.3f}};
    const auto drift = [&](bool snap) {
        Change change;
        Frame before;
        std::vector<Pixel> edges;
        for (int f = 0; f <= kFrames; ++f) {
            ShadowBounds bounds = sceneBounds();
            const orbit::ShadowProjection fit =
                orbit::fitShadowProjection(toSun, bounds, settings.resolution);
            bounds.center +=
                float(f) * fit.texelSize * (0.33f * fit.right + 0.21f * fit.up + 0.25f * fit.toSun);
            renderMap(toSun, settings, snap, bounds);
            Frame now = draw(still);
            if (f == 0) {
                // The casters and the camera are still: the same pixels are the edge pixels every frame.
                edges = edgePixels(classify(mBoxes, still, now, mRig->map.projection(), kEdge), kEdge);
            } else {
                accumulate(change, edges, now, before);
            }
            before = std::move(now);
        }
        change.mean /= double(std::max<std::size_t>(change.pixels, 1));
        return change;
    };
    const Change snapped = drift(true);
    const Change sliding = drift(false);
    std::printf("bounds drifting a third of a texel a frame, %d frames: edge pixels' change between frames "
                "snapped mean %.4f max %.4f (%zu), unsnapped mean %.4f max %.4f (%zu)\n",
                kFrames, snapped.mean, snapped.max, snapped.pixels, sliding.mean, sliding.max,
                sliding.pixels);
    EXPECT_GT(snapped.pixels, std::size_t(100 * kFrames));
    EXPECT_LE(snapped.mean, 0.01);
    EXPECT_GT(sliding.mean, 2.0 * snapped.mean) << "without snapping the edges should move";
}

// softness widens the penumbra; enabled = false gives full visibility; render() and drawVisibility() leave
// the caller's framebuffer, viewport, program, vertex array, depth and culling state as they found them.
TEST_F(OrbitShadowTest, SettingsTakeEffectAndStateIsRestored) {
    const glm::vec3 toSun = sunAt(40, 25);
    const View view{{-3.8f, 2.4f, 1.2f}, {-0.4f, 0.0f, -0.3f}};
    const auto penumbra = [&](const ShadowSettings& settings, float& minimum) {
        renderMap(toSun, settings);
        const Frame frame = draw(view);
        int count = 0;
        minimum = 1.0f;
        for (std::size_t i = 0; i < frame.visibility.pixelCount(); ++i) {
            const float v = frame.visibility.rgba[i * 4];
            count += frame.world.rgba[i * 4 + 3] > 0.0f && v > 0.1f && v < 0.9f ? 1 : 0;
            minimum = frame.world.rgba[i * 4 + 3] > 0.0f ? std::min(minimum, v) : minimum;
        }
        return count;
    };
    ShadowSettings hard = testSettings(512);
    hard.softness = 0.0f;
    ShadowSettings soft = hard;
    soft.softness = 6.0f;
    ShadowSettings off = hard;
    off.enabled = false;
    float minHard = 0, minSoft = 0, minOff = 0;
    const int hardCount = penumbra(hard, minHard);
    const int softCount = penumbra(soft, minSoft);
    const int offCount = penumbra(off, minOff);
    std::printf("penumbra pixels (visibility 0.1-0.9): softness 0: %d, softness 6: %d; disabled: %d, least "
                "visibility %.3f\n",
                hardCount, softCount, offCount, double(minOff));
    EXPECT_GT(softCount, 2 * hardCount);
    EXPECT_LT(minHard, 0.01f);
    EXPECT_EQ(offCount, 0);
    EXPECT_EQ(minOff, 1.0f);

    const Texture color({.extent = {64, 64}, .format = GL_RGBA8, .debugName = "shadow test host"});
    const Framebuffer host(color, 0, "shadow test host");
    glBindFramebuffer(GL_FRAMEBUFFER, host.id());
    glViewport(3, 5, 40, 30);
    glEnable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glUseProgram(0);
    glBindVertexArray(0);
    renderMap(toSun, hard);
    GLint framebuffer = 0, viewport[4] = {}, program = -1, vertexArray = -1, depthFunc = 0;
    GLboolean depthMask = GL_TRUE;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    EXPECT_EQ(GLuint(framebuffer), host.id());
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[1], 5);
    EXPECT_EQ(viewport[2], 40);
    EXPECT_EQ(viewport[3], 30);
    EXPECT_EQ(program, 0);
    EXPECT_EQ(vertexArray, 0);
    EXPECT_EQ(depthFunc, GL_GREATER);
    EXPECT_EQ(depthMask, GL_FALSE);
    EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    glDisable(GL_CULL_FACE);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // A program deleted while it is current goes away when render() unbinds it: render() must not bind the
    // dead name again (GL_INVALID_VALUE, which the fixture counts), and leaves no program bound instead.
    {
        const Program doomed = makeGraphicsProgram("scenes/orbit/orbit_shadow_depth.vert.glsl",
                                                   "scenes/orbit/orbit_shadow_depth.frag.glsl");
        doomed.use();
    }
    renderMap(toSun, hard);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    EXPECT_EQ(program, 0);
}

} // namespace photopic::test
