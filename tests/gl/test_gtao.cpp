// GTAO against the testbed's ray-traced ambient occlusion (same radius, cosine-weighted): the visibility the
// lighting stage hands the host, on a still frame at 160x90.

#include "GlTest.h"
#include "OctahedralNormals.h"

#include "core/Quality.h"
#include "gl/Capabilities.h"
#include "gl/TextureIo.h"
#include "passes/gtao/GtaoPass.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedScene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;

std::unique_ptr<TestbedScene> stillScene(float cameraTime) {
    auto scene = std::make_unique<TestbedScene>();
    for (const std::string& a : {std::string("cameraSpeed=0"), std::string("objectSpeed=0"),
                                 "cameraStart=" + std::to_string(cameraTime)}) {
        EXPECT_TRUE(scene->applyOverride(a).empty()) << a;
    }
    scene->resize({kW, kH});
    return scene;
}

Settings aoSettings(GtaoResolution resolution, bool sampleMips = false) {
    Settings s;
    s.gtao.sampleMips = sampleMips;
    s.autoExposure.enabled = false;
    s.gtao.enabled = true;
    s.gtao.radius = 1.0f; // the testbed's aoRadius default: the reference's
    s.gtao.resolution = resolution;
    return s;
}

/// The lighting stage's visibility for frame `frame` of `scene` (rows top to bottom, R).
ImageF gtaoVisibility(TestbedScene& scene, Pipeline& pipeline, std::uint64_t frame) {
    std::vector<double> telemetry;
    const FrameTime time{.dt = kDt, .frameIndex = frame};
    const FrameInputs in = scene.render(time, pipeline, telemetry);
    const LightingOutputs& lit = pipeline.renderLighting(in, time);
    EXPECT_NE(lit.ambientOcclusion, nullptr);
    ImageF out = lit.ambientOcclusion ? readTextureF(*lit.ambientOcclusion) : ImageF(kW, kH, 1.0f);
    pipeline.execute(in, time);
    return out;
}

struct AoFigures {
    double mae = 0.0;       ///< over pixels with reference visibility < 0.95
    double bias = 0.0;      ///< mean signed error (GTAO - reference) over the same pixels
    long occluded = 0;      ///< how many
    double halo = 1.0;      ///< mean GTAO visibility on the background side of silhouettes
    double haloTruth = 1.0; ///< the reference's mean over the same band
    long band = 0;
    double clearHalo = 1.0; ///< GTAO's mean over the band's pixels the reference sees unoccluded (>= 0.97)
    long clearBand = 0;
};

/// The background side of a silhouette: a surface pixel with, within 3 px, a surface nearer by more than the
/// radius (an occluder the reference does not count).
AoFigures measure(const ImageF& gtao, const ImageF& truth, const ImageF& depth, float radius) {
    AoFigures f;
    double abs = 0.0, signedSum = 0.0, halo = 0.0, haloTruth = 0.0, clearHalo = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const double g = gtao.at(x, y)[0];
            const double t = truth.at(x, y)[0];
            const float z = depth.at(x, y)[0];
            if (t < 0.95) {
                abs += std::abs(g - t);
                signedSum += g - t;
                ++f.occluded;
            }
            if (!std::isfinite(z)) {
                continue;
            }
            bool background = false;
            for (int dy = -3; dy <= 3 && !background; ++dy) {
                for (int dx = -3; dx <= 3 && !background; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= kW || qy >= kH) {
                        continue;
                    }
                    const float zq = depth.at(qx, qy)[0];
                    background = std::isfinite(zq) && zq < z - radius;
                }
            }
            if (background) {
                halo += g;
                haloTruth += t;
                ++f.band;
                if (t >= 0.97) {
                    clearHalo += g;
                    ++f.clearBand;
                }
            }
        }
    }
    f.mae = f.occluded ? abs / double(f.occluded) : 0.0;
    f.bias = f.occluded ? signedSum / double(f.occluded) : 0.0;
    f.halo = f.band ? halo / double(f.band) : 1.0;
    f.haloTruth = f.band ? haloTruth / double(f.band) : 1.0;
    f.clearHalo = f.clearBand ? clearHalo / double(f.clearBand) : 1.0;
    return f;
}

} // namespace

// Still camera (path time 0.3 s): the lighting stage's visibility against the ray tracer's `ao` (16 x 16
// cosine-weighted rays, the same radius). Over the occluded pixels (reference < 0.95): mean absolute error
// <= 0.08 and bias within +-0.03 (measured 0.050 and +0.005). No halo: over the clear band, GTAO's mean
// visibility >= 0.97 (measured 0.979). The clear band is the background side of silhouettes (a surface pixel
// with, within 3 px, a surface nearer by more than the radius) where the ray-traced visibility is >= 0.97:
// nothing occludes there, so darkening is a halo. The whole band is printed too (GTAO 0.918, the reference
// itself 0.932: the band takes in occluded ground at the feet of objects, so no bound near 1 holds for it).
// Half resolution stays within 0.02 of full resolution's error (measured 0.063).
TEST_F(GlTest, GtaoMatchesTheRayTracedAmbientOcclusion) {
    auto scene = stillScene(0.3f);
    const testbed::TruthOptions options = scene->truthOptions({.dt = kDt, .frameIndex = 0});
    ASSERT_EQ(options.aoRadius, 1.0f);
    const ImageF truth = testbed::renderTruth(testbed::TruthKind::Ao, options);
    const ImageF depth = testbed::renderTruth(testbed::TruthKind::Depth, options);

    Pipeline full({.settings = aoSettings(GtaoResolution::Full)});
    const ImageF gtao = gtaoVisibility(*scene, full, 0);
    const AoFigures f = measure(gtao, truth, depth, options.aoRadius);
    std::printf("gtao full (high, radius 1): MAE %.4f, bias %+.4f over %ld occluded px; halo band mean %.4f "
                "(reference %.4f) over %ld px\n",
                f.mae, f.bias, f.occluded, f.halo, f.haloTruth, f.band);
    std::printf("gtao full: clear band (background side, reference >= 0.97): mean %.4f over %ld px\n",
                f.clearHalo, f.clearBand);

    Pipeline half({.settings = aoSettings(GtaoResolution::Half)});
    const AoFigures h = measure(gtaoVisibility(*scene, half, 0), truth, depth, options.aoRadius);
    std::printf("gtao half (high, radius 1): MAE %.4f, bias %+.4f; halo band mean %.4f\n", h.mae, h.bias,
                h.halo);

    Pipeline mips({.settings = aoSettings(GtaoResolution::Full, true)});
    const AoFigures m = measure(gtaoVisibility(*scene, mips, 0), truth, depth, options.aoRadius);
    std::printf("gtao full from the surface pyramid: MAE %.4f, bias %+.4f; clear band mean %.4f\n", m.mae,
                m.bias, m.clearHalo);

    EXPECT_GT(f.occluded, 100);
    EXPECT_GT(f.band, 20);
    EXPECT_GT(f.clearBand, 500);
    EXPECT_LE(f.mae, 0.08);
    EXPECT_LE(std::abs(f.bias), 0.03);
    EXPECT_GE(f.clearHalo, 0.97);
    EXPECT_LE(std::abs(h.mae - f.mae), 0.02);
    EXPECT_LE(m.mae, 0.08);
    EXPECT_LE(std::abs(m.bias), 0.03);
    EXPECT_GE(m.clearHalo, 0.97);

    // At radius 1 the far steps span up to about 15 px here, so the pyramid's levels 1-2 take few of them;
    // at radius 3 they reach levels 2-3 (cells of 4 and 8 px), as a 1080p frame's do at radius 1.
    testbed::TruthOptions wide = options;
    wide.aoRadius = 3.0f;
    const ImageF wideTruth = testbed::renderTruth(testbed::TruthKind::Ao, wide);
    AoFigures wideFigures[2];
    for (const bool sampleMips : {false, true}) {
        Settings settings = aoSettings(GtaoResolution::Full, sampleMips);
        settings.gtao.radius = wide.aoRadius;
        Pipeline pipeline({.settings = settings});
        const AoFigures w = measure(gtaoVisibility(*scene, pipeline, 0), wideTruth, depth, wide.aoRadius);
        std::printf(
            "gtao full (high, radius 3)%s: MAE %.4f, bias %+.4f over %ld occluded px; clear band %.4f\n",
            sampleMips ? " from the surface pyramid" : "", w.mae, w.bias, w.occluded, w.clearHalo);
        wideFigures[sampleMips ? 1 : 0] = w;
    }
    EXPECT_LE(wideFigures[1].mae - wideFigures[0].mae, 0.01);
}

// A slow orbit (the camera path at a tenth of its speed): the mean per-pixel change of visibility between
// consecutive frames, over occluded pixels, stays <= 0.02 although the noise pattern moves every frame
// (measured 0.018).
TEST_F(GlTest, GtaoIsStableUnderASlowOrbit) {
    for (const bool mips : {false, true}) {
        auto scene = std::make_unique<TestbedScene>();
        for (const char* a : {"cameraSpeed=0.1", "objectSpeed=0", "cameraStart=0.3"}) {
            EXPECT_TRUE(scene->applyOverride(a).empty()) << a;
        }
        scene->resize({kW, kH});
        Pipeline pipeline({.settings = aoSettings(GtaoResolution::Full, mips)});
        ImageF previous;
        double change = 0.0;
        long count = 0;
        for (std::uint64_t frame = 0; frame < 12; ++frame) {
            ImageF current = gtaoVisibility(*scene, pipeline, frame);
            if (frame >= 4) {
                for (int y = 0; y < kH; ++y) {
                    for (int x = 0; x < kW; ++x) {
                        const float a = current.at(x, y)[0], b = previous.at(x, y)[0];
                        if (a < 1.0f || b < 1.0f) {
                            change += std::abs(double(a) - b);
                            ++count;
                        }
                    }
                }
            }
            previous = std::move(current);
        }
        const double mean = count ? change / double(count) : 0.0;
        std::printf("gtao slow orbit%s: mean frame-to-frame change %.4f over %ld px\n",
                    mips ? " (surface pyramid)" : "", mean, count);
        EXPECT_GT(count, 1000);
        EXPECT_LE(mean, 0.02);
    }
}

// The surface pyramid ssao.sampleMips reads: level 0 is the packing without it, bit for bit; each coarse
// level's texel is the level-0 texel of a pixel of its 2^L block (within the image where the block overhangs
// it), the pixel's place in the block in the depth's low 8 bits (the sky's bits unchanged), its normal's
// bits unchanged; and the places spread over the block (no fixed corner). On a size whose blocks overhang
// the image at every level (150 x 70), one that is smaller than a level-4 block (13 x 5), and one pixel.
TEST_F(GlTest, GtaoSurfacePyramidKeepsARealPixelOfEachBlock) {
    const float inf = std::numeric_limits<float>::infinity();
    for (const Extent e : {Extent{150, 70}, Extent{13, 5}, Extent{1, 1}}) {
        ImageF depth(e.width, e.height), normals(e.width, e.height);
        for (int y = 0; y < e.height; ++y) {
            for (int x = 0; x < e.width; ++x) {
                depth.at(x, y)[0] = (x * 7 + y * 3) % 23 == 0 ? inf : 0.5f + float((x * 37 + y * 11) % 101);
                const float a = float(x) * 0.3f, b = float(y) * 0.2f;
                float* n = normals.at(x, y);
                n[0] = std::cos(a) * std::sin(b);
                n[1] = std::sin(a) * std::sin(b);
                n[2] = std::cos(b);
            }
        }
        const Texture linear = makeTexture(depth, "pyramid test depth", GL_R32F);
        const Texture normalTexture = makeTexture(normals, "pyramid test normals", GL_RGBA16F);
        const Camera camera{.projection =
                                perspectiveProjection(1.0f, float(e.width) / float(e.height), 0.1f, 100.0f)};
        std::vector<std::uint32_t> plain, pyramid;
        Extent pyramidExtent{};
        for (const bool mips : {false, true}) {
            Settings settings;
            settings.gtao.enabled = true;
            settings.gtao.sampleMips = mips;
            const QualityTier tier = qualityTier(settings.quality);
            const Capabilities caps = detectCapabilities();
            FrameInputs in;
            in.camera = &camera;
            const FrameTime time;
            FrameContext ctx{settings, tier, caps, in, time, e};
            FrameResources resources;
            resources.bind(Resource::LinearDepth, linear);
            resources.bind(Resource::Normals, normalTexture);
            GtaoPass pass(GtaoPass::Stage::Lighting);
            const Texture& surface = pass.packSurface(ctx, resources);
            ASSERT_EQ(surface.extent(), mips ? GtaoPass::surfacePyramidExtent(e) : e);
            glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT); // the pass's image stores, for the read below
            (mips ? pyramid : plain) = readTextureU32(surface, 2);
            pyramidExtent = surface.extent();
        }
        // Word k of GL texel (x, y) (row 0 at the bottom, as the shaders address them) of the plain surface
        // or the pyramid, which readTextureU32 hands over rows top to bottom.
        auto word = [&](const std::vector<std::uint32_t>& t, int x, int y, int k) {
            const Extent size = &t == &pyramid ? pyramidExtent : e;
            return t[(std::size_t(size.height - 1 - y) * size.width + x) * 2 + k];
        };
        for (int y = 0; y < e.height; ++y) {
            for (int x = 0; x < e.width; ++x) {
                for (int k = 0; k < 2; ++k) {
                    ASSERT_EQ(word(pyramid, x, y, k), word(plain, x, y, k)) << x << ", " << y;
                }
            }
        }
        const int band = (e.height + 15) & ~15;
        for (int level = 1; level <= GtaoPass::kSurfaceLevels; ++level) {
            const int lw = ((e.width - 1) >> level) + 1, lh = ((e.height - 1) >> level) + 1;
            const int ox = e.width, oy = band - (band >> (level - 1));
            ASSERT_LE(ox + lw, pyramidExtent.width);
            ASSERT_LE(oy + lh, pyramidExtent.height);
            std::vector<int> places(std::size_t(1) << (2 * level), 0);
            int cells = 0, interior = 0;
            for (int cy = 0; cy < lh; ++cy) {
                for (int cx = 0; cx < lw; ++cx) {
                    const std::uint32_t zBits = word(pyramid, ox + cx, oy + cy, 0);
                    const std::uint32_t nBits = word(pyramid, ox + cx, oy + cy, 1);
                    float z = 0.0f;
                    std::memcpy(&z, &zBits, 4);
                    const bool sky = std::isinf(z);
                    // The pixel the texel names (a sky texel names none: its bits are level 0's at some
                    // pixel of the block, found by search).
                    int px = -1, py = -1;
                    for (int by = 0; by < (1 << level) && px < 0; ++by) {
                        for (int bx = 0; bx < (1 << level) && px < 0; ++bx) {
                            const int x = (cx << level) + bx, y = (cy << level) + by;
                            if (x >= e.width || y >= e.height) {
                                continue;
                            }
                            const std::uint32_t z0 = word(plain, x, y, 0);
                            const bool named = sky ? z0 == zBits
                                                   : (z0 & 0xFFFFFF00u) == (zBits & 0xFFFFFF00u) &&
                                                         int(zBits & 15u) == bx &&
                                                         int((zBits >> 4) & 15u) == by;
                            if (named && word(plain, x, y, 1) == nBits) {
                                px = x;
                                py = y;
                            }
                        }
                    }
                    ASSERT_GE(px, 0) << "level " << level << " cell " << cx << ", " << cy << " of " << e.width
                                     << " x " << e.height << " holds no pixel of its block";
                    ++cells;
                    if (!sky && (cx + 1) << level <= e.width && (cy + 1) << level <= e.height) {
                        ++interior;
                        ++places[std::size_t((py - (cy << level)) * (1 << level) + (px - (cx << level)))];
                    }
                }
            }
            EXPECT_EQ(cells, lw * lh);
            // Spread: with 20 or more whole blocks, no place of the block takes more than half of them.
            if (interior >= 20) {
                const int most = *std::max_element(places.begin(), places.end());
                EXPECT_LE(most, interior / 2) << "level " << level << " of " << e.width << " x " << e.height;
            }
        }
    }
}

// ssao off: the lighting stage hands no texture. apply = multiply: the lighting stage hands none either (the
// post stage multiplies the scene colour instead), and the post image is darker where the surface is
// occluded.
TEST_F(GlTest, GtaoRunsInTheStageItsApplyModeNames) {
    auto scene = stillScene(0.3f);
    const FrameTime time{.dt = kDt, .frameIndex = 0};
    std::vector<double> telemetry;

    Settings off = aoSettings(GtaoResolution::Full);
    off.gtao.enabled = false;
    Pipeline plain({.settings = off});
    FrameInputs in = scene->render(time, plain, telemetry);
    EXPECT_EQ(plain.renderLighting(in, time).ambientOcclusion, nullptr);
    const ImageF without = readTextureF(plain.execute(in, time));

    Settings multiply = aoSettings(GtaoResolution::Full);
    multiply.gtao.apply = GtaoApply::Multiply;
    Pipeline post({.settings = multiply});
    in = scene->render(time, post, telemetry);
    EXPECT_EQ(post.renderLighting(in, time).ambientOcclusion, nullptr);
    const ImageF with = readTextureF(post.execute(in, time));
    const PipelineStatus status = post.status();
    EXPECT_NE(std::find(status.ran.begin(), status.ran.end(), "ao multiply"), status.ran.end());
    double sumWithout = 0.0, sumWith = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            sumWithout += without.at(x, y)[1];
            sumWith += with.at(x, y)[1];
        }
    }
    EXPECT_LT(sumWith, sumWithout);
}

// The host may hand normals octahedral-encoded (RG): GTAO reads them as the same directions. The testbed's
// view-space normals encoded on the CPU (Cigolle et al. 2014) into an RG32F texture give the visibility the
// view xyz normals give, to the precision of the pass's own 16-bit packing (measured: largest difference
// 0.0000 over the frame).
TEST_F(GlTest, GtaoReadsOctahedralNormalsAsTheDirectionsTheyEncode) {
    auto scene = stillScene(0.3f);
    const FrameTime time{.dt = kDt, .frameIndex = 0};
    std::vector<double> telemetry;
    Pipeline viewXyz({.settings = aoSettings(GtaoResolution::Full)});
    FrameInputs in = scene->render(time, viewXyz, telemetry);
    ASSERT_NE(in.normals, nullptr);
    const ImageF reference = readTextureF(*viewXyz.renderLighting(in, time).ambientOcclusion);

    const ImageF encoded = octahedralEncoded(readTextureF(*in.normals));
    const Texture octahedral = makeTexture(encoded, "octahedral normals", GL_RG32F);
    in.normals = &octahedral;
    in.normalEncoding = NormalEncoding::Octahedral;
    Pipeline octa({.settings = aoSettings(GtaoResolution::Full)});
    const LightingOutputs& lit = octa.renderLighting(in, time);
    ASSERT_NE(lit.ambientOcclusion, nullptr);
    const ImageF decoded = readTextureF(*lit.ambientOcclusion);
    double largest = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            largest = std::max(largest, double(std::abs(decoded.at(x, y)[0] - reference.at(x, y)[0])));
        }
    }
    std::printf("gtao octahedral normals against view xyz: largest difference %.4f\n", largest);
    EXPECT_LE(largest, 0.01);
}

} // namespace photopic::test
