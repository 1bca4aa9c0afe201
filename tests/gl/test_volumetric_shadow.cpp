// Volumetric light's shadow-map march at 160x90 on analytic geometry: a floor and, 4 m above it, a roof with
// a square hole, lit by a tilted sun, seen from under the roof. The sun's shadow map is written here from the
// same geometry (ray cast per texel) with the orbit scene's light projection, and a CPU ray-march of the
// same single scattering with exact visibility and many steps is the truth: the pass agrees with it, the
// roof cuts the light outside the shaft, the light holds still on a slow pan, the pass falls back to the
// screen-space rays without a map, the debug view holds the light added, and broken inputs stay out. The
// measured figures are printed and written down in docs/architecture.md ("Volumetric light").

#include "GlTest.h"

#include "core/Camera.h"
#include "gl/Objects.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"
#include "scenes/orbit/OrbitShadowMap.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr int kMapSize = 512;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kRoofY = 4.0f;
constexpr float kExtent = 12.0f;            ///< the floor and the roof span [-12, 12] in x and z
constexpr float kHoleHalf = 0.6f;           ///< the hole: |x| < 0.6, |z| < 0.6
constexpr float kVerticalFov = 0.87266463f; ///< 50 degrees
constexpr glm::vec3 kEye{0.0f, 1.6f, 7.0f};
constexpr glm::vec3 kIlluminance{10.0f, 9.0f, 8.0f};

glm::vec3 sunDirection() {
    return glm::normalize(glm::vec3(0.25f, 1.0f, 0.15f));
}

/// The scene: with `roof` false, the floor alone (nothing shadows the air).
struct Scene {
    bool roof = true;

    [[nodiscard]] bool roofAt(float x, float z) const {
        const bool inside = std::abs(x) <= kExtent && std::abs(z) <= kExtent;
        const bool hole = std::abs(x) < kHoleHalf && std::abs(z) < kHoleHalf;
        return roof && inside && !hole;
    }
    /// The nearest hit along o + t d (t > 0), or nothing.
    [[nodiscard]] std::optional<float> hit(glm::vec3 o, glm::vec3 d) const {
        std::optional<float> best;
        for (float y : {0.0f, kRoofY}) {
            if (d.y == 0.0f) {
                continue;
            }
            const float t = (y - o.y) / d.y;
            if (!(t > 1e-5f) || (best && t >= *best)) {
                continue;
            }
            const glm::vec3 p = o + t * d;
            const bool surface =
                y == 0.0f ? (std::abs(p.x) <= kExtent && std::abs(p.z) <= kExtent) : roofAt(p.x, p.z);
            if (surface) {
                best = t;
            }
        }
        return best;
    }
    /// Whether the sun reaches a point of the air (above the floor): exact.
    [[nodiscard]] bool lit(glm::vec3 p) const {
        if (p.y >= kRoofY) {
            return true;
        }
        const glm::vec3 s = sunDirection();
        const glm::vec3 h = p + ((kRoofY - p.y) / s.y) * s;
        return !roofAt(h.x, h.z);
    }
};

/// The orbit scene's light projection around the whole scene: any host's directional map fits the same way.
orbit::ShadowProjection lightProjection() {
    return orbit::fitShadowProjection(
        sunDirection(),
        orbit::ShadowBounds::aroundBox({-kExtent, -0.5f, -kExtent}, {kExtent, kRoofY + 0.5f, kExtent}),
        kMapSize);
}

/// The sun's shadow map of the scene: per texel, a ray from the light's near plane along -sun, its first
/// hit's standard depth (1 where it hits nothing).
Texture shadowMapOf(const Scene& scene, const glm::mat4& worldToClip) {
    const glm::mat4 clipToWorld = glm::inverse(worldToClip);
    std::vector<float> depth(std::size_t(kMapSize) * kMapSize, 1.0f);
    for (int y = 0; y < kMapSize; ++y) {
        for (int x = 0; x < kMapSize; ++x) {
            const glm::vec2 ndc = (glm::vec2(float(x), float(y)) + 0.5f) / float(kMapSize) * 2.0f - 1.0f;
            const glm::vec4 n = clipToWorld * glm::vec4(ndc, -1.0f, 1.0f);
            const glm::vec3 origin = glm::vec3(n) / n.w;
            if (const std::optional<float> t = scene.hit(origin, -sunDirection())) {
                const glm::vec4 c = worldToClip * glm::vec4(origin - *t * sunDirection(), 1.0f);
                depth[std::size_t(y) * kMapSize + std::size_t(x)] =
                    std::clamp(c.z / c.w * 0.5f + 0.5f, 0.0f, 1.0f);
            }
        }
    }
    Texture map(
        {.extent = {kMapSize, kMapSize}, .format = GL_DEPTH_COMPONENT32F, .debugName = "sun shadow map"});
    glTextureSubImage2D(map.id(), 0, 0, 0, kMapSize, kMapSize, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return map;
}

Camera cameraLooking(float yawDeg, float prevYawDeg) {
    const auto forward = [](float yaw) {
        const float a = glm::radians(yaw);
        return glm::normalize(glm::vec3(std::sin(a), 0.25f, -std::cos(a)));
    };
    Camera c;
    c.verticalFov = kVerticalFov;
    c.nearPlane = 0.1f;
    c.farPlane = 1000.0f;
    c.projection = perspectiveProjection(c.verticalFov, float(kW) / float(kH), c.nearPlane, c.farPlane);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    c.view = glm::lookAt(kEye, kEye + forward(yawDeg), up);
    c.prevViewProjection = c.projection * glm::lookAt(kEye, kEye + forward(prevYawDeg), up);
    return c;
}

/// The world-space direction (not normalised) through image pixel (x, y) (rows top to bottom) per unit of
/// linear depth.
glm::vec3 pixelRay(const Camera& c, float x, float y) {
    const glm::vec2 ndc(x / float(kW) * 2.0f - 1.0f, 1.0f - y / float(kH) * 2.0f);
    const glm::vec3 v(ndc.x / c.projection[0][0], ndc.y / c.projection[1][1], -1.0f);
    return glm::mat3(glm::inverse(c.view)) * v;
}

/// Linear depth of each pixel centre (+inf: sky), rows top to bottom, in R.
ImageF depthOf(const Scene& scene, const Camera& c) {
    ImageF depth(kW, kH, 0.0f);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const glm::vec3 ray = pixelRay(c, float(x) + 0.5f, float(y) + 0.5f);
            const std::optional<float> t = scene.hit(kEye, ray);
            depth.at(x, y)[0] = t ? *t : kInf; // the ray has unit view-axis length: t is the linear depth
        }
    }
    return depth;
}

float luma(const float* c) {
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

/// The CPU truth: single scattering along each pixel centre's ray to its surface (the sky's to maxDistance),
/// `steps` midpoint steps of exact visibility: intensity x illuminance x albedo x HG(g) x integral of
/// extinction x visibility x transmittance.
ImageF referenceOf(const Scene& scene, const Camera& c, const ImageF& depth, const VolumetricLightSettings& s,
                   int steps) {
    ImageF out(kW, kH, 0.0f);
    const float extinction = s.density * s.scattering;
    const float g = s.anisotropy;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const glm::vec3 ray = pixelRay(c, float(x) + 0.5f, float(y) + 0.5f);
            const float perDepth = glm::length(ray);
            const glm::vec3 dir = ray / perDepth;
            const float z = depth.at(x, y)[0];
            const float length = std::isinf(z) ? s.maxDistance : std::min(z * perDepth, s.maxDistance);
            const float dt = length / float(steps);
            double integral = 0.0;
            for (int i = 0; i < steps; ++i) {
                const float t = (float(i) + 0.5f) * dt;
                if (scene.lit(kEye + t * dir)) {
                    integral += double(extinction) * std::exp(-double(extinction) * t) * dt;
                }
            }
            const float cosTheta = glm::dot(dir, sunDirection());
            const float d = 1.0f + g * g - 2.0f * g * cosTheta;
            const float phase = (1.0f - g * g) / (4.0f * 3.14159265f * d * std::sqrt(d));
            const glm::vec3 v = s.intensity * kIlluminance * s.decay * phase * float(integral);
            float* o = out.at(x, y);
            o[0] = v.x;
            o[1] = v.y;
            o[2] = v.z;
            o[3] = 1.0f;
        }
    }
    return out;
}

Settings shadowSettings() {
    Settings s;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.volumetricLight.enabled = true;
    s.volumetricLight.scattering = 0.05f;
    s.volumetricLight.maxDistance = 30.0f;
    s.debug.view = DebugView::VolumetricLight;
    return s;
}

/// A host of the analytic scene: grey colour, its linear depth, its sun shadow map.
class Host {
public:
    explicit Host(const Scene& scene = {})
        : mScene(scene)
        , mWorldToClip(lightProjection().viewProjection)
        , mMap(shadowMapOf(scene, mWorldToClip))
        , mColor(makeTexture(ImageF(kW, kH, 0.1f), "color")) {}

    /// One frame; the light added (the debug view) or the image, read back.
    ImageF render(Pipeline& pipeline, const Camera& camera, std::uint64_t frameIndex, bool withMap = true) {
        if (!mDepth.valid() || !(camera.view == mDepthView)) {
            mDepth = makeTexture(depthOf(mScene, camera), "depth");
            mDepthView = camera.view;
        }
        FrameInputs in{.color = &mColor,
                       .depth = &mDepth,
                       .depthKind = DepthKind::LinearView,
                       .camera = &camera,
                       .sunDirection = sunDirection()};
        if (withMap) {
            in.sunShadow = {.depth = &mMap, .worldToClip = mWorldToClip, .illuminance = kIlluminance};
        }
        pipeline.execute(in, {.dt = 1.0f / 30.0f, .frameIndex = frameIndex});
        return readTextureF(pipeline.sceneReferred());
    }
    ImageF still(Pipeline& pipeline, const Camera& camera, std::uint64_t frames, bool withMap = true) {
        pipeline.reset();
        ImageF out;
        for (std::uint64_t i = 0; i < frames; ++i) {
            out = render(pipeline, camera, i, withMap);
        }
        return out;
    }
    [[nodiscard]] const Scene& scene() const { return mScene; }

private:
    Scene mScene;
    glm::mat4 mWorldToClip;
    Texture mMap;
    Texture mColor;
    Texture mDepth;
    glm::mat4 mDepthView{0.0f};
};

constexpr std::uint64_t kSettleFrames = 24;

struct Agreement {
    double meanAbsError = 0.0; ///< over the mean of the reference
    double total = 0.0;        ///< the pass's sum over the reference's
};

Agreement agreement(const ImageF& light, const ImageF& reference) {
    double error = 0.0, sum = 0.0, ref = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const double l = luma(light.at(x, y)), r = luma(reference.at(x, y));
            error += std::abs(l - r);
            sum += l;
            ref += r;
        }
    }
    return {.meanAbsError = error / ref, .total = sum / ref};
}

} // namespace

// Against the CPU march (4000 steps, exact visibility) of the same single scattering, at half and quarter
// resolution, the sun 17 degrees from the zenith: the mean absolute error over the reference's mean (<= 4%
// and 8%) and the total (within 2%).
TEST_F(GlTest, VolumetricShadowMatchesTheCpuMarch) {
    Host host;
    const Camera camera = cameraLooking(0.0f, 0.0f);
    const ImageF depth = depthOf(host.scene(), camera);
    for (VolumetricLightResolution r :
         {VolumetricLightResolution::Half, VolumetricLightResolution::Quarter}) {
        Settings s = shadowSettings();
        s.volumetricLight.resolution = r;
        Pipeline pipeline({.settings = s});
        const ImageF light = host.still(pipeline, camera, kSettleFrames);
        const ImageF reference = referenceOf(host.scene(), camera, depth, s.volumetricLight, 4000);
        const Agreement a = agreement(light, reference);
        std::printf(
            "volumetric light (shadow map, %s) against the CPU march: mean absolute error %.4f of the "
            "mean, total %.4f\n",
            r == VolumetricLightResolution::Half ? "half" : "quarter", a.meanAbsError, a.total);
        EXPECT_LE(a.meanAbsError, r == VolumetricLightResolution::Half ? 0.04 : 0.08);
        EXPECT_NEAR(a.total, 1.0, 0.02);
    }
}

// The roof cuts the light: over the pixels whose reference light is below 10% of the image's brightest
// (rays in the roof's shadow) the light is <= 1% of the shaft's (pixels above 50%), within a quarter of the
// reference's ratio, and <= 1% of what the same pixels get with the roof left out of the shadow map.
TEST_F(GlTest, VolumetricShadowOccludersCutTheLight) {
    const Camera camera = cameraLooking(0.0f, 0.0f);
    Host host;
    Host open(Scene{.roof = false});
    const Settings s = shadowSettings();
    Pipeline pipeline({.settings = s});
    const ImageF light = host.still(pipeline, camera, kSettleFrames);
    const ImageF unshadowed = open.still(pipeline, camera, kSettleFrames);
    const ImageF reference =
        referenceOf(host.scene(), camera, depthOf(host.scene(), camera), s.volumetricLight, 2000);
    float peak = 0.0f;
    for (int i = 0; i < kW * kH; ++i) {
        peak = std::max(peak, luma(&reference.rgba[std::size_t(i) * 4]));
    }
    double shaft = 0.0, shadow = 0.0, shaftRef = 0.0, shadowRef = 0.0, shadowOpen = 0.0;
    int shaftCount = 0, shadowCount = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float r = luma(reference.at(x, y));
            if (r >= 0.5f * peak) {
                shaft += luma(light.at(x, y));
                shaftRef += r;
                ++shaftCount;
            } else if (r <= 0.1f * peak) {
                shadow += luma(light.at(x, y));
                shadowRef += r;
                shadowOpen += luma(unshadowed.at(x, y));
                ++shadowCount;
            }
        }
    }
    ASSERT_GT(shaftCount, 20);
    ASSERT_GT(shadowCount, 20);
    const double ratio = (shadow / shadowCount) / (shaft / shaftCount);
    const double ratioRef = (shadowRef / shadowCount) / (shaftRef / shaftCount);
    const double cut = shadow / shadowOpen;
    std::printf("volumetric light (shadow map): shadowed/shaft %.4f (reference %.4f) over %d and %d pixels; "
                "shadowed pixels keep %.4f of their light without the roof\n",
                ratio, ratioRef, shadowCount, shaftCount, cut);
    EXPECT_LE(ratio, 0.01);
    EXPECT_NEAR(ratio, ratioRef, 0.25 * ratioRef + 0.0005);
    EXPECT_LE(cut, 0.01);
}

// A slow pan (0.1 degree of yaw per frame, about 0.2 px, the camera turning in place so every view ray keeps
// its light): after settling, the light changes between consecutive frames by <= 2% of its mean once the
// previous frame is reprojected to this one (exactly, by direction), at 64 and 16 samples; the march alone,
// reset every frame, changes more (at 16 samples, more than twice as much).
TEST_F(GlTest, VolumetricShadowHoldsStillOnASlowPan) {
    Host host;
    const auto change = [&](bool accumulate, int samples) {
        Settings s = shadowSettings();
        s.volumetricLight.samples = samples;
        Pipeline pipeline({.settings = s});
        ImageF last;
        Camera lastCamera;
        double moved = 0.0, mean = 0.0;
        for (std::uint64_t i = 0; i < 30; ++i) {
            const float yaw = 0.1f * float(i);
            const Camera camera = cameraLooking(yaw, i > 0 ? yaw - 0.1f : yaw);
            if (!accumulate) {
                pipeline.reset();
            }
            const ImageF light = host.render(pipeline, camera, i);
            if (i >= 20) {
                for (int y = 2; y < kH - 2; ++y) {
                    for (int x = 2; x < kW - 2; ++x) {
                        // Where this pixel's direction was in the last frame (a turn moves no ray's light).
                        const glm::vec3 ray = pixelRay(camera, float(x) + 0.5f, float(y) + 0.5f);
                        const glm::vec4 clip = lastCamera.viewProjection() * glm::vec4(ray, 0.0f);
                        const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
                        const glm::vec2 from(uv.x * float(kW), (1.0f - uv.y) * float(kH));
                        const glm::vec2 q = from - 0.5f;
                        const int x0 = int(std::floor(q.x)), y0 = int(std::floor(q.y));
                        const float fx = q.x - float(x0), fy = q.y - float(y0);
                        const auto at = [&](int px, int py) {
                            return luma(last.at(std::clamp(px, 0, kW - 1), std::clamp(py, 0, kH - 1)));
                        };
                        const float previous = (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
                                               fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
                        const float l = luma(light.at(x, y));
                        moved += std::abs(double(l) - double(previous));
                        mean += l;
                    }
                }
            }
            last = light;
            lastCamera = camera;
        }
        return mean > 0.0 ? moved / mean : 1.0;
    };
    for (int samples : {64, 16}) {
        const double accumulated = change(true, samples);
        const double alone = change(false, samples);
        std::printf(
            "volumetric light (shadow map, %d samples) on a slow pan: frame-to-frame change %.4f of the "
            "mean (march alone: %.4f)\n",
            samples, accumulated, alone);
        EXPECT_LE(accumulated, 0.02);
        EXPECT_LT(accumulated, samples == 16 ? 0.5 * alone : alone);
    }
}

// The history is rejected where the depth changed and dropped on a cut: after 12 frames under the roof the
// roof is taken away (the camera still). Where the depth changed (the roof became sky) with no unchanged
// pixel within 6 px, the light is what a fresh history gives at the same frame: nothing of the roof's
// shadowed light stays behind; where it did not change (the floor) the history carries on. A cut to the
// roof again gives the fresh history's frame everywhere.
TEST_F(GlTest, VolumetricShadowRejectsTheHistoryOnDepthChangeAndCut) {
    Camera camera = cameraLooking(0.0f, 0.0f);
    Host roofed;
    Host open(Scene{.roof = false});
    const ImageF depthRoofed = depthOf(roofed.scene(), camera), depthOpen = depthOf(open.scene(), camera);
    Pipeline pipeline({.settings = shadowSettings()});
    Pipeline fresh({.settings = shadowSettings()});
    for (std::uint64_t i = 0; i < 12; ++i) {
        roofed.render(pipeline, camera, i);
    }
    const ImageF after = open.render(pipeline, camera, 12);
    const ImageF first = open.render(fresh, camera, 12);
    const auto changed = [&](int x, int y) { return depthRoofed.at(x, y)[0] != depthOpen.at(x, y)[0]; };
    double changedError = 0.0, changedSum = 0.0, keptDifference = 0.0, keptSum = 0.0;
    int changedCount = 0;
    for (int y = 6; y < kH - 6; ++y) {
        for (int x = 6; x < kW - 6; ++x) {
            bool all = true, none = true;
            for (int dy = -6; dy <= 6; ++dy) {
                for (int dx = -6; dx <= 6; ++dx) {
                    all = all && changed(x + dx, y + dy);
                    none = none && !changed(x + dx, y + dy);
                }
            }
            const double a = luma(after.at(x, y)), f = luma(first.at(x, y));
            if (all) {
                changedError += std::abs(a - f);
                changedSum += f;
                ++changedCount;
            } else if (none) {
                keptDifference += std::abs(a - f);
                keptSum += f;
            }
        }
    }
    ASSERT_GT(changedCount, 100);
    std::printf("volumetric light (shadow map) after the roof went: %d pixels of changed depth differ from a "
                "fresh history by %.5f of their light; unchanged pixels by %.4f\n",
                changedCount, changedError / changedSum, keptDifference / keptSum);
    EXPECT_LE(changedError / changedSum, 1e-3);
    EXPECT_GT(keptDifference / keptSum, 0.01);

    camera.cut = true;
    const ImageF cut = roofed.render(pipeline, camera, 13);
    fresh.reset();
    const ImageF cutFresh = roofed.render(fresh, camera, 13);
    EXPECT_EQ(cut.rgba, cutFresh.rgba);
}

// Without a shadow map, auto and shadowmap run the screen-space rays: the same image, bit for bit, as mode
// screen; with one, auto marches the map (an image other than screen's, the same as shadowmap's).
TEST_F(GlTest, VolumetricShadowFallsBackToTheScreenRaysWithoutAMap) {
    const Camera camera = cameraLooking(0.0f, 0.0f);
    Host host;
    const auto run = [&](VolumetricLightMode mode, bool withMap) {
        Settings s = shadowSettings();
        s.volumetricLight.mode = mode;
        Pipeline pipeline({.settings = s});
        pipeline.reset();
        ImageF out;
        for (std::uint64_t i = 0; i < 3; ++i) {
            out = host.render(pipeline, camera, i, withMap);
        }
        return out;
    };
    const ImageF screen = run(VolumetricLightMode::Screen, true);
    EXPECT_EQ(run(VolumetricLightMode::Auto, false).rgba, screen.rgba);
    EXPECT_EQ(run(VolumetricLightMode::ShadowMap, false).rgba, screen.rgba);
    const ImageF marched = run(VolumetricLightMode::Auto, true);
    EXPECT_NE(marched.rgba, screen.rgba);
    EXPECT_EQ(run(VolumetricLightMode::ShadowMap, true).rgba, marched.rgba);
}

// The debug view holds the light the march added: the image with the pass minus the image without it, and
// bright where the reference is (in the shaft).
TEST_F(GlTest, VolumetricShadowDebugViewIsTheLightAdded) {
    const Camera camera = cameraLooking(0.0f, 0.0f);
    Host host;
    ImageF images[3];
    for (int i = 0; i < 3; ++i) {
        Settings s = shadowSettings();
        s.volumetricLight.enabled = i > 0;
        s.debug.view = i == 2 ? DebugView::VolumetricLight : DebugView::None;
        s.tonemapping.exposure = 0.0f;
        Pipeline pipeline({.settings = s});
        images[i] = host.still(pipeline, camera, 8);
    }
    double worst = 0.0, viewSum = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double added = double(images[1].at(x, y)[c]) - double(images[0].at(x, y)[c]);
                const double view = images[2].at(x, y)[c];
                worst = std::max(worst, std::abs(added - view) / (0.01 + std::abs(view)));
                viewSum += view;
            }
        }
    }
    std::printf("volumetric light (shadow map) debug view against image minus image: largest relative "
                "difference %.5f\n",
                worst);
    EXPECT_GT(viewSum, 0.0);
    EXPECT_LE(worst, 0.01);
}

// Broken inputs: a shadow map that is not a depth texture, a matrix with a NaN, a negative illuminance are
// each refused (named in the input errors; the screen rays run); NaN, infinite, zero and negative depths
// leave the image and the light finite.
TEST_F(GlTest, VolumetricShadowKeepsBrokenInputsOut) {
    const Camera camera = cameraLooking(0.0f, 0.0f);
    const Texture color = makeTexture(ImageF(kW, kH, 0.1f), "color");
    ImageF depth = depthOf(Scene{}, camera);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    depth.at(3, 6)[0] = nan;
    depth.at(5, 6)[0] = -kInf;
    depth.at(7, 6)[0] = 0.0f;
    depth.at(9, 6)[0] = -2.0f;
    depth.at(80, 20)[0] = nan;
    const Texture d = makeTexture(depth, "depth");
    const glm::mat4 worldToClip = lightProjection().viewProjection;
    const Texture map = shadowMapOf(Scene{}, worldToClip);
    const Texture notDepth({.extent = {8, 8}, .format = GL_R32F, .debugName = "not a depth map"});
    glm::mat4 nanMatrix = worldToClip;
    nanMatrix[1][2] = nan;
    const struct {
        SunShadowMap shadow;
        const char* error; ///< the start of the input error, or null
    } cases[] = {
        {{.depth = &map, .worldToClip = worldToClip, .illuminance = kIlluminance}, nullptr},
        {{.depth = &notDepth, .worldToClip = worldToClip}, "sunShadow.depth: format"},
        {{.depth = &map, .worldToClip = nanMatrix}, "sunShadow.worldToClip"},
        {{.depth = &map, .worldToClip = worldToClip, .illuminance = glm::vec3(1.0f, -1.0f, 1.0f)},
         "sunShadow.illuminance"},
    };
    for (const auto& c : cases) {
        for (DebugView view : {DebugView::VolumetricLight, DebugView::None}) {
            Settings s = shadowSettings();
            s.debug.view = view;
            Pipeline pipeline({.settings = s});
            for (std::uint64_t i = 0; i < 3; ++i) {
                pipeline.execute({.color = &color,
                                  .depth = &d,
                                  .depthKind = DepthKind::LinearView,
                                  .camera = &camera,
                                  .sunDirection = sunDirection(),
                                  .sunShadow = c.shadow},
                                 {.frameIndex = i});
            }
            const std::vector<std::string>& errors = pipeline.status().inputErrors;
            if (c.error) {
                ASSERT_EQ(errors.size(), 1u);
                EXPECT_EQ(errors[0].rfind(c.error, 0), 0u) << errors[0];
            } else {
                EXPECT_TRUE(errors.empty());
            }
            for (float v : readTextureF(pipeline.sceneReferred()).rgba) {
                ASSERT_TRUE(std::isfinite(v));
            }
        }
    }
}

} // namespace photopic::test
