#include "scenes/testbed/TestbedRaytracer.h"

#include "core/Hash.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>
#include <utility>

namespace photopic::testbed {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInf = std::numeric_limits<float>::infinity();

constexpr std::array<std::pair<TruthKind, std::string_view>, 10> kNames{{
    {TruthKind::Color, "color"},
    {TruthKind::Depth, "depth"},
    {TruthKind::Normals, "normals"},
    {TruthKind::Motion, "motion"},
    {TruthKind::ObjectId, "objectid"},
    {TruthKind::Ao, "ao"},
    {TruthKind::Sun, "sun"},
    {TruthKind::Shutter, "shutter"},
    {TruthKind::ThinLens, "thinlens"},
    {TruthKind::Reflection, "reflection"},
}};

/// A uniform float in [0, 1) from a hash of the arguments.
float random01(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const std::uint32_t h = hash32(a ^ hash32(b ^ hash32(c + 0x9e3779b9U)));
    return float(h >> 8) * (1.0f / 16777216.0f);
}

/// Concentric map of the unit square onto the unit disc (Shirley and Chiu, "A Low Distortion Map Between
/// Disk and Square", JGT 1997).
glm::vec2 concentricDisc(glm::vec2 u) {
    const glm::vec2 p = 2.0f * u - 1.0f;
    if (p.x == 0.0f && p.y == 0.0f) {
        return glm::vec2(0.0f);
    }
    float r = 0.0f;
    float phi = 0.0f;
    if (std::abs(p.x) > std::abs(p.y)) {
        r = p.x;
        phi = 0.25f * kPi * (p.y / p.x);
    } else {
        r = p.y;
        phi = 0.5f * kPi - 0.25f * kPi * (p.x / p.y);
    }
    return r * glm::vec2(std::cos(phi), std::sin(phi));
}

/// An orthonormal basis around unit n (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
void basis(const glm::vec3& n, glm::vec3& b1, glm::vec3& b2) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    b1 = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    b2 = glm::vec3(b, sign + n.y * n.y * a, -n.y);
}

/// Stratum k of an n x n grid with a hashed offset inside it, in [0, 1)^2.
glm::vec2 stratified(int k, int n, std::uint32_t pixel, std::uint32_t stream) {
    const float u = random01(pixel, std::uint32_t(k), stream);
    const float v = random01(pixel, std::uint32_t(k), stream + 1u);
    return {(float(k % n) + u) / float(n), (float(k / n) + v) / float(n)};
}

/// Runs fn(y) for every row, rows interleaved over the workers.
template <class Fn>
void forRows(int height, int threads, const Fn& fn) {
    int count = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    count = std::clamp(count, 1, std::max(height, 1));
    std::vector<std::thread> workers;
    workers.reserve(std::size_t(count));
    for (int w = 0; w < count; ++w) {
        workers.emplace_back([&, w] {
            for (int y = w; y < height; y += count) {
                fn(y);
            }
        });
    }
    for (std::thread& t : workers) {
        t.join();
    }
}

/// Everything one frame's rays need, built once.
struct Frame {
    Camera camera;
    std::vector<Primitive> prims;
    glm::mat4 invView{1.0f};
};

Frame frameAt(const TruthOptions& o, double cameraTime, double objectTime) {
    Frame f;
    const double prevCamera = o.times.prevCamera + (cameraTime - o.times.camera);
    const double prevObjects = o.times.prevObjects + (objectTime - o.times.objects);
    f.camera = testbedCamera(cameraTime, prevCamera, o.width, o.height, o.lens);
    if (o.fixedView) {
        f.camera.view = glm::lookAt(o.fixedView->eye, o.fixedView->target, glm::vec3(0.0f, 1.0f, 0.0f));
        f.camera.prevViewProjection = f.camera.projection * f.camera.view;
        f.camera.cut = false;
        f.camera.lens.focusDistance = glm::length(o.fixedView->target - o.fixedView->eye);
    }
    if (o.focusDistance > 0.0f) {
        f.camera.lens.focusDistance = o.focusDistance;
    }
    f.prims = primitivesAt(objectTime, prevObjects);
    f.invView = glm::inverse(f.camera.view);
    return f;
}

glm::vec2 ndcOf(const TruthOptions& o, float x, float y) {
    return {2.0f * x / float(o.width) - 1.0f, 1.0f - 2.0f * y / float(o.height)};
}

/// Offset of a secondary ray's origin from a surface point: above float error at that distance.
float surfaceEpsilon(const glm::vec3& p) {
    const float m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
    return 2e-4f * m;
}

/// Colour sub-sample k of pixel (x, y): the same sub-pixel position for color, shutter and thinlens.
glm::vec2 subPixel(const TruthOptions& o, int x, int y, int k) {
    if (o.samples == 1) {
        return glm::vec2(float(x) + 0.5f - o.jitter.x, float(y) + 0.5f + o.jitter.y);
    }
    const std::uint32_t pixel = std::uint32_t(y * o.width + x);
    return glm::vec2(float(x), float(y)) + stratified(k, o.samples, pixel, 1u);
}

/// The number of shutter instants (strata of the shutter interval) per pixel.
int shutterCount(const TruthOptions& o) {
    return o.samples * o.samples * std::max(o.shutterTimes, 1);
}

/// The shutter's time stratum of sub-sample k (of shutterCount strata centred on the frame's time): a
/// per-pixel rotation of the strata decorrelates time from the position within the pixel.
int shutterStratum(const TruthOptions& o, int x, int y, int k) {
    const auto count = std::uint32_t(shutterCount(o));
    const std::uint32_t pixel = std::uint32_t(y * o.width + x);
    return int((std::uint32_t(k) * 7919u + hash32(pixel ^ 0x51ed270bU)) % count);
}

void pixelCentreKinds(TruthKind kind, const Frame& f, const TruthOptions& o, int x, int y, float* out) {
    const Ray ray = cameraRay(f.camera, ndcOf(o, float(x) + 0.5f - o.jitter.x, float(y) + 0.5f + o.jitter.y));
    Hit hit;
    const bool found = intersectScene(f.prims, ray, 0.0f, kFar * 2.0f, hit);
    const Primitive* prim = found ? &f.prims[std::size_t(hit.primitive)] : nullptr;
    const glm::vec3 p = ray.origin + hit.t * ray.direction;
    const std::uint32_t pixel = std::uint32_t(y * o.width + x);
    switch (kind) {
    case TruthKind::Depth:
        out[0] = found ? -(f.camera.view * glm::vec4(p, 1.0f)).z : kInf;
        break;
    case TruthKind::Normals:
        if (found) {
            const glm::vec3 n = glm::normalize(glm::mat3(f.camera.view) * hit.worldNormal);
            out[0] = n.x;
            out[1] = n.y;
            out[2] = n.z;
        }
        break;
    case TruthKind::Motion: {
        const glm::vec2 m = motionUv(f.camera, prim, p, ray.direction);
        out[0] = m.x;
        out[1] = m.y;
        break;
    }
    case TruthKind::ObjectId:
        out[0] = found ? float(prim->id) : 0.0f;
        break;
    case TruthKind::Ao: {
        const float v =
            found ? ambientOcclusionAt(f.prims, p, hit.worldNormal, o.aoRadius, o.aoSamples, pixel) : 1.0f;
        out[0] = out[1] = out[2] = v;
        break;
    }
    case TruthKind::Sun: {
        const float v =
            found ? sunVisibilityAt(f.prims, p, hit.worldNormal, o.sunMaxDistance, o.sunSamples, pixel)
                  : 1.0f;
        out[0] = out[1] = out[2] = v;
        break;
    }
    case TruthKind::Reflection:
        if (found && prim->material.metallic > 0.0f) {
            const glm::vec3 n = hit.worldNormal;
            const glm::vec3 r = glm::normalize(glm::reflect(ray.direction, n));
            const glm::vec3 c = radiance(f.prims, {p + surfaceEpsilon(p) * n, r});
            out[0] = c.r;
            out[1] = c.g;
            out[2] = c.b;
            out[3] = 1.0f;
        }
        break;
    default:
        break;
    }
}

ImageF renderColor(TruthKind kind, const TruthOptions& o) {
    ImageF image(o.width, o.height, 0.0f);
    const double shutter = shutterSeconds(o);
    const bool moving =
        kind == TruthKind::Shutter && shutter > 0.0 && (o.times.cameraRate > 0.0 || o.times.objectRate > 0.0);
    // Sub-samples per pixel: each position once, or shutterTimes times (one instant each) with motion.
    const int times = moving ? std::max(o.shutterTimes, 1) : 1;
    const int count = o.samples * o.samples * times;
    const Frame still = frameAt(o, o.times.camera, o.times.objects);
    // The shutter's instants: the centres of `count` equal strata of [t - s/2, t + s/2] in frame time.
    std::vector<Frame> instants;
    if (moving) {
        instants.reserve(std::size_t(count));
        for (int i = 0; i < count; ++i) {
            const double offset = ((double(i) + 0.5) / double(count) - 0.5) * shutter;
            instants.push_back(frameAt(o, o.times.camera + o.times.cameraRate * offset,
                                       o.times.objects + o.times.objectRate * offset));
        }
    }
    // Thin lens: aperture diameter = focal length / f-number (mm -> scene metres).
    const float lensRadius = 0.5f * still.camera.lens.focalLengthMm / still.camera.lens.fNumber * 1e-3f;
    const float focus = still.camera.lens.focusDistance;
    forRows(o.height, o.threads, [&](int y) {
        for (int x = 0; x < o.width; ++x) {
            glm::vec3 sum(0.0f);
            for (int k = 0; k < count; ++k) {
                const glm::vec2 s = subPixel(o, x, y, k / times);
                const glm::vec2 ndc = ndcOf(o, s.x, s.y);
                if (moving) {
                    const Frame& f = instants[std::size_t(shutterStratum(o, x, y, k))];
                    sum += radiance(f.prims, cameraRay(f.camera, ndc));
                } else if (kind == TruthKind::ThinLens) {
                    const glm::mat4& p = still.camera.projection;
                    const glm::vec3 viewDir((ndc.x + p[2][0]) / p[0][0], (ndc.y + p[2][1]) / p[1][1], -1.0f);
                    const glm::vec3 focal = viewDir * focus; // on the plane z = -focus
                    const std::uint32_t pixel = std::uint32_t(y * o.width + x);
                    const glm::vec2 l = lensRadius * concentricDisc(stratified(k, o.samples, pixel, 41u));
                    const glm::vec3 lensPoint(l, 0.0f);
                    const glm::vec3 origin = glm::vec3(still.invView * glm::vec4(lensPoint, 1.0f));
                    const glm::vec3 dir = glm::normalize(glm::mat3(still.invView) * (focal - lensPoint));
                    sum += radiance(still.prims, {origin, dir});
                } else {
                    sum += radiance(still.prims, cameraRay(still.camera, ndc));
                }
            }
            float* px = image.at(x, y);
            const glm::vec3 c = sum / float(count);
            px[0] = c.r;
            px[1] = c.g;
            px[2] = c.b;
            px[3] = 1.0f;
        }
    });
    return image;
}

} // namespace

std::string_view truthKindName(TruthKind kind) {
    for (const auto& [k, name] : kNames) {
        if (k == kind) {
            return name;
        }
    }
    return "?";
}

std::optional<TruthKind> parseTruthKind(std::string_view name) {
    for (const auto& [k, n] : kNames) {
        if (n == name) {
            return k;
        }
    }
    return std::nullopt;
}

const std::vector<TruthKind>& allTruthKinds() {
    static const std::vector<TruthKind> kAll = [] {
        std::vector<TruthKind> all;
        for (const auto& entry : kNames) {
            all.push_back(entry.first);
        }
        return all;
    }();
    return kAll;
}

float ambientOcclusionAt(const std::vector<Primitive>& prims, const glm::vec3& p, const glm::vec3& n,
                         float radius, int samples, std::uint32_t salt) {
    glm::vec3 b1, b2;
    basis(n, b1, b2);
    const glm::vec3 origin = p + surfaceEpsilon(p) * n;
    const int count = samples * samples;
    int open = 0;
    for (int k = 0; k < count; ++k) {
        // Cosine-weighted by Malley's method: uniform on the disc, lifted onto the hemisphere.
        const glm::vec2 d = concentricDisc(stratified(k, samples, salt, 11u));
        const float z = std::sqrt(std::max(0.0f, 1.0f - glm::dot(d, d)));
        const glm::vec3 dir = glm::normalize(d.x * b1 + d.y * b2 + z * n);
        open += occluded(prims, {origin, dir}, 0.0f, radius) ? 0 : 1;
    }
    return float(open) / float(count);
}

float sunVisibilityAt(const std::vector<Primitive>& prims, const glm::vec3& p, const glm::vec3& n,
                      float maxDistance, int samples, std::uint32_t salt) {
    const Environment& env = environment();
    if (glm::dot(n, env.sunDirection) <= 0.0f) {
        return 0.0f;
    }
    const glm::vec3 origin = p + surfaceEpsilon(p) * n;
    const float tMax = maxDistance > 0.0f ? maxDistance : kInf;
    if (samples <= 1) {
        return occluded(prims, {origin, env.sunDirection}, 0.0f, tMax) ? 0.0f : 1.0f;
    }
    glm::vec3 b1, b2;
    basis(env.sunDirection, b1, b2);
    const float spread = std::tan(env.sunAngularRadius);
    const int count = samples * samples;
    int open = 0;
    for (int k = 0; k < count; ++k) {
        const glm::vec2 d = spread * concentricDisc(stratified(k, samples, salt, 21u));
        const glm::vec3 dir = glm::normalize(env.sunDirection + d.x * b1 + d.y * b2);
        open += occluded(prims, {origin, dir}, 0.0f, tMax) ? 0 : 1;
    }
    return float(open) / float(count);
}

Camera truthCamera(const TruthOptions& options) {
    return frameAt(options, options.times.camera, options.times.objects).camera;
}

TruthInstant truthInstant(const TruthOptions& options, double offset) {
    Frame f = frameAt(options, options.times.camera + options.times.cameraRate * offset,
                      options.times.objects + options.times.objectRate * offset);
    return {f.camera, std::move(f.prims)};
}

double shutterSeconds(const TruthOptions& options) {
    return options.lens.exposureTimeS > 0.0f ? double(options.lens.exposureTimeS)
                                             : double(options.lens.shutterAngleDeg) / 360.0 * options.dt;
}

ImageF renderTruth(TruthKind kind, const TruthOptions& options) {
    if (kind == TruthKind::Color || kind == TruthKind::Shutter || kind == TruthKind::ThinLens) {
        return renderColor(kind, options);
    }
    ImageF image(options.width, options.height, 0.0f);
    const Frame f = frameAt(options, options.times.camera, options.times.objects);
    forRows(options.height, options.threads, [&](int y) {
        for (int x = 0; x < options.width; ++x) {
            pixelCentreKinds(kind, f, options, x, y, image.at(x, y));
        }
    });
    return image;
}

} // namespace photopic::testbed
