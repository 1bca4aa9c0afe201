// The canvas scene's GL-free maths: the tilt's light vector, the motion CSV, tile occupancy, material codes.

#include "scenes/canvas/CanvasMaterial.h"
#include "core/Motion.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>

namespace photopic {

namespace {

/// The line a malformed CSV is rejected at, or -1 when it parses.
int errorLine(std::string_view text, std::string* message = nullptr) {
    try {
        parseMotionCsv(text, "motion.csv");
    } catch (const MotionError& e) {
        if (message) {
            *message = e.what();
        }
        return e.line();
    }
    return -1;
}

} // namespace

TEST(CanvasLight, LevelDeviceLightsStraightAlongTheSeedsMinusZ) {
    const glm::vec3 l = seedLightVector(0, 0);
    EXPECT_FLOAT_EQ(l.x, 0);
    EXPECT_FLOAT_EQ(l.y, 0);
    EXPECT_FLOAT_EQ(l.z, -1);
    const glm::vec3 c = canvasLightDirection(0, 0);
    EXPECT_FLOAT_EQ(c.z, 1); // towards the viewer in the canvas frame
}

TEST(CanvasLight, SignsFollowRollAndPitch) {
    const glm::vec3 roll = seedLightVector(0, 0.3);
    EXPECT_NEAR(roll.x, std::sin(0.3), 1e-6);
    EXPECT_FLOAT_EQ(roll.y, 0);
    EXPECT_LT(roll.z, 0);
    const glm::vec3 pitch = seedLightVector(0.2, 0);
    EXPECT_FLOAT_EQ(pitch.x, 0);
    EXPECT_NEAR(pitch.y, std::sin(0.2), 1e-6);
    EXPECT_LT(seedLightVector(-0.2, -0.3).x, 0);
    EXPECT_LT(seedLightVector(-0.2, -0.3).y, 0);
    // The canvas frame keeps x and y (so the highlight moves right / up) and points z at the viewer.
    const glm::vec3 c = canvasLightDirection(0.2, 0.3);
    EXPECT_GT(c.x, 0);
    EXPECT_GT(c.y, 0);
    EXPECT_GT(c.z, 0);
}

TEST(CanvasLight, IsNormalisedEvenWhereTheSeedsFormulaIsNot) {
    // (sin r, sin p, -cos p cos r) has length > 1 when both angles are non-zero; the rule normalises it.
    const glm::vec3 l = seedLightVector(0.5, 0.6);
    EXPECT_NEAR(glm::length(l), 1.0f, 1e-6f);
    const double raw = std::sqrt(std::pow(std::sin(0.6), 2) + std::pow(std::sin(0.5), 2) +
                                 std::pow(std::cos(0.5) * std::cos(0.6), 2));
    EXPECT_NEAR(l.x, std::sin(0.6) / raw, 1e-6);
}

TEST(MotionCsv, ParsesAndInterpolatesLinearlyAndClamps) {
    const MotionTrack track =
        parseMotionCsv("time_s,pitch,roll,yaw\n0,0,0,0\n1,0.2,-0.4,1\r\n\n3,0.2,0.4,1\n", "m.csv");
    ASSERT_EQ(track.samples().size(), 3u);
    EXPECT_NEAR(track.at(0.5).pitch, 0.1, 1e-12);
    EXPECT_NEAR(track.at(0.5).roll, -0.2, 1e-12);
    EXPECT_NEAR(track.at(2.0).roll, 0.0, 1e-12);
    EXPECT_NEAR(track.at(-5).roll, 0.0, 1e-12);
    EXPECT_NEAR(track.at(10).roll, 0.4, 1e-12);
    EXPECT_NEAR(track.at(10).yaw, 1.0, 1e-12);
}

TEST(MotionCsv, MalformedFilesNameTheLine) {
    std::string message;
    EXPECT_EQ(errorLine("time,pitch,roll,yaw\n0,0,0,0\n", &message), 1);
    EXPECT_NE(message.find("motion.csv:1:"), std::string::npos) << message;
    EXPECT_NE(message.find("time_s,pitch,roll,yaw"), std::string::npos) << message;
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,0,0,0\n0.5,0,abc,0\n", &message), 3);
    EXPECT_NE(message.find("roll"), std::string::npos) << message;
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,0,0\n"), 2);              // too few columns
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,0,0,0,0\n"), 2);          // too many
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n1,0,0,0\n\n1,0,0,0\n"), 4); // time does not increase
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,nan,0,0\n"), 2);
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,1e999,0,0\n"), 2);
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,,0,0\n"), 2);
    EXPECT_EQ(errorLine("", &message), 0); // empty: no line to name, the file is named
    EXPECT_NE(message.find("motion.csv"), std::string::npos);
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n"), 0);
    EXPECT_EQ(errorLine("time_s,pitch,roll,yaw\n0,0.1,-0.2,+3\n"), -1);
}

TEST(MotionCsv, MissingFileIsNamed) {
    try {
        loadMotionCsv("/nonexistent/motion.csv");
        FAIL() << "no error";
    } catch (const MotionError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/motion.csv"), std::string::npos);
    }
}

TEST(ScriptedTilt, StartsLevelAndSweepsBothAxes) {
    const ScriptedTilt tilt;
    EXPECT_DOUBLE_EQ(tilt.at(0).roll, 0);
    EXPECT_DOUBLE_EQ(tilt.at(0).pitch, 0);
    EXPECT_NEAR(tilt.at(tilt.period / 4).roll, tilt.rollAmplitude, 1e-12);
    EXPECT_NEAR(tilt.at(tilt.period * 1.5 / 4).pitch, tilt.pitchAmplitude, 1e-12);
}

TEST(CanvasTiles, GridCoversTheImageAndChoosesExactFractions) {
    const TileGrid grid = makeTileGrid(1920, 1080, 256);
    EXPECT_EQ(grid.tilesX, 8);
    EXPECT_EQ(grid.tilesY, 5);
    const auto chosen = chooseTiles(grid, 0.3, 3);
    EXPECT_EQ(std::accumulate(chosen.begin(), chosen.end(), 0), 12); // 30% of 40
    EXPECT_EQ(chosen, chooseTiles(grid, 0.3, 3));                    // deterministic
    EXPECT_NE(chosen, chooseTiles(grid, 0.3, 4));
    const auto all = chooseTiles(grid, 1.0, 3);
    EXPECT_EQ(std::accumulate(all.begin(), all.end(), 0), 40);
}

TEST(CanvasTiles, TilesCountFromTheBottomLeftLikeGlTexels) {
    const TileGrid grid = makeTileGrid(40, 40, 16); // 3 x 3, partial last column and top row
    EXPECT_EQ(grid.tileOfImagePixel(0, 39, 40), 0); // bottom-left image pixel
    EXPECT_EQ(grid.tileOfImagePixel(39, 0, 40), 8); // top-right
    EXPECT_EQ(grid.tileOfImagePixel(0, 7, 40), 6);  // texel row 32: the top (partial) row of tiles
    EXPECT_EQ(grid.tileOfImagePixel(0, 8, 40), 3);  // texel row 31
    Image8 material(40, 40, 0);
    material.at(20, 39)[2] = 1;  // shininess code 1
    material.at(39, 0)[3] = 200; // glitter
    material.at(0, 0)[3] = 127;  // below the glitter threshold: no material
    const auto occupied = tileOccupancy(material, grid);
    EXPECT_EQ(occupied, (std::vector<std::uint8_t>{0, 1, 0, 0, 0, 0, 0, 0, 1}));
}

TEST(CanvasMaterial, CodesRoundTripAndSparkleConstants) {
    std::uint8_t r = 0, g = 0;
    encodeMaterialNormal({0, 0, 1}, r, g);
    EXPECT_EQ(r, 128);
    EXPECT_EQ(g, 128);
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));
    encodeMaterialNormal(tilted, r, g);
    EXPECT_GT(glm::dot(decodeMaterialNormal(r, g), tilted), std::cos(0.5 * 3.14159 / 180));
    EXPECT_EQ(decodeShininess(0), 0.0f);
    EXPECT_NEAR(decodeShininess(255), 2048.0f, 1e-2f);
    // 0.9^(1/128): the sparkle lives within ~2.3 degrees of a facet's normal.
    EXPECT_NEAR(sparkleCosine(), 0.999177, 1e-6);
    EXPECT_NEAR(std::acos(sparkleCosine()) * 180 / 3.14159265, 2.325, 0.01);
}

TEST(CanvasMaterial, ReferenceShadingSparklesOnlyAtThePeak) {
    std::uint8_t m[4] = {0, 0, 0, 255};
    const glm::vec3 facet = canvasLightDirection(0.1, 0.2);
    encodeMaterialNormal(facet, m[0], m[1]);
    CanvasLighting lit{.light = facet};
    const glm::vec3 base(0.5f);
    const glm::vec3 peak = shadeCanvasPixel(base, m, {0, 0, 0}, lit);
    EXPECT_GT(peak.r, 1.0f + lit.sparkleExposure * 0.9f);
    lit.light = canvasLightDirection(0.1, 0.3); // 0.1 rad away: far outside the 2.3 degree lobe
    const glm::vec3 off = shadeCanvasPixel(base, m, {0, 0, 0}, lit);
    EXPECT_LT(off.r, 1.0f);
    EXPECT_NEAR(off.r, 0.5f * (lit.ambient + glm::dot(decodeMaterialNormal(m[0], m[1]), lit.light)), 1e-5f);
}

} // namespace photopic
