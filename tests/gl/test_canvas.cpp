// The canvas scene on the GPU: highlights travel with the tilt, glitter sparkles above 1.0 only at
// its peak, the tiled and full-screen paths agree, the tile count, and bad input files.

#include "GlTest.h"

#include "core/Color.h"
#include "core/Motion.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"
#include "scenes/Scene.h"
#include "scenes/canvas/CanvasRenderer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

namespace photopic::test {

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "photopic_canvas_tests";
    fs::create_directories(dir);
    return dir / name;
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::unique_ptr<Scene> canvasScene(Extent size, const std::vector<std::string>& overrides) {
    auto scene = makeScene("canvas");
    for (const auto& o : overrides) {
        const auto issues = scene->applyOverride(o);
        EXPECT_TRUE(issues.empty()) << o << ": " << (issues.empty() ? "" : issues[0].message);
    }
    scene->resize(size);
    return scene;
}

struct Rendered {
    Image8 display;
    ImageF hdr;
    std::vector<double> telemetry;
};

Rendered renderFrame(Scene& scene, Pipeline& pipeline, std::uint64_t frame, float dt = 1.0f) {
    Rendered r;
    const FrameTime time{.dt = dt, .frameIndex = frame};
    const FrameInputs inputs = scene.render(time, pipeline, r.telemetry);
    r.hdr = readTextureF(*inputs.color);
    r.display = readTexture8(pipeline.execute(inputs, time));
    return r;
}

Settings displaySettings(const Scene& scene) {
    Settings s = scene.defaultSettings();
    s.output.dither = false; // compare curves, not dither patterns
    return s;
}

/// Centroid (x, row top-down) of the light `a` has more than `b` (both read back from the scene's HDR
/// texture). Scene-linear, because the display encoding would weigh the same highlight more on dark paint.
glm::vec2 brighteningCentroid(const ImageF& a, const ImageF& b) {
    double sx = 0, sy = 0, sw = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const auto luma = [&](const ImageF& im) {
                const float* p = im.at(x, y);
                return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            };
            const double w = std::max(0.0, luma(a) - luma(b));
            sx += w * x;
            sy += w * y;
            sw += w;
        }
    }
    EXPECT_GT(sw, 0.0);
    return {float(sx / sw), float(sy / sw)};
}

} // namespace

TEST_F(GlTest, CanvasHighlightMovesRightWithRollAndUpWithPitch) {
    // One motion file, one sample per frame (dt = 1 s): level, roll -/+, pitch -/+.
    const fs::path motion = scratch("sweep.csv");
    writeText(motion, "time_s,pitch,roll,yaw\n0,0,-0.3,0\n1,0,0,0\n2,0,0.3,0\n3,-0.25,0,0\n4,0.25,0,0\n");
    const Extent size{192, 108};
    const std::vector<std::string> common{"motion=" + motion.string(), "occupancy=1", "tileSize=16",
                                          "sparkleExposure=0"};
    auto glossy = canvasScene(size, common);
    auto common2 = common;
    common2.push_back("specular=0");
    auto matte = canvasScene(size, common2);
    Pipeline pipeline({.settings = displaySettings(*glossy)});
    std::vector<glm::vec2> centroid;
    for (std::uint64_t f = 0; f < 5; ++f) {
        const ImageF withHighlight = renderFrame(*glossy, pipeline, f).hdr;
        const ImageF without = renderFrame(*matte, pipeline, f).hdr;
        centroid.push_back(brighteningCentroid(withHighlight, without));
    }
    // The read-back image's rows run top to bottom: "up" is a smaller row.
    EXPECT_LT(centroid[0].x + 10, centroid[1].x) << "roll -0.3 -> 0 must move the highlight right";
    EXPECT_LT(centroid[1].x + 10, centroid[2].x) << "roll 0 -> 0.3 must move the highlight right";
    // The broad varnish lobe spreads over the whole canvas, so its centroid moves less than the mirror point
    // (8 rows of 108 measured for pitch, 17 px of 192 per 0.3 rad of roll).
    EXPECT_GT(centroid[3].y, centroid[4].y + 4) << "pitch -0.25 -> 0.25 must move the highlight up";
    EXPECT_GT(centroid[2].x, size.width / 2);
    EXPECT_LT(centroid[4].y, size.height / 2);
}

TEST_F(GlTest, CanvasGlitterExceedsOneOnlyAtItsPeakAngle) {
    // Every pixel is a glitter facet facing the lamp at pitch 0.1, roll 0.2 (no broad specular).
    const int w = 48, h = 32;
    CanvasImages images{ImageF(w, h, 0.5f), Image8(w, h, 0)};
    const glm::vec3 facet = canvasLightDirection(0.1, 0.2);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::uint8_t* m = images.material.at(x, y);
            encodeMaterialNormal(facet, m[0], m[1]);
            m[3] = 255;
        }
    }
    CanvasRenderer renderer;
    renderer.setCanvas(images, 16);
    EXPECT_EQ(renderer.occupiedTiles(), renderer.grid().count());
    for (CanvasShading shading : {CanvasShading::Tiled, CanvasShading::Fullscreen}) {
        const CanvasLighting peak{.light = facet};
        const ImageF atPeak = readTextureF(renderer.execute(peak, shading));
        const CanvasLighting away{.light = canvasLightDirection(0.1, -0.2)};
        const ImageF awayFromPeak = readTextureF(renderer.execute(away, shading));
        float minPeak = 1e9f, maxAway = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                minPeak = std::min(minPeak, atPeak.at(x, y)[1]);
                maxAway = std::max(maxAway, awayFromPeak.at(x, y)[1]);
            }
        }
        EXPECT_GT(minPeak, 1.0f + 0.9f * peak.sparkleExposure) << "sparkle missing at the peak";
        EXPECT_LT(maxAway, 1.0f) << "glitter above 1.0 away from its peak";
    }
}

TEST_F(GlTest, CanvasProceduralGlitterSparklesAboveOneAndBlooms) {
    // The procedural canvas during the scripted sweep: some glitter flakes reach far above 1.0 in HDR (what
    // bloom with threshold 1.0 picks up), while pixels without glitter stay under the sparkle's level.
    auto scene = canvasScene({256, 144}, {"occupancy=1", "tileSize=16"});
    Pipeline pipeline({.settings = displaySettings(*scene)});
    int sparkling = 0;
    for (std::uint64_t f = 0; f < 4; ++f) {
        const Rendered r = renderFrame(*scene, pipeline, f * 10, 1.0f / 30.0f);
        for (std::size_t i = 0; i < r.hdr.pixelCount(); ++i) {
            sparkling += r.hdr.rgba[i * 4 + 1] > 3.0f ? 1 : 0;
        }
    }
    EXPECT_GT(sparkling, 0);
}

TEST_F(GlTest, CanvasTiledAndFullscreenAgreeOnTheDisplayImage) {
    const Extent size{160, 96};
    auto tiled = canvasScene(size, {"occupancy=0.3", "tileSize=16", "shading=tiled"});
    auto full = canvasScene(size, {"occupancy=0.3", "tileSize=16", "shading=fullscreen"});
    Pipeline pipeline({.settings = tiled->defaultSettings()}); // dither on: same frame index, same pattern
    for (std::uint64_t f : {0u, 7u, 40u}) {
        const Rendered a = renderFrame(*tiled, pipeline, f, 1.0f / 30.0f);
        const Rendered b = renderFrame(*full, pipeline, f, 1.0f / 30.0f);
        int maxDiff = 0;
        for (std::size_t i = 0; i < a.display.rgba.size(); ++i) {
            maxDiff = std::max(maxDiff, std::abs(int(a.display.rgba[i]) - int(b.display.rgba[i])));
        }
        EXPECT_LE(maxDiff, 1) << "frame " << f;
        float maxHdr = 0;
        for (std::size_t i = 0; i < a.hdr.rgba.size(); ++i) {
            maxHdr = std::max(maxHdr, std::abs(a.hdr.rgba[i] - b.hdr.rgba[i]));
        }
        EXPECT_EQ(maxHdr, 0.0f) << "both paths run the same per-pixel code";
    }
}

TEST_F(GlTest, CanvasThirtyPercentOccupiedShadesThirtyPercentOfTiles) {
    auto scene = canvasScene({160, 96}, {"occupancy=0.3", "tileSize=16"}); // 10 x 6 tiles
    const auto columns = scene->telemetryColumns();
    const auto column = [&](std::string_view name) {
        return std::size_t(std::find(columns.begin(), columns.end(), name) - columns.begin());
    };
    ASSERT_LT(column("tiles_shaded"), columns.size());
    ASSERT_LT(column("light_z"), columns.size());
    Pipeline pipeline;
    const Rendered r = renderFrame(*scene, pipeline, 0);
    EXPECT_EQ(r.telemetry[column("tiles_total")], 60.0);
    EXPECT_EQ(r.telemetry[column("tiles_shaded")], 18.0);
    EXPECT_NEAR(r.telemetry[column("light_z")], -1.0, 1e-6); // frame 0 of the scripted tilt is level

    auto full = canvasScene({160, 96}, {"occupancy=0.3", "tileSize=16", "shading=fullscreen"});
    EXPECT_EQ(renderFrame(*full, pipeline, 0).telemetry[column("tiles_shaded")], 60.0);
}

TEST_F(GlTest, CanvasGpuTileCountMatchesTheCpuOccupancyAndShadingMatchesTheCpuReference) {
    const CanvasImages images =
        makeProceduralCanvas({.width = 96, .height = 72, .tileSize = 16, .occupancy = 0.4});
    const TileGrid grid = makeTileGrid(96, 72, 16);
    const auto occupied = tileOccupancy(images.material, grid);
    CanvasRenderer renderer;
    renderer.setCanvas(images, 16);
    EXPECT_EQ(renderer.occupiedTiles(), std::accumulate(occupied.begin(), occupied.end(), 0));
    EXPECT_EQ(renderer.occupiedTiles(), int(std::lround(0.4 * grid.count())));

    const CanvasLighting lighting{.light = canvasLightDirection(0.15, -0.2)};
    const ImageF gpu = readTextureF(renderer.execute(lighting, CanvasShading::Tiled));
    double worst = 0;
    for (int y = 0; y < 72; ++y) {
        for (int x = 0; x < 96; ++x) {
            const float* b = images.color.at(x, y);
            // Texel space is y up: image row y is texel row 71 - y.
            const glm::vec3 cpu = shadeCanvasPixel({b[0], b[1], b[2]}, images.material.at(x, y),
                                                   canvasPosition(float(x), float(71 - y), 96, 72), lighting);
            for (int c = 0; c < 3; ++c) {
                // Half-float storage (11-bit mantissa) plus float pow differences: 0.4% relative.
                worst = std::max(worst, std::abs(double(gpu.at(x, y)[c]) - cpu[c]) /
                                            std::max(1.0, double(cpu[c])) / 0.004);
            }
        }
    }
    EXPECT_LE(worst, 1.0);
}

TEST_F(GlTest, CanvasMalformedMotionCsvNamesFileAndLine) {
    const fs::path motion = scratch("bad_motion.csv");
    writeText(motion, "time_s,pitch,roll,yaw\n0,0,0,0\n0.5,0.1,oops,0\n");
    auto scene = makeScene("canvas");
    ASSERT_TRUE(scene->applyOverride("motion=" + motion.string()).empty());
    try {
        scene->resize({64, 36});
        FAIL() << "no error";
    } catch (const SceneInputError& e) {
        EXPECT_NE(std::string(e.what()).find(motion.string() + ":3:"), std::string::npos) << e.what();
    }
}

TEST_F(GlTest, CanvasMalformedMaterialImageNamesTheFile) {
    const fs::path garbage = scratch("garbage_material.png");
    writeText(garbage, "this is not a PNG");
    auto scene = makeScene("canvas");
    ASSERT_TRUE(scene->applyOverride("material=" + garbage.string()).empty());
    try {
        scene->resize({64, 36});
        FAIL() << "no error";
    } catch (const SceneInputError& e) {
        EXPECT_NE(std::string(e.what()).find(garbage.string()), std::string::npos) << e.what();
    }

    // A readable PNG that is no material map: (255, 255) is a "normal" with x^2 + y^2 = 2.
    const fs::path notMaterial = scratch("white_material.png");
    writePng(notMaterial, Image8(8, 8, 255));
    try {
        loadCanvasMaterial(notMaterial, 16, 16);
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(notMaterial.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("unit disc"), std::string::npos) << e.what();
    }
    EXPECT_THROW(loadCanvasMaterial(scratch("missing_material.png"), 16, 16), IoError);
}

TEST_F(GlTest, CanvasLoadsColorAndMaterialFiles) {
    // A grey canvas whose material is a glossy left half: only the left tiles hold material.
    const fs::path color = scratch("colour.png");
    const fs::path material = scratch("material.png");
    writePng(color, Image8(32, 16, 128));
    Image8 m(32, 16, 0);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 32; ++x) {
            std::uint8_t* p = m.at(x, y);
            p[0] = p[1] = 128;
            p[2] = x < 16 ? 100 : 0;
            p[3] = x < 16 ? 255 : 0;
        }
    }
    writePng(material, m);
    auto scene =
        canvasScene({64, 32}, {"colour=" + color.string(), "material=" + material.string(), "tileSize=16"});
    Pipeline pipeline;
    const Rendered r = renderFrame(*scene, pipeline, 0);
    EXPECT_EQ(r.telemetry[7], 8.0);
    EXPECT_EQ(r.telemetry[6], 4.0); // the left half: 2 x 2 of the 4 x 2 tiles
    EXPECT_NEAR(r.hdr.at(48, 16)[0], srgbDecode(128.0f / 255.0f) * 1.25f, 2e-3f); // diffuse only, level lamp
}

} // namespace photopic::test

namespace photopic::test {

// The trial alone: the paths in turn until each has its times, then the lower median for good; times that
// arrive late or for a path already timed do not reopen it, and restart() times both again.
TEST(CanvasPathTrial, AlternatesThenKeepsTheLowerMedian) {
    CanvasPathTrial trial;
    EXPECT_EQ(trial.take(), CanvasShading::Tiled);
    EXPECT_EQ(trial.take(), CanvasShading::Fullscreen);
    for (double ms : {5.0, 9.0, 6.0}) {
        trial.record(CanvasShading::Tiled, ms);
    }
    EXPECT_FALSE(trial.chosen());
    EXPECT_EQ(trial.take(), CanvasShading::Fullscreen) << "the path still short of times runs";
    EXPECT_EQ(trial.take(), CanvasShading::Fullscreen);
    for (double ms : {4.0, 30.0, 5.5}) {
        trial.record(CanvasShading::Fullscreen, ms);
    }
    ASSERT_TRUE(trial.chosen());
    EXPECT_EQ(*trial.chosen(), CanvasShading::Fullscreen); // median 5.5 against 6
    EXPECT_EQ(trial.medians()[0], 6.0);
    EXPECT_EQ(trial.medians()[1], 5.5);
    trial.record(CanvasShading::Tiled, 0.1);
    EXPECT_EQ(trial.take(), CanvasShading::Fullscreen);
    trial.restart();
    EXPECT_FALSE(trial.chosen());
    for (int i = 0; i < CanvasPathTrial::kSamples; ++i) {
        trial.record(CanvasShading::Tiled, 1.0);
        trial.record(CanvasShading::Fullscreen, 2.0);
    }
    EXPECT_EQ(trial.chosen(), CanvasShading::Tiled);
}

// `auto` on this device: the same HDR bits as the full-screen reference on every frame, the trial decided
// within 16 frames, and telemetry that does not depend on which path it kept (the tiles with material).
TEST_F(GlTest, CanvasAutoShadingChoosesAPathAndChangesNoPixel) {
    const Extent size{160, 96};
    auto automatic = canvasScene(size, {"occupancy=0.3", "tileSize=16", "shading=auto"});
    auto full = canvasScene(size, {"occupancy=0.3", "tileSize=16", "shading=fullscreen"});
    const auto columns = automatic->telemetryColumns();
    const std::size_t shaded =
        std::size_t(std::find(columns.begin(), columns.end(), "tiles_shaded") - columns.begin());
    Pipeline pipeline({.settings = automatic->defaultSettings()});
    for (std::uint64_t f = 0; f < 16; ++f) {
        const Rendered a = renderFrame(*automatic, pipeline, f, 1.0f / 30.0f);
        const Rendered b = renderFrame(*full, pipeline, f, 1.0f / 30.0f);
        float maxHdr = 0;
        for (std::size_t i = 0; i < a.hdr.rgba.size(); ++i) {
            maxHdr = std::max(maxHdr, std::abs(a.hdr.rgba[i] - b.hdr.rgba[i]));
        }
        ASSERT_EQ(maxHdr, 0.0f) << "frame " << f;
        ASSERT_EQ(a.telemetry[shaded], 18.0) << "frame " << f;
    }
    const CanvasImages images =
        makeProceduralCanvas({.width = 160, .height = 96, .tileSize = 16, .occupancy = 0.3});
    CanvasRenderer renderer;
    renderer.setCanvas(images, 16);
    const CanvasLighting lighting{.light = canvasLightDirection(0.1, 0.2)};
    for (int f = 0; f < 16 && !renderer.autoChoice(); ++f) {
        (void)readTextureF(renderer.execute(lighting, CanvasShading::Auto)); // the read waits for the frame
    }
    ASSERT_TRUE(renderer.autoChoice()) << "the trial ends once each path has its times";
    EXPECT_NE(*renderer.autoChoice(), CanvasShading::Auto);
    renderer.setCanvas(images, 16);
    EXPECT_FALSE(renderer.autoChoice()) << "a new canvas is timed again";
}

} // namespace photopic::test
