#include "scenes/testbed/TestbedGeometry.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photopic::testbed {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::mat4 placement(const glm::vec3& position, float yaw = 0.0f, const glm::vec3& axis = {0, 1, 0}) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    if (yaw != 0.0f) {
        m = glm::rotate(m, yaw, axis);
    }
    return m;
}

float boundRadiusOf(Shape shape, const glm::vec3& size) {
    switch (shape) {
    case Shape::Sphere:
        return size.x;
    case Shape::Box:
        return glm::length(size);
    case Shape::Cylinder:
        return std::sqrt(size.x * size.x + size.y * size.y);
    }
    return 0.0f;
}

Primitive make(std::uint32_t id, Shape shape, const glm::vec3& size, const glm::mat4& now,
               const glm::mat4& before, const Material& material) {
    Primitive p;
    p.id = id;
    p.shape = shape;
    p.size = size;
    p.toWorld = now;
    p.toObject = glm::inverse(now);
    p.prevToWorld = before;
    p.material = material;
    p.boundCentre = glm::vec3(now[3]);
    p.boundRadius = boundRadiusOf(shape, size) * 1.001f + 1e-4f;
    return p;
}

Primitive still(std::uint32_t id, Shape shape, const glm::vec3& size, const glm::mat4& where,
                const Material& material) {
    return make(id, shape, size, where, where, material);
}

/// The mover's x: back and forth over [-4, 4] m at a constant 2 m/s (period 8 s).
float moverX(double seconds) {
    const double u = seconds - 8.0 * std::floor(seconds / 8.0);
    return float(u < 4.0 ? -4.0 + 2.0 * u : 4.0 - 2.0 * (u - 4.0));
}

constexpr float kSpinRate = 2.0f; ///< rad/s, the spinner about its vertical axis
constexpr float kStripTop = 0.02f;
constexpr float kSpinnerHalf = 0.35f;
constexpr float kMoverRadius = 0.35f;

glm::mat4 spinnerAt(double seconds) {
    return placement({-0.8f, kStripTop + kSpinnerHalf, 2.0f}, float(kSpinRate * seconds));
}
glm::mat4 moverAt(double seconds) {
    return placement({moverX(seconds), kMoverRadius, -4.4f});
}

} // namespace

const Environment& environment() {
    static const Environment kEnvironment = [] {
        Environment e;
        // Low afternoon sun (25 degrees up) from behind the checker wall, a little to the left: it is on
        // screen in the second shot, behind the poles, and casts long shadows towards the camera.
        e.sunDirection = glm::normalize(glm::vec3(-0.260f, 0.423f, -0.868f));
        e.sunIlluminance = 10.0f * glm::vec3(1.0f, 0.96f, 0.9f);
        e.sunAngularRadius = 0.02f;
        e.skyZenith = {0.25f, 0.45f, 0.9f};
        e.skyHorizon = {0.8f, 0.85f, 0.9f};
        e.groundRadiance = {0.12f, 0.11f, 0.1f};
        e.ambientSky = {1.5f, 1.75f, 2.2f};
        e.ambientGround = {0.35f, 0.33f, 0.3f};
        return e;
    }();
    return kEnvironment;
}

std::vector<Primitive> primitivesAt(double seconds, double prevSeconds) {
    std::vector<Primitive> prims;
    prims.reserve(40);
    Material ground{.albedo = {0.30f, 0.29f, 0.27f}, .albedo2 = {0.38f, 0.37f, 0.34f}, .checker = 1.0f};
    prims.push_back(
        still(ids::kGround, Shape::Box, {100.0f, 0.5f, 100.0f}, placement({0, -0.5f, 0}), ground));
    Material wall{.albedo = {0.85f, 0.85f, 0.85f}, .albedo2 = {0.02f, 0.02f, 0.02f}, .checker = 0.5f};
    prims.push_back(still(ids::kWall, Shape::Box, {6.0f, 2.0f, 0.1f}, placement({0, 2.0f, -6.0f}), wall));
    Material metal{.albedo = {0.9f, 0.9f, 0.92f}, .metallic = 0.9f, .roughness = 0.05f};
    prims.push_back(still(ids::kStrip, Shape::Box, {6.0f, 0.5f * kStripTop, 0.8f},
                          placement({0, 0.5f * kStripTop, 2.0f}), metal));
    prims.push_back(still(ids::kBigSphere, Shape::Sphere, glm::vec3(1.0f), placement({-2.5f, 1.0f, -2.0f}),
                          {.albedo = {0.8f, 0.8f, 0.78f}}));
    prims.push_back(still(ids::kSmallSphere, Shape::Sphere, glm::vec3(0.5f), placement({1.2f, 0.5f, 0.0f}),
                          {.albedo = {0.75f, 0.12f, 0.1f}, .roughness = 0.3f}));
    prims.push_back(still(ids::kCube, Shape::Box, glm::vec3(0.5f), placement({2.2f, 0.5f, -3.0f}, 0.5236f),
                          {.albedo = {0.15f, 0.3f, 0.75f}}));
    prims.push_back(still(ids::kTallBox, Shape::Box, {0.3f, 1.0f, 0.3f}, placement({-4.8f, 1.0f, -0.5f}),
                          {.albedo = {0.85f, 0.7f, 0.3f}}));
    prims.push_back(make(ids::kSpinner, Shape::Box, glm::vec3(kSpinnerHalf), spinnerAt(seconds),
                         spinnerAt(prevSeconds),
                         {.albedo = {0.9f, 0.85f, 0.2f}, .albedo2 = {0.1f, 0.1f, 0.12f}, .checker = 0.35f}));
    prims.push_back(make(ids::kMover, Shape::Sphere, glm::vec3(kMoverRadius), moverAt(seconds),
                         moverAt(prevSeconds),
                         {.albedo = {0.9f, 0.9f, 0.9f}, .emissive = {6.0f, 5.2f, 4.0f}}));

    // A 5 x 3 grid of thin poles (aliasing; the sun shines through them in the second shot).
    std::uint32_t id = ids::kFirstPole;
    const Material pole{.albedo = {0.6f, 0.6f, 0.6f}, .metallic = 0.3f, .roughness = 0.4f};
    for (int iz = 0; iz < 3; ++iz) {
        for (int ix = 0; ix < 5; ++ix) {
            const glm::vec3 at(3.0f + 0.6f * float(ix), 1.5f, -1.0f + 0.8f * float(iz));
            prims.push_back(still(id++, Shape::Cylinder, {0.025f, 1.5f, 0.0f}, placement(at), pole));
        }
    }
    // A wire fence: two posts, five horizontal wires (cylinders turned onto x), eight vertical wires.
    const Material post{.albedo = {0.35f, 0.25f, 0.15f}};
    const Material wire{.albedo = {0.7f, 0.7f, 0.72f}, .metallic = 0.5f, .roughness = 0.3f};
    for (float x : {-7.0f, -2.5f}) {
        prims.push_back(still(id++, Shape::Cylinder, {0.04f, 0.8f, 0.0f}, placement({x, 0.8f, 2.5f}), post));
    }
    for (int i = 0; i < 5; ++i) {
        const glm::vec3 at(-4.75f, 0.3f + 0.3f * float(i), 2.5f);
        prims.push_back(
            still(id++, Shape::Cylinder, {0.008f, 2.25f, 0.0f}, placement(at, 0.5f * kPi, {0, 0, 1}), wire));
    }
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 at(-6.5f + 0.5f * float(i), 0.8f, 2.5f);
        prims.push_back(still(id++, Shape::Cylinder, {0.008f, 0.8f, 0.0f}, placement(at), wire));
    }
    return prims;
}

CameraPose cameraPoseAt(double seconds) {
    const double t = std::max(seconds, 0.0);
    CameraPose p;
    if (t < kCutTime) {
        // Shot 0: a pan from 15 degrees left to 10 degrees right, then a dolly in of 3 m.
        p.shot = 0;
        p.pitch = -0.10f;
        const double pan = std::min(t / kPanEnd, 1.0);
        p.yaw = float(0.26 - 0.43 * pan);
        const double dolly = std::max(0.0, (t - kPanEnd) / (kCutTime - kPanEnd));
        p.position = {0.0f, 1.7f, float(9.0 - 3.0 * dolly)};
        p.focusDistance = glm::length(p.position - glm::vec3(0.0f, 0.8f, -1.0f));
    } else {
        // Shot 1: low, looking up towards the sun through the poles, panning right at 0.25 rad/s.
        p.shot = 1;
        p.position = {5.2f, 0.5f, 4.0f};
        p.yaw = float(0.45 - 0.25 * (t - kCutTime));
        p.pitch = 0.22f;
        p.focusDistance = 4.5f;
    }
    return p;
}

glm::mat4 viewMatrix(const CameraPose& pose) {
    const float cp = std::cos(pose.pitch);
    const glm::vec3 forward(-std::sin(pose.yaw) * cp, std::sin(pose.pitch), -std::cos(pose.yaw) * cp);
    return glm::lookAt(pose.position, pose.position + forward, glm::vec3(0.0f, 1.0f, 0.0f));
}

FrameTimes frameTimes(std::uint64_t frameIndex, double dt, const Clock& camera, const Clock& objects) {
    const double now = double(frameIndex) * dt;
    const double before = frameIndex == 0 ? now : now - dt;
    FrameTimes t;
    t.camera = camera.start + camera.rate * now;
    t.prevCamera = camera.start + camera.rate * before;
    t.objects = objects.start + objects.rate * now;
    t.prevObjects = objects.start + objects.rate * before;
    t.cameraRate = camera.rate;
    t.objectRate = objects.rate;
    return t;
}

Camera testbedCamera(double seconds, double prevSeconds, int width, int height, const Lens& lens) {
    const CameraPose pose = cameraPoseAt(seconds);
    CameraPose prev = cameraPoseAt(prevSeconds);
    Camera c;
    c.cut = prev.shot != pose.shot;
    if (c.cut) {
        prev = pose;
    }
    c.view = viewMatrix(pose);
    c.projection = perspectiveProjection(kVerticalFov, float(width) / float(height), kNear, kFar);
    c.prevViewProjection = c.projection * viewMatrix(prev);
    c.nearPlane = kNear;
    c.farPlane = kFar;
    c.verticalFov = kVerticalFov;
    c.lens = lens;
    c.lens.focalLengthMm = 0.5f * lens.sensorHeightMm / std::tan(0.5f * kVerticalFov);
    c.lens.focusDistance = pose.focusDistance;
    return c;
}

// ---- intersections ----

namespace {

/// Ray/sphere with the precise formulation of Haines, Guenther and Akenine-Moeller, "Precision Improvements
/// for Ray/Sphere Intersection", Ray Tracing Gems (2019), ch. 7: the discriminant from the ray's closest
/// approach, the near root from the stable quadratic form.
bool sphere(float r, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, float& t, glm::vec3& n) {
    const float b = -glm::dot(o, d);
    const glm::vec3 l = o + b * d;
    const float disc = r * r - glm::dot(l, l);
    if (disc < 0.0f) {
        return false;
    }
    const float c = glm::dot(o, o) - r * r;
    const float q = b + std::copysign(std::sqrt(disc), b);
    float t0 = q != 0.0f ? c / q : 0.0f;
    float t1 = q;
    if (t0 > t1) {
        std::swap(t0, t1);
    }
    t = t0 > tMin ? t0 : t1;
    if (!(t > tMin && t < tMax)) {
        return false;
    }
    n = (o + t * d) / r;
    return true;
}

glm::vec3 safeInverse(const glm::vec3& d) {
    glm::vec3 inv;
    for (int i = 0; i < 3; ++i) {
        inv[i] = 1.0f / (std::abs(d[i]) < 1e-12f ? 1e-12f : d[i]);
    }
    return inv;
}

/// Slab test (Kay and Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986).
bool box(const glm::vec3& h, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, float& t,
         glm::vec3& n) {
    const glm::vec3 inv = safeInverse(d);
    const glm::vec3 t1 = (-h - o) * inv;
    const glm::vec3 t2 = (h - o) * inv;
    const glm::vec3 lo = glm::min(t1, t2);
    const glm::vec3 hi = glm::max(t1, t2);
    const float tNear = std::max(lo.x, std::max(lo.y, lo.z));
    const float tFar = std::min(hi.x, std::min(hi.y, hi.z));
    if (tNear > tFar) {
        return false;
    }
    int axis = 0;
    float sign = 0.0f;
    if (tNear > tMin) {
        t = tNear;
        axis = lo.x == tNear ? 0 : (lo.y == tNear ? 1 : 2);
        sign = d[axis] > 0.0f ? -1.0f : 1.0f;
    } else {
        t = tFar;
        axis = hi.x == tFar ? 0 : (hi.y == tFar ? 1 : 2);
        sign = d[axis] > 0.0f ? 1.0f : -1.0f;
    }
    if (!(t > tMin && t < tMax)) {
        return false;
    }
    n = glm::vec3(0.0f);
    n[axis] = sign;
    return true;
}

bool cylinder(float r, float h, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, float& t,
              glm::vec3& n) {
    bool found = false;
    float best = tMax;
    const float a = d.x * d.x + d.z * d.z;
    if (a > 1e-12f) {
        const float b = o.x * d.x + o.z * d.z;
        const float c = o.x * o.x + o.z * o.z - r * r;
        const float disc = b * b - a * c;
        if (disc >= 0.0f) {
            const float s = std::sqrt(disc);
            for (float root : {(-b - s) / a, (-b + s) / a}) {
                const float y = o.y + root * d.y;
                if (root > tMin && root < best && std::abs(y) <= h) {
                    best = root;
                    n = glm::vec3(o.x + root * d.x, 0.0f, o.z + root * d.z) / r;
                    found = true;
                    break;
                }
            }
        }
    }
    if (std::abs(d.y) > 1e-12f) {
        for (float cap : {-h, h}) {
            const float root = (cap - o.y) / d.y;
            const float x = o.x + root * d.x;
            const float z = o.z + root * d.z;
            if (root > tMin && root < best && x * x + z * z <= r * r) {
                best = root;
                n = glm::vec3(0.0f, cap > 0.0f ? 1.0f : -1.0f, 0.0f);
                found = true;
            }
        }
    }
    t = best;
    return found;
}

bool boundMiss(const Primitive& prim, const Ray& ray, float tMin, float tMax) {
    const glm::vec3 oc = prim.boundCentre - ray.origin;
    const float tca = glm::dot(oc, ray.direction);
    const float d2 = glm::dot(oc, oc) - tca * tca;
    const float r = prim.boundRadius;
    return d2 > r * r || tca + r < tMin || tca - r > tMax;
}

} // namespace

bool intersect(const Primitive& prim, const Ray& ray, float tMin, float tMax, Hit& hit) {
    const glm::vec3 o = glm::vec3(prim.toObject * glm::vec4(ray.origin, 1.0f));
    const glm::vec3 d = glm::mat3(prim.toObject) * ray.direction;
    float t = 0.0f;
    glm::vec3 n(0.0f);
    bool found = false;
    switch (prim.shape) {
    case Shape::Sphere:
        found = sphere(prim.size.x, o, d, tMin, tMax, t, n);
        break;
    case Shape::Box:
        found = box(prim.size, o, d, tMin, tMax, t, n);
        break;
    case Shape::Cylinder:
        found = cylinder(prim.size.x, prim.size.y, o, d, tMin, tMax, t, n);
        break;
    }
    if (!found) {
        return false;
    }
    hit.t = t;
    hit.objectPoint = o + t * d;
    hit.objectNormal = n;
    hit.worldNormal = glm::normalize(glm::mat3(prim.toWorld) * n);
    return true;
}

bool intersectScene(const std::vector<Primitive>& prims, const Ray& ray, float tMin, float tMax, Hit& hit) {
    bool found = false;
    for (std::size_t i = 0; i < prims.size(); ++i) {
        if (boundMiss(prims[i], ray, tMin, tMax)) {
            continue;
        }
        Hit h;
        if (intersect(prims[i], ray, tMin, tMax, h)) {
            tMax = h.t;
            h.primitive = int(i);
            hit = h;
            found = true;
        }
    }
    return found;
}

bool occluded(const std::vector<Primitive>& prims, const Ray& ray, float tMin, float tMax) {
    for (const Primitive& p : prims) {
        Hit h;
        if (!boundMiss(p, ray, tMin, tMax) && intersect(p, ray, tMin, tMax, h)) {
            return true;
        }
    }
    return false;
}

// ---- shading ----

glm::vec3 albedoAt(const Primitive& prim, const glm::vec3& objectPoint, const glm::vec3& objectNormal) {
    const Material& m = prim.material;
    if (m.checker <= 0.0f) {
        return m.albedo;
    }
    glm::vec3 q = objectPoint / m.checker;
    if (prim.shape == Shape::Box) {
        // On a box face the coordinate along the normal sits on a square boundary: use the face's two axes.
        q *= glm::vec3(1.0f) - glm::abs(objectNormal);
    }
    const float sum = std::floor(q.x) + std::floor(q.y) + std::floor(q.z);
    const float parity = sum - 2.0f * std::floor(0.5f * sum);
    return parity < 0.5f ? m.albedo : m.albedo2;
}

glm::vec3 shadeLocal(const Primitive& prim, const Hit& hit, float sunVisibility, float ambientVisibility) {
    const Environment& env = environment();
    const Material& m = prim.material;
    const glm::vec3 n = hit.worldNormal;
    const glm::vec3 ambient = glm::mix(env.ambientGround, env.ambientSky, 0.5f + 0.5f * n.y);
    const float nl = std::max(glm::dot(n, env.sunDirection), 0.0f);
    const glm::vec3 diffuse = albedoAt(prim, hit.objectPoint, hit.objectNormal) * (1.0f - m.metallic);
    return diffuse * (env.sunIlluminance * (nl * sunVisibility) + ambient * ambientVisibility) / kPi +
           m.emissive;
}

glm::vec3 skyRadiance(const glm::vec3& d) {
    const Environment& env = environment();
    glm::vec3 l = d.y >= 0.0f ? glm::mix(env.skyHorizon, env.skyZenith, std::sqrt(d.y)) : env.groundRadiance;
    if (glm::dot(d, env.sunDirection) >= std::cos(env.sunAngularRadius)) {
        l += env.sunIlluminance / (kPi * env.sunAngularRadius * env.sunAngularRadius);
    }
    return l;
}

glm::vec3 radiance(const std::vector<Primitive>& prims, const Ray& ray) {
    Hit hit;
    if (intersectScene(prims, ray, 0.0f, kFar * 2.0f, hit)) {
        return shadeLocal(prims[std::size_t(hit.primitive)], hit);
    }
    return skyRadiance(ray.direction);
}

Ray cameraRay(const Camera& camera, glm::vec2 ndc) {
    const glm::mat4& p = camera.projection;
    const glm::vec3 viewDir((ndc.x + p[2][0]) / p[0][0], (ndc.y + p[2][1]) / p[1][1], -1.0f);
    const glm::mat4 invView = glm::inverse(camera.view);
    return {glm::vec3(invView[3]), glm::normalize(glm::mat3(invView) * viewDir)};
}

glm::vec2 motionUv(const Camera& camera, const Primitive* prim, const glm::vec3& worldPoint,
                   const glm::vec3& skyDirection) {
    glm::vec4 now(skyDirection, 0.0f);
    glm::vec4 before(skyDirection, 0.0f);
    if (prim != nullptr) {
        now = glm::vec4(worldPoint, 1.0f);
        before = prim->prevToWorld * (prim->toObject * now);
    }
    const glm::vec4 a = camera.viewProjection() * now;
    const glm::vec4 b = camera.prevViewProjection * before;
    return 0.5f * (glm::vec2(a) / a.w - glm::vec2(b) / b.w);
}

} // namespace photopic::testbed
