// Which channels feed what (io/ExrChannels.h): the presets, layers, --aov overrides and their errors, and
// the reader applying a mapping's conventions to a Blender-style multilayer file.

#include "TestData.h"

#include "io/ExrChannels.h"
#include "io/ExrFrame.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace photopic {
namespace {

namespace fs = std::filesystem;
using Names = std::vector<std::string>;

Names blenderChannels(const std::string& layer) {
    Names names;
    for (const char* pass : {"Combined.R", "Combined.G", "Combined.B", "Combined.A", "Depth.Z", "Normal.X",
                             "Normal.Y", "Normal.Z", "Vector.X", "Vector.Y", "Vector.Z", "Vector.W", "AO.R",
                             "AO.G", "AO.B", "IndexOB.X", "Noisy Image.R"})
        names.push_back(layer + "." + pass);
    return names;
}

std::string errorOf(const Names& channels, bool blender, const AovRequest& request) {
    try {
        (void)resolveAovs(channels, blender, request);
    } catch (const AovError& e) {
        return e.what();
    }
    return "";
}

TEST(ExrChannels, PhotopicNamesByDefault) {
    const AovChannels a =
        resolveAovs({"A", "B", "G", "N.X", "N.Y", "N.Z", "R", "Z", "motion.X", "motion.Y"}, false, {});
    EXPECT_EQ(a.preset, AovPreset::Photopic);
    EXPECT_EQ(a.layer, "");
    EXPECT_EQ(a.of(Aov::Color), (Names{"R", "G", "B", "A"}));
    EXPECT_EQ(a.of(Aov::Depth), (Names{"Z"}));
    EXPECT_EQ(a.of(Aov::Normals), (Names{"N.X", "N.Y", "N.Z"}));
    EXPECT_EQ(a.of(Aov::Motion), (Names{"motion.X", "motion.Y"}));
    EXPECT_FALSE(a.has(Aov::Ao));
    EXPECT_EQ(a.conventions.motionSense, AovConventions::MotionSense::CurrentMinusPrevious);
    EXPECT_FALSE(a.conventions.motionYUp);
    EXPECT_EQ(a.feeds("N.Y"), Aov::Normals);
    EXPECT_FALSE(a.feeds("other").has_value());
    // Lower-case components are normals and motion too.
    const AovChannels lower =
        resolveAovs({"R", "G", "B", "N.x", "N.y", "N.z", "motion.x", "motion.y"}, false, {});
    EXPECT_EQ(lower.of(Aov::Normals), (Names{"N.x", "N.y", "N.z"}));
    EXPECT_EQ(lower.of(Aov::Motion), (Names{"motion.x", "motion.y"}));
}

TEST(ExrChannels, BlenderPresetFromTheAttribute) {
    const AovChannels a = resolveAovs(blenderChannels("ViewLayer"), true, {});
    EXPECT_EQ(a.preset, AovPreset::Blender);
    EXPECT_EQ(a.layer, "ViewLayer");
    EXPECT_EQ(a.of(Aov::Color), (Names{"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
                                       "ViewLayer.Combined.A"}));
    EXPECT_EQ(a.of(Aov::Depth), (Names{"ViewLayer.Depth.Z"}));
    EXPECT_EQ(a.of(Aov::Motion), (Names{"ViewLayer.Vector.X", "ViewLayer.Vector.Y"}));
    EXPECT_EQ(a.of(Aov::Ao), (Names{"ViewLayer.AO.R"}));
    EXPECT_EQ(a.of(Aov::ObjectId), (Names{"ViewLayer.IndexOB.X"}));
    EXPECT_EQ(a.conventions.normals, AovConventions::Normals::WorldZUp);
    EXPECT_EQ(a.conventions.motionSense, AovConventions::MotionSense::PreviousMinusCurrent);
    EXPECT_TRUE(a.conventions.motionYUp);
    // Read under the photopic preset, Blender's names are several layers; the error says what to do.
    AovRequest photopic;
    photopic.preset = AovPreset::Photopic;
    const std::string error = errorOf(blenderChannels("ViewLayer"), true, photopic);
    EXPECT_NE(error.find("2 layers (ViewLayer.Combined, ViewLayer.AO)"), std::string::npos) << error;
    EXPECT_NE(error.find("try --aovs blender"), std::string::npos) << error;
    const std::string noColour = errorOf({"ViewLayer.Combined.X", "ViewLayer.Depth.Z"}, false, {});
    EXPECT_NE(noColour.find("no colour channels under the photopic preset"), std::string::npos) << noColour;
    EXPECT_NE(noColour.find("try --aovs blender"), std::string::npos) << noColour;
    AovRequest asked;
    asked.preset = AovPreset::Blender;
    EXPECT_EQ(resolveAovs(blenderChannels("ViewLayer"), false, asked).layer, "ViewLayer");
}

TEST(ExrChannels, BlenderCombinedOnlyFilesLackTheAttribute) {
    // Blender writes BlenderMultiChannel only beside other passes.
    const AovChannels a = resolveAovs(
        {"ViewLayer.Combined.A", "ViewLayer.Combined.B", "ViewLayer.Combined.G", "ViewLayer.Combined.R"},
        false, {});
    EXPECT_EQ(a.preset, AovPreset::Blender);
    EXPECT_EQ(a.of(Aov::Color).front(), "ViewLayer.Combined.R");
}

TEST(ExrChannels, SeveralLayersNeedOneChosen) {
    Names channels = blenderChannels("Fg");
    for (const std::string& name : blenderChannels("Bg"))
        channels.push_back(name);
    EXPECT_EQ(aovLayers(channels, AovPreset::Blender), (Names{"Fg", "Bg"}));
    const std::string error = errorOf(channels, true, {});
    EXPECT_NE(error.find("2 layers (Fg, Bg): choose one with --layer NAME"), std::string::npos) << error;
    AovRequest bg;
    bg.layer = "Bg";
    EXPECT_EQ(resolveAovs(channels, true, bg).of(Aov::Depth), (Names{"Bg.Depth.Z"}));
    bg.layer = "Mid";
    const std::string missing = errorOf(channels, true, bg);
    EXPECT_NE(missing.find("--layer Mid: the file has no such blender layer (layers: Fg, Bg"),
              std::string::npos)
        << missing;
    // Standard OpenEXR layers: the unprefixed colour is the default, a prefix is chosen by name.
    const Names layered{"R", "G", "B", "diffuse.R", "diffuse.G", "diffuse.B"};
    EXPECT_EQ(aovLayers(layered, AovPreset::Photopic), (Names{"", "diffuse"}));
    EXPECT_EQ(resolveAovs(layered, false, {}).of(Aov::Color), (Names{"R", "G", "B"}));
    AovRequest diffuse;
    diffuse.layer = "diffuse";
    EXPECT_EQ(resolveAovs(layered, false, diffuse).of(Aov::Color),
              (Names{"diffuse.R", "diffuse.G", "diffuse.B"}));
}

TEST(ExrChannels, OverridesByNameByPrefixAndConventions) {
    const Names channels{"beauty.R", "beauty.G", "beauty.B", "P.dist", "n.x", "n.y", "n.z", "mv.u", "mv.v"};
    AovRequest r;
    for (const char* text : {"color=beauty", "depth=P.dist:radial", "normals=n:camera", "motion=mv:ndc,y-up"})
        r.overrides.push_back(parseAovOverride(text));
    const AovChannels a = resolveAovs(channels, false, r);
    EXPECT_EQ(a.of(Aov::Color), (Names{"beauty.R", "beauty.G", "beauty.B"}));
    EXPECT_EQ(a.of(Aov::Depth), (Names{"P.dist"}));
    EXPECT_EQ(a.of(Aov::Normals), (Names{"n.x", "n.y", "n.z"}));
    EXPECT_EQ(a.of(Aov::Motion), (Names{"mv.u", "mv.v"}));
    EXPECT_EQ(a.conventions.depth, AovConventions::Depth::Radial);
    EXPECT_EQ(a.conventions.normals, AovConventions::Normals::Camera);
    EXPECT_EQ(a.conventions.motionUnits, AovConventions::MotionUnits::Ndc);
    EXPECT_TRUE(a.conventions.motionYUp);
    EXPECT_EQ(a.origin[std::size_t(Aov::Depth)], "--aov");

    // Conventions alone keep the preset's channels; none drops a kind; pair=2 takes the other pair.
    AovRequest b;
    for (const char* text : {"motion=:pair=2,jittered", "depth=none"})
        b.overrides.push_back(parseAovOverride(text));
    const AovChannels blender = resolveAovs(blenderChannels("L"), true, b);
    EXPECT_EQ(blender.of(Aov::Motion), (Names{"L.Vector.Z", "L.Vector.W"}));
    EXPECT_EQ(blender.conventions.motionSense, AovConventions::MotionSense::CurrentMinusNext);
    EXPECT_TRUE(blender.conventions.motionJittered);
    EXPECT_FALSE(blender.has(Aov::Depth));
    // A name within the chosen layer.
    AovRequest c;
    c.overrides.push_back(parseAovOverride("depth=Depth.Z"));
    EXPECT_EQ(resolveAovs(blenderChannels("L"), true, c).of(Aov::Depth), (Names{"L.Depth.Z"}));
}

TEST(ExrChannels, BadOverridesNameWhatIsWrong) {
    const auto parseError = [](const char* text) {
        try {
            (void)parseAovOverride(text);
        } catch (const AovError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(parseError("depth").find("expected KIND=CHANNELS[:CONVENTIONS]"), std::string::npos);
    EXPECT_NE(parseError("albedo=A").find("unknown kind \"albedo\""), std::string::npos);
    EXPECT_NE(parseError("depth=Z:sideways")
                  .find("\"sideways\" is no convention of depth (conventions: "
                        "planar, radial)"),
              std::string::npos);
    EXPECT_NE(parseError("color=R:planar").find("it takes none"), std::string::npos);
    EXPECT_NE(parseError("normals=a,b").find("2 channels given, expected 3 (x, y, z)"), std::string::npos);
    EXPECT_NE(parseError("depth=").find("no channels and no conventions"), std::string::npos);
    EXPECT_NE(parseError("depth=Z,,Y").find("an empty channel name"), std::string::npos);
    try {
        (void)parseAovPreset("arnold");
        ADD_FAILURE();
    } catch (const AovError& e) {
        EXPECT_NE(std::string(e.what()).find("presets: photopic, blender"), std::string::npos);
    }
    AovRequest r;
    r.overrides.push_back(parseAovOverride("depth=P.Z"));
    const std::string missing = errorOf({"R", "G", "B"}, false, r);
    EXPECT_NE(missing.find("the file has no channel P.Z"), std::string::npos) << missing;
    EXPECT_NE(missing.find("(channels: R, G, B)"), std::string::npos) << missing;
    // A layer with some of its components is an error naming the missing ones.
    const std::string partial = errorOf({"R", "G", "B", "N.X", "N.Y"}, false, {});
    EXPECT_NE(partial.find("has N.X, N.Y but not N.Z"), std::string::npos) << partial;
}

using ChannelValues = std::vector<std::pair<std::string, float>>;

/// FLOAT slices of `w` x `h` pixels, each channel's every pixel its value, over `planes` (filled here).
Imf::FrameBuffer constantSlices(const ChannelValues& channels, int w, int h,
                                std::vector<std::vector<float>>& planes) {
    planes.clear();
    for (const auto& [name, value] : channels)
        planes.emplace_back(std::size_t(w) * std::size_t(h), value);
    Imf::FrameBuffer frameBuffer;
    for (std::size_t c = 0; c < channels.size(); ++c)
        frameBuffer.insert(channels[c].first,
                           Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[c].data()), sizeof(float),
                                      sizeof(float) * std::size_t(w)));
    return frameBuffer;
}

/// A Blender-style multilayer file: one part, <layer>.<pass>.<channel> names, the BlenderMultiChannel
/// attribute; every pixel the same values.
void writeBlenderStyle(const fs::path& path, int width, int height) {
    Imf::Header header(width, height);
    header.insert("BlenderMultiChannel", Imf::StringAttribute("Blender V2.55.1 and newer"));
    const ChannelValues values{
        {"ViewLayer.Combined.R", 0.25f}, {"ViewLayer.Combined.G", 0.5f}, {"ViewLayer.Combined.B", 0.75f},
        {"ViewLayer.Combined.A", 1.0f},  {"ViewLayer.Depth.Z", 7.5f},    {"ViewLayer.Normal.X", 0.0f},
        {"ViewLayer.Normal.Y", 0.0f},    {"ViewLayer.Normal.Z", 1.0f},   {"ViewLayer.Vector.X", 3.0f},
        {"ViewLayer.Vector.Y", -2.0f},   {"ViewLayer.Vector.Z", -9.0f},  {"ViewLayer.Vector.W", 9.0f},
        {"ViewLayer.IndexOB.X", 4.0f}};
    for (const auto& [name, value] : values)
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    std::vector<std::vector<float>> planes;
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(constantSlices(values, width, height, planes));
    file.writePixels(height);
}

TEST(ExrChannels, TheReaderAppliesTheBlenderConventions) {
    const fs::path path =
        fs::temp_directory_path() / ("photopic-blender-style-" + std::to_string(::getpid()) + ".exr");
    writeBlenderStyle(path, 4, 3);
    const ExrFrame frame = readExrFrame(path);
    fs::remove(path);
    EXPECT_EQ(frame.aovs.preset, AovPreset::Blender);
    ASSERT_EQ(frame.width(), 4);
    EXPECT_FLOAT_EQ(frame.color.rgba[0], 0.25f);
    EXPECT_FLOAT_EQ(frame.color.rgba[2], 0.75f);
    ASSERT_EQ(frame.depth.size(), 12u);
    EXPECT_FLOAT_EQ(frame.depth[5], 7.5f);
    // Blender's Z-up world normal (0, 0, 1) is Y-up (0, 1, 0).
    ASSERT_EQ(frame.normals.size(), 36u);
    EXPECT_FLOAT_EQ(frame.normals[0], 0.0f);
    EXPECT_FLOAT_EQ(frame.normals[1], 1.0f);
    EXPECT_FLOAT_EQ(frame.normals[2], 0.0f);
    // The first pair, previous minus current with y up: current minus previous with y down is (-3, -2).
    ASSERT_EQ(frame.motion.size(), 24u);
    EXPECT_FLOAT_EQ(frame.motion[0], -3.0f);
    EXPECT_FLOAT_EQ(frame.motion[1], -2.0f);
    ASSERT_EQ(frame.objectId.size(), 12u);
    EXPECT_FLOAT_EQ(frame.objectId[0], 4.0f);
}

/// A multi-part file as a compositor writes one: colour in part "rgba", depth, normals and motion each in a
/// part named after its layer with bare channel names.
void writeMultipart(const fs::path& path, int width, int height, bool mismatchedWindow = false) {
    struct Part {
        const char* name;
        ChannelValues channels;
    };
    const std::vector<Part> parts{{"rgba", {{"R", 0.5f}, {"G", 0.25f}, {"B", 0.125f}, {"A", 1.0f}}},
                                  {"depth", {{"Z", 3.0f}}},
                                  {"N", {{"X", 0.0f}, {"Y", 0.0f}, {"Z", 1.0f}}},
                                  {"motion", {{"X", 2.0f}, {"Y", -1.0f}}}};
    std::vector<Imf::Header> headers;
    for (const Part& part : parts) {
        Imf::Header header(width, height);
        if (mismatchedWindow && std::string(part.name) == "depth")
            header.dataWindow() = Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(width / 2, height - 1));
        header.setName(part.name);
        header.setType(Imf::SCANLINEIMAGE);
        for (const auto& [name, value] : part.channels)
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        headers.push_back(header);
    }
    Imf::MultiPartOutputFile file(path.c_str(), headers.data(), int(headers.size()));
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Imath::Box2i window = headers[k].dataWindow();
        const int w = window.max.x - window.min.x + 1;
        const int h = window.max.y - window.min.y + 1;
        std::vector<std::vector<float>> planes;
        Imf::OutputPart part(file, int(k));
        part.setFrameBuffer(constantSlices(parts[k].channels, w, h, planes));
        part.writePixels(h);
    }
}

TEST(ExrChannels, MultiPartFilesAreReadPartByPart) {
    const fs::path path =
        fs::temp_directory_path() / ("photopic-multipart-" + std::to_string(::getpid()) + ".exr");
    writeMultipart(path, 5, 3);
    const ExrFrame frame = readExrFrame(path);
    EXPECT_EQ(frame.parts, (Names{"rgba", "depth", "N", "motion"}));
    EXPECT_EQ(frame.channels,
              (Names{"A", "B", "G", "R", "depth.Z", "N.X", "N.Y", "N.Z", "motion.X", "motion.Y"}));
    ASSERT_EQ(frame.width(), 5);
    EXPECT_FLOAT_EQ(frame.color.rgba[4 * 7 + 0], 0.5f);
    EXPECT_FLOAT_EQ(frame.color.rgba[4 * 7 + 2], 0.125f);
    ASSERT_EQ(frame.depth.size(), 15u);
    EXPECT_FLOAT_EQ(frame.depth[14], 3.0f);
    ASSERT_EQ(frame.normals.size(), 45u);
    EXPECT_FLOAT_EQ(frame.normals[3 * 4 + 2], 1.0f);
    ASSERT_EQ(frame.motion.size(), 30u);
    EXPECT_FLOAT_EQ(frame.motion[0], 2.0f);
    EXPECT_FLOAT_EQ(frame.motion[1], -1.0f);
    // A part whose data window differs from the colour's is named in the error.
    writeMultipart(path, 5, 3, true);
    try {
        (void)readExrFrame(path);
        ADD_FAILURE() << "a part of another data window was read";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("channel depth.Z is in part depth, whose data window differs"),
                  std::string::npos)
            << e.what();
    }
    fs::remove(path);
}

// Blender's own file (tests/data/blender, Cycles 3.4.1): read by itself under the blender preset, Z-up
// normals turned Y up, the first Vector pair turned into current minus previous, y down.
TEST(ExrChannels, BlendersOwnFileReadsInPhotopicsConventions) {
    const ExrFrame frame = readExrFrame(test::testInputDir() / "blender" / "passes" / "frame_0003.exr");
    EXPECT_EQ(frame.aovs.preset, AovPreset::Blender);
    EXPECT_EQ(frame.aovs.layer, "ViewLayer");
    ASSERT_EQ(frame.width(), 320);
    ASSERT_EQ(frame.height(), 180);
    const auto at = [&](int x, int y) { return std::size_t(y) * 320u + std::size_t(x); };
    // The sky at the top, the ground at the bottom, the back wall above the objects.
    EXPECT_EQ(frame.depth[at(160, 2)], 1e10f);
    const std::size_t ground = at(240, 168);
    EXPECT_NEAR(frame.normals[3 * ground + 0], 0.0f, 1e-4f);
    EXPECT_NEAR(frame.normals[3 * ground + 1], 1.0f, 1e-4f); // Blender's +z
    EXPECT_NEAR(frame.normals[3 * ground + 2], 0.0f, 1e-4f);
    const std::size_t wall = at(210, 40);
    EXPECT_NEAR(frame.normals[3 * wall + 2], 1.0f, 1e-3f); // Blender's -y: towards the camera
    // The camera trucks right: the static wall moves left, not up or down.
    EXPECT_LT(frame.motion[2 * wall], -1.0f);
    EXPECT_NEAR(frame.motion[2 * wall + 1], 0.0f, 1e-3f);
    // Combined's alpha is read (1: an opaque film).
    EXPECT_EQ(frame.color.rgba[4 * wall + 3], 1.0f);
}

} // namespace
} // namespace photopic
