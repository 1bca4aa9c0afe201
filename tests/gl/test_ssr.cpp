// Screen-space reflections against the testbed's ray-traced mirror reflection (`reflection` truth: the
// radiance along the mirror direction at each pixel centre on metals), read through the `ssr` debug view's
// raw values (RGB: the reflected radiance, A: the confidence) as a host or the CLI gets them.
//
// Pixels measured: the metal strip's, where the ray tracer's mirror ray from the pixel centre hits a surface
// whose point projects on screen and is the surface the camera sees there (the "resolvable" pixels); and the
// strip's pixels whose mirror ray leaves the screen or hits the sky ("unresolvable"), where the confidence
// must be exactly 0. Left out, and counted: strip pixels whose 3x3 neighbourhood is not all strip (the pixel
// footprint straddles the strip's edge), and reflected points whose 3x3 neighbourhood on screen is not one
// object (the reflection straddles a silhouette, where one pixel centre's ray and the depth buffer's pixel
// disagree about which object is hit).

#include "GlTest.h"
#include "OctahedralNormals.h"

#include "core/Quality.h"
#include "gl/Capabilities.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "passes/ssr/SsrPass.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedRenderer.h"
#include "scenes/testbed/TestbedScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;

testbed::TruthOptions stillOptions(float seconds) {
    TestbedScene scene;
    for (const std::string& a :
         {std::string("cameraSpeed=0"), std::string("objectSpeed=0"),
          "cameraStart=" + std::to_string(seconds), "objectStart=" + std::to_string(seconds)}) {
        EXPECT_TRUE(scene.applyOverride(a).empty()) << a;
    }
    scene.resize({kW, kH});
    return scene.truthOptions({.dt = kDt, .frameIndex = 0});
}

/// SSR traced and resolved but not added to the image (intensity 0): the ray tracer's truth is the local
/// shading of the reflected point, and with intensity 1 the history the resolve reads would hold the
/// reflections SSR added to that point (F0 0.04 on every dielectric), a second bounce the truth has not.
Settings ssrSettings(SsrResolution resolution = SsrResolution::Full) {
    Settings s;
    s.ssr.intensity = 0.0f;
    s.autoExposure.enabled = false;
    s.ssr.enabled = true;
    s.ssr.resolution = resolution;
    s.debug.view = DebugView::Ssr;
    return s;
}

/// How the frame hands SSR the testbed's normals: as view xyz, octahedral-encoded, or not at all (SSR
/// reconstructs them from the depth).
enum class NormalsFrom { ViewXyz, Octahedral, None };

/// Renders `frames` still frames of the testbed through the pipeline; returns the last frame's `ssr` view
/// (raw values).
ImageF renderSsr(const testbed::TruthOptions& options, const Settings& settings, int frames,
                 bool material = true, const Texture* colorOverride = nullptr,
                 const Texture* depthOverride = nullptr, const Texture* normalsOverride = nullptr,
                 NormalsFrom normalsFrom = NormalsFrom::ViewXyz) {
    testbed::TestbedRenderer renderer;
    renderer.resize({options.width, options.height});
    Pipeline pipeline({.settings = settings});
    const Camera camera = testbed::truthCamera(options);
    const std::vector<testbed::Primitive> prims =
        testbed::primitivesAt(options.times.objects, options.times.prevObjects);
    for (int i = 0; i < frames; ++i) {
        const FrameTime time{.dt = kDt, .frameIndex = std::uint64_t(i)};
        const glm::vec2 jitter = pipeline.beginFrame(time, &camera);
        renderer.draw({.camera = &camera, .jitter = jitter, .primitives = &prims});
        FrameInputs in{.color = colorOverride ? colorOverride : &renderer.color(),
                       .depth = depthOverride ? depthOverride : &renderer.depth(),
                       .depthKind = depthOverride ? DepthKind::LinearView : DepthKind::Standard,
                       .normals = normalsOverride ? normalsOverride : &renderer.normals(),
                       .motion = &renderer.motion(),
                       .camera = &camera,
                       .material = material ? &renderer.material() : nullptr};
        Texture octahedral;
        if (normalsFrom == NormalsFrom::Octahedral) {
            octahedral =
                makeTexture(octahedralEncoded(readTextureF(*in.normals)), "octahedral normals", GL_RG32F);
            in.normals = &octahedral;
            in.normalEncoding = NormalEncoding::Octahedral;
        } else if (normalsFrom == NormalsFrom::None) {
            in.normals = nullptr;
        }
        pipeline.execute(in, time);
        EXPECT_TRUE(pipeline.status().skipped.empty());
    }
    return readTextureF(pipeline.sceneReferred());
}

enum class PixelClass { Other, Resolvable, Unresolvable, Excluded };

/// Classifies the strip's pixels by where the ray tracer's mirror ray from the pixel centre ends.
std::vector<PixelClass> classify(const testbed::TruthOptions& o) {
    const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, o);
    const ImageF depth = testbed::renderTruth(testbed::TruthKind::Depth, o);
    testbed::TruthOptions centres = o;
    centres.samples = 1;
    const ImageF colour = testbed::renderTruth(testbed::TruthKind::Color, centres);
    const Camera camera = testbed::truthCamera(o);
    const std::vector<testbed::Primitive> prims = testbed::primitivesAt(o.times.objects, o.times.prevObjects);
    const auto id = [&](int x, int y) {
        return std::uint32_t(ids.at(std::clamp(x, 0, kW - 1), std::clamp(y, 0, kH - 1))[0]);
    };
    const auto uniform = [&](int x, int y) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if (id(x + dx, y + dy) != id(x, y)) {
                    return false;
                }
            }
        }
        return true;
    };
    // The 3x3 neighbourhood's colours within 25% of each other (no checker edge or shading step in it).
    const auto smooth = [&](int x, int y) {
        double lo = 1e30, hi = 0.0;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const float* c = colour.at(std::clamp(x + dx, 0, kW - 1), std::clamp(y + dy, 0, kH - 1));
                const double l = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
                lo = std::min(lo, l);
                hi = std::max(hi, l);
            }
        }
        return hi <= 1.25 * lo;
    };
    std::vector<PixelClass> classes(std::size_t(kW * kH), PixelClass::Other);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (id(x, y) != testbed::ids::kStrip) {
                continue;
            }
            PixelClass& c = classes[std::size_t(y * kW + x)];
            if (!uniform(x, y)) {
                c = PixelClass::Excluded;
                continue;
            }
            const glm::vec2 ndc(2.0f * (float(x) + 0.5f) / kW - 1.0f, 1.0f - 2.0f * (float(y) + 0.5f) / kH);
            const testbed::Ray ray = testbed::cameraRay(camera, ndc);
            testbed::Hit hit;
            if (!testbed::intersectScene(prims, ray, 0.0f, 1e4f, hit)) {
                c = PixelClass::Excluded;
                continue;
            }
            const glm::vec3 p = ray.origin + hit.t * ray.direction;
            const glm::vec3 r = glm::normalize(glm::reflect(ray.direction, hit.worldNormal));
            testbed::Hit second;
            if (!testbed::intersectScene(prims, {p + 1e-3f * hit.worldNormal, r}, 0.0f, 1e4f, second)) {
                c = PixelClass::Unresolvable; // the sky
                continue;
            }
            const glm::vec3 q = p + 1e-3f * hit.worldNormal + second.t * r;
            const glm::vec4 clip = camera.viewProjection() * glm::vec4(q, 1.0f);
            const glm::vec2 qn = glm::vec2(clip) / clip.w;
            const float qx = (qn.x + 1.0f) * 0.5f * kW;
            const float qy = (1.0f - qn.y) * 0.5f * kH;
            if (clip.w <= 0.0f || qx < 0.0f || qy < 0.0f || qx >= kW || qy >= kH) {
                c = PixelClass::Unresolvable;
                continue;
            }
            const int ix = int(qx);
            const int iy = int(qy);
            const float seen = depth.at(ix, iy)[0];
            const float qDepth = -(camera.view * glm::vec4(q, 1.0f)).z;
            if (!uniform(ix, iy) || !smooth(ix, iy) || !(std::abs(seen - qDepth) < 0.01f * qDepth)) {
                c = PixelClass::Excluded; // a silhouette or a colour edge, or hidden from the camera
                continue;
            }
            c = PixelClass::Resolvable;
        }
    }
    return classes;
}

struct Figures {
    int resolvable = 0, unresolvable = 0, excluded = 0;
    int covered = 0;           ///< resolvable pixels with confidence > 0
    double meanRelative = 0.0; ///< over covered pixels: |ssr - truth| / truth, luminance
    double p95Relative = 0.0;
    double within10 = 0.0;       ///< fraction of covered pixels within 10% of the truth
    int unresolvableNonZero = 0; ///< unresolvable pixels with confidence != 0
};

double luminance(const float* c) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

Figures measure(const ImageF& view, const ImageF& truth, const std::vector<PixelClass>& classes) {
    Figures f;
    std::vector<double> errors;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const PixelClass c = classes[std::size_t(y * kW + x)];
            const float* v = view.at(x, y);
            if (c == PixelClass::Excluded) {
                ++f.excluded;
            } else if (c == PixelClass::Unresolvable) {
                ++f.unresolvable;
                f.unresolvableNonZero += v[3] != 0.0f ? 1 : 0;
                // PHOTOPIC_SSR_DIAG=1 lists them (and the colour SSR gave them).
                if (v[3] != 0.0f && std::getenv("PHOTOPIC_SSR_DIAG")) {
                    std::printf("    unresolvable (%d, %d): confidence %.4f, colour %.4f %.4f %.4f\n", x, y,
                                v[3], v[0], v[1], v[2]);
                }
            } else if (c == PixelClass::Resolvable) {
                ++f.resolvable;
                if (v[3] > 0.0f) {
                    ++f.covered;
                    const double t = luminance(truth.at(x, y));
                    errors.push_back(std::abs(luminance(v) - t) / std::max(t, 1e-4));
                }
            }
        }
    }
    if (!errors.empty()) {
        double sum = 0.0;
        for (double e : errors) {
            sum += e;
        }
        f.meanRelative = sum / double(errors.size());
        f.within10 = double(std::count_if(errors.begin(), errors.end(), [](double e) { return e <= 0.1; })) /
                     double(errors.size());
        std::sort(errors.begin(), errors.end());
        f.p95Relative = errors[std::size_t(0.95 * double(errors.size() - 1))];
    }
    return f;
}

void print(const char* label, const Figures& f) {
    std::printf("  %s: resolvable %d (covered %d, %.1f%%), within 10%%: %.1f%%, relative error mean %.4f, "
                "p95 %.4f; unresolvable %d (confidence != 0: %d); excluded %d\n",
                label, f.resolvable, f.covered, 100.0 * f.covered / std::max(f.resolvable, 1),
                100.0 * f.within10, f.meanRelative, f.p95Relative, f.unresolvable, f.unresolvableNonZero,
                f.excluded);
}

/// A frame context of extent `e` with SSR on, for running one of SSR's passes alone.
struct LoneFrame {
    explicit LoneFrame(Extent e)
        : ctx{settings, tier, caps, in, time, e} {}
    Settings settings = [] {
        Settings s;
        s.ssr.enabled = true;
        return s;
    }();
    QualityTier tier = qualityTier(settings.quality);
    Capabilities caps = detectCapabilities();
    FrameInputs in;
    FrameTime time;
    FrameContext ctx; ///< last: it refers to the members above
};

} // namespace

TEST_F(GlTest, SsrMatchesTheRayTracedMirrorReflectionOnTheStrip) {
    for (float seconds : {0.3f, 0.9f}) {
        const testbed::TruthOptions o = stillOptions(seconds);
        const std::vector<PixelClass> classes = classify(o);
        const ImageF truth = testbed::renderTruth(testbed::TruthKind::Reflection, o);
        const Figures full = measure(renderSsr(o, ssrSettings(), 4), truth, classes);
        std::printf("path time %.1f s\n", double(seconds));
        print("full", full);
        EXPECT_GT(full.resolvable, 100);
        EXPECT_GT(full.unresolvable, 100);
        EXPECT_GE(full.covered, int(0.95 * full.resolvable)); // measured 100% and 100%
        // Measured 99.1% and 100% within 10%, p95 0.037 and 0.027, mean 0.016 and 0.009. The rest are hits
        // a pixel off across a step the 25% neighbourhood test lets through (a dark checker square reflected
        // as the light one beside it), which would dominate the mean: the bound is on the fraction and the
        // 95th percentile.
        EXPECT_GE(full.within10, 0.95);
        EXPECT_LE(full.p95Relative, 0.10);
        // Known limit: the poles are under a pixel wide here and thinner than `thickness`. A mirror ray that
        // crosses a pole's pixel within a quarter pixel of its centre, or passes behind the pole within
        // `thickness`, is taken as a hit where the ray tracer's ray passes beside the pole to the sky:
        // measured 1 of 200 and 3 of 338 unresolvable pixels. Bounded here, not yet 0.
        EXPECT_LE(full.unresolvableNonZero, int(0.02 * full.unresolvable));
        // The first frame has no history: the radiance is this frame's colour at the hit.
        const Figures first = measure(renderSsr(o, ssrSettings(), 1), truth, classes);
        print("first frame", first);
        EXPECT_GE(first.within10, 0.95);
        EXPECT_LE(first.p95Relative, 0.10);
        // Half resolution: the first pixel of each 2 x 2 block traces; every other pixel marches its own ray
        // where it passes the hits of the blocks around it, so it gets its own reflection, or none where its
        // ray misses what theirs hit: measured 100% covered, 99.1% and 100% within 10%, p95 0.037 and 0.027,
        // 0 and 2 unresolvable pixels with a confidence.
        const Figures half = measure(renderSsr(o, ssrSettings(SsrResolution::Half), 4), truth, classes);
        print("half", half);
        EXPECT_GE(half.covered, int(0.95 * half.resolvable));
        EXPECT_GE(half.within10, 0.95);
        EXPECT_LE(half.p95Relative, 0.10);
        EXPECT_LE(half.unresolvableNonZero, int(0.02 * half.unresolvable));
    }
}

// The trace is built once per source of normals. Octahedral-encoded normals give the reflections the view
// xyz ones give; without normals, SSR reconstructs them from the depth (measured at 0.3 s: octahedral 3 of
// 14400 px differ by more than 0.1%, the largest by 2.2%; reconstructed 95.7% covered, 92.8% within 10%).
TEST_F(GlTest, SsrReadsEverySourceOfNormals) {
    const testbed::TruthOptions o = stillOptions(0.3f);
    const std::vector<PixelClass> classes = classify(o);
    const ImageF truth = testbed::renderTruth(testbed::TruthKind::Reflection, o);
    const ImageF viewXyz = renderSsr(o, ssrSettings(), 2);
    const ImageF octahedral =
        renderSsr(o, ssrSettings(), 2, true, nullptr, nullptr, nullptr, NormalsFrom::Octahedral);
    // A normal decoded from its octahedral pair differs from the view xyz one in the last bits, and a mirror
    // ray that grazes a texel boundary may then end in the next texel: a few pixels differ a little.
    int differing = 0;
    double largest = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            double relative = 0.0;
            for (int c = 0; c < 4; ++c) {
                const double reference = viewXyz.at(x, y)[c];
                relative = std::max(relative, std::abs(octahedral.at(x, y)[c] - reference) /
                                                  std::max(std::abs(reference), 0.1));
            }
            differing += relative > 0.001 ? 1 : 0;
            largest = std::max(largest, relative);
        }
    }
    std::printf("ssr octahedral normals against view xyz: %d of %d px differ by > 0.1%%, largest %.4f\n",
                differing, kW * kH, largest);
    EXPECT_LE(differing, kW * kH / 1000);
    EXPECT_LE(largest, 0.05);
    // Known limit: a normal from the depths is the cross product of steps to the neighbours nearest in depth.
    // The misses sit in two neighbouring rows at one edge of the strip (8 of its 116 resolvable pixels),
    // where they reflect the wrong texels (a relative error up to 40 on a dark square): the bound is on the
    // fraction within 10%, not on the 95th percentile.
    const Figures reconstructed = measure(
        renderSsr(o, ssrSettings(), 4, true, nullptr, nullptr, nullptr, NormalsFrom::None), truth, classes);
    print("reconstructed normals", reconstructed);
    EXPECT_GE(reconstructed.covered, int(0.95 * reconstructed.resolvable));
    EXPECT_GE(reconstructed.within10, 0.90);
    EXPECT_LE(reconstructed.unresolvableNonZero, int(0.02 * reconstructed.unresolvable));
}

TEST_F(GlTest, SsrStaysFiniteWithNonFiniteInputs) {
    const testbed::TruthOptions o = stillOptions(0.3f);
    // Linear depth, normals and colour with NaN, +-Inf, zero and negative values in a pattern.
    const float bad[] = {std::numeric_limits<float>::quiet_NaN(),
                         std::numeric_limits<float>::infinity(),
                         -std::numeric_limits<float>::infinity(),
                         0.0f,
                         -1.0f,
                         1e30f};
    ImageF depth(kW, kH, 5.0f), normals(kW, kH, 0.0f), color(kW, kH, 1.0f);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const int k = (x * 7 + y * 3) % 9;
            depth.at(x, y)[0] = k < 6 ? bad[k] : 2.0f + 0.05f * float(y);
            float* n = normals.at(x, y);
            n[0] = k < 6 ? bad[(k + 1) % 6] : 0.0f;
            n[1] = k < 6 ? bad[(k + 2) % 6] : 1.0f;
            n[2] = 0.0f;
            color.at(x, y)[0] = k < 6 ? bad[(k + 3) % 6] : 1.0f;
        }
    }
    const Texture depthTexture = makeTexture(depth, "bad depth");
    const Texture normalTexture = makeTexture(normals, "bad normals");
    const Texture colorTexture = makeTexture(color, "bad colour");
    for (bool material : {true, false}) {
        const ImageF view =
            renderSsr(o, ssrSettings(), 3, material, &colorTexture, &depthTexture, &normalTexture);
        int nonFinite = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                for (int c = 0; c < 4; ++c) {
                    nonFinite += std::isfinite(view.at(x, y)[c]) ? 0 : 1;
                }
            }
        }
        EXPECT_EQ(nonFinite, 0);
    }
}

// The history the glossy cones read next frame: level 0 the sanitised scene colour, each further level the
// box mean of the level below (so of level 0's 2^L x 2^L block), as many levels as the smaller side allows up
// to six, on a size no tile divides (83 x 45: the tiles' overhang, odd rows and columns each level leaves
// out) and with values the sanitising must clean (NaN, infinities, negatives, past half float's range); the
// one-dispatch build (a GPU's) and the dispatch-a-level build (a software renderer's) alike.
TEST_F(GlTest, SsrHistoryIsTheSanitisedSceneAndItsBoxMeans) {
    const int w = 83, h = 45;
    ImageF scene(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float* c = scene.at(x, y);
            c[0] = float((x * 7 + y * 13) % 31) * 0.37f;
            c[1] = float((x * x + 3 * y) % 17) * 2.5f;
            c[2] = 0.01f * float(x + y);
            c[3] = 1.0f;
        }
    }
    scene.at(3, 4)[0] = std::numeric_limits<float>::quiet_NaN();
    scene.at(40, 20)[1] = std::numeric_limits<float>::infinity();
    scene.at(41, 20)[2] = -5.0f;
    scene.at(80, 44)[0] = 1e9f; // RGBA16F: +inf after the upload's rounding
    const Texture input = makeTexture(scene, "ssr history scene", GL_RGBA16F);
    const ImageF stored = readTextureF(input); // the half floats the pass reads, rows top to bottom
    auto clean = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 65000.0f) : 0.0f; };

    // Both builds: one dispatch through shared memory (a GPU's) and a dispatch a level (a software
    // renderer's), each level read back.
    std::vector<std::vector<float>> chains[2];
    for (const bool shared : {false, true}) {
        forceSharedMemoryTiles(shared);
        LoneFrame frame(Extent{w, h});
        FrameResources resources;
        resources.bind(Resource::SceneColor, input);
        SsrHistoryPass pass;
        pass.execute(frame.ctx, resources);
        ASSERT_NE(pass.previous(), nullptr);
        const Texture& history = *pass.previous();
        glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        GLint levels = 0;
        glGetTextureParameteriv(history.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        ASSERT_EQ(levels, 6);
        for (int level = 0; level < levels; ++level) {
            const int lw = std::max(1, w >> level), lh = std::max(1, h >> level);
            std::vector<float> texels(std::size_t(lw) * lh * 4);
            glGetTextureImage(history.id(), level, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                              texels.data());
            chains[shared ? 1 : 0].push_back(texels);
        }
    }
    ASSERT_EQ(chains[0].size(), chains[1].size());
    for (std::size_t k = 0; k < 2 * chains[0].size(); ++k) {
        const int level = int(k % chains[0].size());
        const std::vector<float>& texels = chains[k / chains[0].size()][std::size_t(level)];
        // Each checked against the CPU below (a GPU may round a half float either way when it stores one).
        const int lw = std::max(1, w >> level), lh = std::max(1, h >> level);
        double worst = 0.0;
        for (int ty = 0; ty < lh; ++ty) {
            for (int tx = 0; tx < lw; ++tx) {
                const int block = 1 << level;
                for (int c = 0; c < 3; ++c) {
                    double sum = 0.0;
                    for (int by = 0; by < block; ++by) {
                        for (int bx = 0; bx < block; ++bx) {
                            // Texel (x, y) of GL's level 0 is the image's row h - 1 - y.
                            sum += clean(stored.at(tx * block + bx, h - 1 - (ty * block + by))[c]);
                        }
                    }
                    const double expected = sum / double(block * block);
                    const double got = texels[(std::size_t(ty) * lw + tx) * 4 + c];
                    // Half float's rounding of the result (and of each level's mean it was made from).
                    worst = std::max(worst, std::abs(got - expected) / std::max(std::abs(expected), 1e-2));
                }
                EXPECT_EQ(texels[(std::size_t(ty) * lw + tx) * 4 + 3], 1.0f);
            }
        }
        EXPECT_LE(worst, 2e-3) << "level " << level << " (" << lw << " x " << lh << "), "
                               << (k < chains[0].size() ? "a dispatch a level" : "one dispatch");
    }
}

// The depth pyramid the march climbs: level 0 the linear depth with broken depths (NaN, zero, negative,
// infinite) and the padding as the sky, each further level the nearest (R) and the farthest (G) of the 2 x 2
// cells below, the sky having no farthest depth (0), every level at its place in the atlas; on sizes whose
// tiles overhang the image and the pyramid (150 x 70: seven levels; 20 x 9: four, a 64 x 64 tile over a
// 24 x 16 level 0) and on one pixel, built in one dispatch through shared memory (a GPU's build) and a
// dispatch a level (a software renderer's).
TEST_F(GlTest, SsrDepthPyramidIsTheNearestAndFarthestDepthOfEachCell) {
    const Extent sizes[] = {{150, 70}, {20, 9}, {1, 1}};
    const float inf = std::numeric_limits<float>::infinity();
    for (const Extent e : sizes) {
        ImageF depth(e.width, e.height);
        for (int y = 0; y < e.height; ++y) {
            for (int x = 0; x < e.width; ++x) {
                depth.at(x, y)[0] = 0.5f + float((x * 37 + y * 11) % 101) * 0.25f;
            }
        }
        if (e.width > 10) {
            depth.at(3, 2)[0] = std::numeric_limits<float>::quiet_NaN();
            depth.at(4, 2)[0] = 0.0f;
            depth.at(5, 2)[0] = -1.0f;
            depth.at(6, 2)[0] = inf;
            depth.at(7, 2)[0] = 0.01f; // the nearest of the image: every level's cell over it keeps it
        }
        const Texture linear = makeTexture(depth, "pyramid test depth", GL_R32F);
        const ImageF stored = readTextureF(linear); // rows top to bottom

        // Both builds: one dispatch through shared memory (a GPU's) and a dispatch a level (a software
        // renderer's); each is checked below.
        ImageF atlases[2];
        for (const bool shared : {false, true}) {
            forceSharedMemoryTiles(shared);
            LoneFrame frame(e);
            FrameResources resources;
            resources.bind(Resource::LinearDepth, linear);
            DepthPyramidPass pass;
            pass.execute(frame.ctx, resources);
            const Texture* pyramid = resources.texture(Resource::DepthPyramid);
            ASSERT_NE(pyramid, nullptr);
            ASSERT_EQ(pyramid->extent(), depthPyramidAtlasExtent(e));
            glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
            atlases[shared ? 1 : 0] = readTextureF(*pyramid);
        }
        for (const ImageF& atlas : atlases) {
            const int levels = depthPyramidLevels(e);
            const Extent size0 = depthPyramidExtent(e);
            auto atlasAt = [&](int x, int y, int channel = 0) {
                return atlas.at(x, atlas.height - 1 - y)[channel];
            }; // GL texel (x, y)

            // Level by level, in GL's texel order (row 0 at the bottom): (nearest, farthest).
            std::vector<std::pair<float, float>> level(std::size_t(size0.width) * size0.height);
            for (int y = 0; y < size0.height; ++y) {
                for (int x = 0; x < size0.width; ++x) {
                    const float z = x < e.width && y < e.height ? stored.at(x, e.height - 1 - y)[0] : inf;
                    const bool surface = std::isfinite(z) && z > 0.0f;
                    level[std::size_t(y) * size0.width + x] = {surface ? z : inf, surface ? z : 0.0f};
                }
            }
            int mismatches = 0;
            for (int l = 0; l < levels; ++l) {
                const int lw = size0.width >> l, lh = size0.height >> l;
                const int ox = l == 0 ? 0 : size0.width,
                          oy = l == 0 ? 0 : size0.height - (size0.height >> (l - 1));
                if (l > 0) {
                    std::vector<std::pair<float, float>> next(std::size_t(lw) * lh);
                    const int pw = size0.width >> (l - 1);
                    for (int y = 0; y < lh; ++y) {
                        for (int x = 0; x < lw; ++x) {
                            auto below = [&](int dx, int dy) {
                                return level[std::size_t(2 * y + dy) * pw + std::size_t(2 * x + dx)];
                            };
                            const auto a = below(0, 0), b = below(1, 0), c = below(0, 1), d = below(1, 1);
                            next[std::size_t(y) * lw + x] = {
                                std::min(std::min(a.first, b.first), std::min(c.first, d.first)),
                                std::max(std::max(a.second, b.second), std::max(c.second, d.second))};
                        }
                    }
                    level = std::move(next);
                }
                for (int y = 0; y < lh; ++y) {
                    for (int x = 0; x < lw; ++x) {
                        const auto [nearest, farthest] = level[std::size_t(y) * lw + x];
                        const float gotNearest = atlasAt(ox + x, oy + y, 0);
                        const float gotFarthest = atlasAt(ox + x, oy + y, 1);
                        if ((gotNearest != nearest || gotFarthest != farthest) && mismatches++ < 5) {
                            ADD_FAILURE() << e.width << " x " << e.height << " level " << l << " cell (" << x
                                          << ", " << y << "): (" << gotNearest << ", " << gotFarthest
                                          << "), expected (" << nearest << ", " << farthest << ")";
                        }
                    }
                }
            }
            EXPECT_EQ(mismatches, 0) << e.width << " x " << e.height << ", " << levels << " levels, "
                                     << (&atlas == &atlases[0] ? "a dispatch a level" : "one dispatch");
            if (e.width > 10) {
                // Image pixel (7, 2) is GL texel (7, height - 3); level 1 sits at x = size0.width, y = 0.
                EXPECT_EQ(atlasAt(size0.width + 3, (e.height - 3) / 2), 0.01f)
                    << "level 1 keeps the nearest depth";
                // Its 2 x 2 cell: the sky at image pixel (6, 2) leaves the farthest to the other three.
                const int cellRow = (e.height - 3) / 2; // GL rows 2 cellRow and 2 cellRow + 1
                float farthest = 0.0f;
                for (const int row : {e.height - 1 - 2 * cellRow, e.height - 2 - 2 * cellRow}) {
                    for (const int x : {6, 7}) {
                        const float z = stored.at(x, row)[0];
                        farthest = std::isfinite(z) && z > 0.0f ? std::max(farthest, z) : farthest;
                    }
                }
                EXPECT_GT(farthest, 0.01f);
                EXPECT_EQ(atlasAt(size0.width + 3, cellRow, 1), farthest)
                    << "level 1's farthest depth leaves the sky out";
            }
        }
    }
}

} // namespace photopic::test
