#include "io/ExrFrame.h"

#include "io/ImageIO.h"

#include "common/TempFolder.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <glm/gtc/matrix_transform.hpp>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace photopic {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 8;
constexpr int kHeight = 6;

Camera testCamera() {
    Camera camera;
    camera.view = glm::lookAt(glm::vec3(3.0f, 2.0f, 5.0f), glm::vec3(0.5f, 0.0f, -1.0f), glm::vec3(0, 1, 0));
    camera.verticalFov = 0.8f;
    camera.nearPlane = 0.25f;
    camera.farPlane = 400.0f;
    camera.projection = perspectiveProjection(camera.verticalFov, float(kWidth) / float(kHeight),
                                              camera.nearPlane, camera.farPlane);
    camera.prevViewProjection = camera.viewProjection();
    camera.lens = {.focalLengthMm = 35.0f,
                   .sensorHeightMm = 2.0f * 35.0f * std::tan(0.4f), // consistent with the field of view
                   .fNumber = 4.0f,
                   .focusDistance = 6.5f,
                   .shutterAngleDeg = 172.8f,
                   .exposureTimeS = 0.02f,
                   .iso = 400.0f};
    return camera;
}

ExrFrame testFrame() {
    ExrFrame frame;
    frame.color = ImageF(kWidth, kHeight);
    const std::size_t pixels = std::size_t(kWidth) * kHeight;
    frame.depth.resize(pixels);
    frame.normals.resize(pixels * 3);
    frame.motion.resize(pixels * 2);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 4; ++c)
            frame.color.rgba[i * 4 + c] = 0.25f * float(c) + float(i);
        frame.depth[i] = 1.0f + 0.37f * float(i);
        const glm::vec3 n = glm::normalize(glm::vec3(float(i % 3) - 1.0f, 1.0f, float(i % 5) * 0.25f));
        frame.normals[i * 3 + 0] = n.x;
        frame.normals[i * 3 + 1] = n.y;
        frame.normals[i * 3 + 2] = n.z;
        frame.motion[i * 2 + 0] = 0.125f * float(i);
        frame.motion[i * 2 + 1] = -0.5f * float(i);
    }
    frame.depth[pixels - 1] = std::numeric_limits<float>::infinity(); // the background
    frame.camera = exrFromCamera(testCamera(), kWidth, kHeight);
    frame.camera.jitter = glm::vec2(0.25f, -0.125f);
    frame.camera.sunDirection = glm::vec3(0.25f, 0.75f, -0.5f);
    return frame;
}

void expectMatNear(const glm::mat4& a, const glm::mat4& b, float tolerance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "[" << c << "][" << r << "]";
}

TEST(ExrFrame, RoundTripsEveryLayerAndAttribute) {
    const test::TempFolder folder;
    const ExrFrame written = testFrame();
    writeExrFrame(folder / "frame.exr", written);
    const ExrFrame read = readExrFrame(folder / "frame.exr");

    ASSERT_EQ(read.color.width, kWidth);
    ASSERT_EQ(read.color.height, kHeight);
    for (std::size_t i = 0; i < written.color.rgba.size(); ++i)
        EXPECT_NEAR(read.color.rgba[i], written.color.rgba[i], 1e-3f * std::abs(written.color.rgba[i]));
    EXPECT_EQ(read.depth, written.depth); // float: exact
    EXPECT_EQ(read.motion, written.motion);
    ASSERT_EQ(read.normals.size(), written.normals.size());
    for (std::size_t i = 0; i < written.normals.size(); ++i)
        EXPECT_NEAR(read.normals[i], written.normals[i], 1e-3f); // half
    EXPECT_EQ(read.channels, (std::vector<std::string>{"A", "B", "G", "N.X", "N.Y", "N.Z", "R", "Z",
                                                       "motion.X", "motion.Y"}));
    EXPECT_EQ(read.displaySize, glm::ivec2(kWidth, kHeight));
    EXPECT_EQ(read.dataOrigin, glm::ivec2(0, 0));

    const ExrCameraAttributes& a = read.camera;
    const ExrCameraAttributes& w = written.camera;
    ASSERT_TRUE(a.worldToCamera && a.worldToNDC);
    EXPECT_EQ(*a.worldToCamera, *w.worldToCamera);
    EXPECT_EQ(*a.worldToNDC, *w.worldToNDC);
    EXPECT_EQ(a.focus, w.focus);
    EXPECT_EQ(a.aperture, w.aperture);
    EXPECT_EQ(a.expTime, w.expTime);
    EXPECT_EQ(a.isoSpeed, w.isoSpeed);
    EXPECT_EQ(a.pinholeFocalLength, w.pinholeFocalLength);
    EXPECT_EQ(a.sensorOverallDimensions, w.sensorOverallDimensions);
    EXPECT_EQ(a.shutterAngle, w.shutterAngle);
    EXPECT_EQ(a.jitter, w.jitter);
    EXPECT_EQ(a.nearClip, w.nearClip);
    EXPECT_EQ(a.farClip, w.farClip);
    EXPECT_EQ(a.sunDirection, w.sunDirection);
}

TEST(ExrFrame, ColorOnlyFileHasNoLayersOrCamera) {
    const test::TempFolder folder;
    ImageF image(4, 3, 0.5f);
    writeExr(folder / "plain.exr", image);
    const ExrFrame frame = readExrFrame(folder / "plain.exr");
    EXPECT_EQ(frame.color.width, 4);
    EXPECT_TRUE(frame.depth.empty());
    EXPECT_TRUE(frame.normals.empty());
    EXPECT_TRUE(frame.motion.empty());
    EXPECT_FALSE(frame.camera.worldToCamera);
    EXPECT_FALSE(cameraFromExr(frame.camera, 4, 3).has_value());
}

TEST(ExrFrame, CameraRoundTrip) {
    const Camera camera = testCamera();
    const std::optional<Camera> back = cameraFromExr(exrFromCamera(camera, kWidth, kHeight), kWidth, kHeight);
    ASSERT_TRUE(back.has_value());
    expectMatNear(back->view, camera.view, 1e-5f);
    expectMatNear(back->projection, camera.projection, 1e-4f);
    expectMatNear(back->prevViewProjection, camera.viewProjection(), 1e-4f);
    EXPECT_NEAR(back->nearPlane, camera.nearPlane, 1e-6f);
    EXPECT_NEAR(back->farPlane, camera.farPlane, 1e-3f);
    EXPECT_NEAR(back->verticalFov, camera.verticalFov, 1e-5f);
    EXPECT_NEAR(back->lens.focalLengthMm, camera.lens.focalLengthMm, 1e-4f);
    EXPECT_NEAR(back->lens.sensorHeightMm, camera.lens.sensorHeightMm, 1e-4f);
    EXPECT_EQ(back->lens.fNumber, camera.lens.fNumber);
    EXPECT_EQ(back->lens.focusDistance, camera.lens.focusDistance);
    EXPECT_EQ(back->lens.shutterAngleDeg, camera.lens.shutterAngleDeg);
    EXPECT_EQ(back->lens.exposureTimeS, camera.lens.exposureTimeS);
    EXPECT_EQ(back->lens.iso, camera.lens.iso);
}

TEST(ExrFrame, NearFarComeFromWorldToNdcWithoutClipAttributes) {
    Camera camera = testCamera();
    for (const float far : {400.0f, std::numeric_limits<float>::infinity()}) {
        camera.farPlane = far;
        camera.projection = perspectiveProjection(camera.verticalFov, 1.5f, camera.nearPlane, far);
        ExrCameraAttributes a = exrFromCamera(camera, 12, 8);
        a.nearClip.reset();
        a.farClip.reset();
        const std::optional<Camera> back = cameraFromExr(a, 12, 8);
        ASSERT_TRUE(back.has_value());
        EXPECT_NEAR(back->nearPlane, camera.nearPlane, 1e-5f);
        if (std::isinf(far))
            EXPECT_TRUE(std::isinf(back->farPlane));
        else
            EXPECT_NEAR(back->farPlane, far, 0.5f); // float precision of a near/far ratio of 1600
        expectMatNear(back->projection, camera.projection, 1e-3f);
    }
}

TEST(ExrFrame, NearFarFallBackWhenWorldToNdcHasNoDepthRow) {
    ExrCameraAttributes a = exrFromCamera(testCamera(), kWidth, kHeight);
    a.nearClip.reset();
    a.farClip.reset();
    (*a.worldToNDC)[0][2] = (*a.worldToNDC)[1][2] = (*a.worldToNDC)[2][2] = (*a.worldToNDC)[3][2] = 0.0f;
    const std::optional<Camera> back = cameraFromExr(a, kWidth, kHeight);
    ASSERT_TRUE(back.has_value());
    EXPECT_FLOAT_EQ(back->nearPlane, 0.1f);
    EXPECT_TRUE(std::isinf(back->farPlane));
}

/// A world point lands on the same pixel through the file's worldToNDC (OpenEXR NDC, y down) as through the
/// GL camera (GL NDC, y up, rows flipped).
TEST(ExrFrame, GlCameraProjectsToTheSamePixelAsWorldToNdc) {
    ExrCameraAttributes a = exrFromCamera(testCamera(), kWidth, kHeight);
    // A renderer's own matrix scale is arbitrary: w scaled by 3 leaves NDC unchanged.
    *a.worldToNDC = 3.0f * *a.worldToNDC;
    const std::optional<Camera> camera = cameraFromExr(a, kWidth, kHeight);
    ASSERT_TRUE(camera.has_value());
    for (const glm::vec3 world : {glm::vec3(0.5f, 0.0f, -1.0f), glm::vec3(1.0f, 0.7f, -2.0f),
                                  glm::vec3(-0.3f, -0.2f, 0.4f), glm::vec3(2.0f, 1.0f, -10.0f)}) {
        const glm::vec4 exr = *a.worldToNDC * glm::vec4(world, 1.0f);
        const glm::vec2 exrPixel(exr.x / exr.w * kWidth, exr.y / exr.w * kHeight); // from the top-left
        const glm::vec4 clip = camera->viewProjection() * glm::vec4(world, 1.0f);
        const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
        const glm::vec2 glPixel((ndc.x * 0.5f + 0.5f) * kWidth, (0.5f - ndc.y * 0.5f) * kHeight);
        EXPECT_NEAR(glPixel.x, exrPixel.x, 1e-4f);
        EXPECT_NEAR(glPixel.y, exrPixel.y, 1e-4f);
        // In front of the camera: OpenEXR camera z > 0, GL view z < 0, and the same distance.
        const float exrDepth = (*a.worldToCamera * glm::vec4(world, 1.0f)).z;
        EXPECT_GT(exrDepth, 0.0f);
        EXPECT_NEAR((camera->view * glm::vec4(world, 1.0f)).z, -exrDepth, 1e-5f);
    }
}

TEST(ExrFrame, PreviousFrameGivesPrevViewProjection) {
    const Camera current = testCamera();
    Camera previous = current;
    previous.view = glm::translate(current.view, glm::vec3(0.3f, 0.0f, 0.1f));
    const ExrCameraAttributes prevAttributes = exrFromCamera(previous, kWidth, kHeight);
    const std::optional<Camera> camera =
        cameraFromExr(exrFromCamera(current, kWidth, kHeight), kWidth, kHeight, &prevAttributes);
    ASSERT_TRUE(camera.has_value());
    expectMatNear(camera->prevViewProjection, previous.viewProjection(), 1e-4f);
}

TEST(ExrFrame, DataWindowCropMapsTheDataWindowToFullNdc) {
    const glm::mat4 crop = dataWindowCrop({100, 50}, {20, 10}, {40, 30});
    // The data window's corners in display GL NDC (y up): x 20..60 of 100, rows 10..40 of 50 from the top.
    const glm::vec4 topLeft =
        crop * glm::vec4(-1.0f + 2.0f * 20.0f / 100.0f, 1.0f - 2.0f * 10.0f / 50.0f, 0, 1);
    const glm::vec4 bottomRight =
        crop * glm::vec4(-1.0f + 2.0f * 60.0f / 100.0f, 1.0f - 2.0f * 40.0f / 50.0f, 0, 1);
    EXPECT_NEAR(topLeft.x, -1.0f, 1e-6f);
    EXPECT_NEAR(topLeft.y, 1.0f, 1e-6f);
    EXPECT_NEAR(bottomRight.x, 1.0f, 1e-6f);
    EXPECT_NEAR(bottomRight.y, -1.0f, 1e-6f);
    const glm::mat4 identity = dataWindowCrop({64, 32}, {0, 0}, {64, 32});
    expectMatNear(identity, glm::mat4(1.0f), 1e-6f);
}

/// Writes a small file with the given channels (all FLOAT) and float attributes.
void writeRaw(const fs::path& path, const std::vector<std::string>& channels,
              const std::function<void(Imf::Header&)>& attributes = {}) {
    Imf::Header header(2, 2);
    std::vector<float> values(4, 1.0f);
    Imf::FrameBuffer frameBuffer;
    for (const auto& name : channels) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                            2 * sizeof(float)));
    }
    if (attributes)
        attributes(header);
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frameBuffer);
    file.writePixels(2);
}

void expectIoError(const fs::path& path, const std::string& fragment) {
    try {
        (void)readExrFrame(path);
        ADD_FAILURE() << "no error for " << path;
    } catch (const IoError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.string()), std::string::npos) << what;
        EXPECT_NE(what.find(fragment), std::string::npos) << what;
    }
}

// The camera for the frame's pixels: the display window's cropped to the data window, and refused where
// the crop takes it past the float range (a 64x64 display window over 4x4 pixels, with a projection whose
// entries near 1e38 were finite before the crop's factor of 16).
TEST(ExrFrame, FrameCameraIsCroppedToTheDataWindowAndStaysFinite) {
    ExrFrame frame;
    frame.color = ImageF(40, 30);
    frame.displaySize = {100, 50};
    frame.dataOrigin = {20, 10};
    frame.camera = exrFromCamera(testCamera(), 100, 50);
    const std::optional<Camera> display = cameraFromExr(frame.camera, 100, 50);
    const std::optional<Camera> cropped = frameCamera(frame);
    ASSERT_TRUE(display && cropped);
    const glm::mat4 crop = dataWindowCrop({100, 50}, {20, 10}, {40, 30});
    expectMatNear(cropped->projection, crop * display->projection, 1e-5f);
    expectMatNear(cropped->prevViewProjection, crop * display->prevViewProjection, 1e-4f);
    expectMatNear(cropped->view, display->view, 0.0f);

    frame.color = ImageF(4, 4);
    frame.displaySize = {64, 64};
    frame.dataOrigin = {0, 0};
    // The camera 4 units behind the origin; NDC y picks up a huge multiple of depth.
    frame.camera = {};
    frame.camera.worldToCamera = glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                                           glm::vec4(0, 0, 1, 0), glm::vec4(-0.5f, -1, 4, 1));
    frame.camera.worldToNDC =
        glm::mat4(glm::vec4(1.18261f, 0, 0, 0), glm::vec4(0, -1.18261f, 0, 0),
                  glm::vec4(0.5f, -1.28769e37f, 1.18077e21f, 1), glm::vec4(1.40869f, 3.18261f, 3.76176f, 4));
    EXPECT_NO_THROW((void)cameraFromExr(frame.camera, 64, 64));
    EXPECT_THROW((void)frameCamera(frame), std::invalid_argument);
}

TEST(ExrFrame, IncompleteLayerIsAnErrorNamingTheFile) {
    const test::TempFolder folder;
    writeRaw(folder / "n.exr", {"R", "G", "B", "N.X", "N.Y"});
    expectIoError(folder / "n.exr", "has N.X, N.Y but not N.Z");
    writeRaw(folder / "m.exr", {"R", "G", "B", "motion.Y"});
    expectIoError(folder / "m.exr", "not motion.X");
}

// Luminance/chroma colour is read by its own pass: a file with no other layer has no second one to run.
TEST(ExrFrame, LuminanceChromaFileWithoutLayersIsRead) {
    const test::TempFolder folder;
    const fs::path path = folder / "yc.exr";
    std::vector<Imf::Rgba> pixels(16, Imf::Rgba(0.5f, 0.25f, 0.125f, 1.0f));
    {
        Imf::RgbaOutputFile file(path.c_str(), Imf::Header(4, 4), Imf::WRITE_YC);
        file.setFrameBuffer(pixels.data(), 1, 4);
        file.writePixels(4);
    }
    const ExrFrame frame = readExrFrame(path);
    EXPECT_EQ(frame.color.width, 4);
    EXPECT_TRUE(frame.depth.empty());
    EXPECT_NEAR(frame.color.rgba[0] + frame.color.rgba[1] + frame.color.rgba[2], 0.875f, 0.05f);
}

TEST(ExrFrame, AlternativeLayerNamesAreRead) {
    const test::TempFolder folder;
    writeRaw(folder / "alt.exr", {"R", "G", "B", "depth.Z", "normal.X", "normal.Y", "normal.Z"});
    const ExrFrame frame = readExrFrame(folder / "alt.exr");
    EXPECT_EQ(frame.depth, std::vector<float>(4, 1.0f));
    EXPECT_EQ(frame.normals, std::vector<float>(12, 1.0f));
}

TEST(ExrFrame, WrongTypedAttributeIsAnErrorNamingTheFile) {
    const test::TempFolder folder;
    writeRaw(folder / "attr.exr", {"R", "G", "B"},
             [](Imf::Header& h) { h.insert("worldToNDC", Imf::FloatAttribute(2.0f)); });
    expectIoError(folder / "attr.exr", "attribute worldToNDC is of type float, expected m44f");
    writeRaw(folder / "lens.exr", {"R", "G", "B"},
             [](Imf::Header& h) { h.insert("pinholeFocalLength", Imf::StringAttribute("35mm")); });
    expectIoError(folder / "lens.exr", "pinholeFocalLength");
}

TEST(ExrFrame, NonFiniteJitterIsAnErrorNamingTheFile) {
    const test::TempFolder folder;
    writeRaw(folder / "jitter.exr", {"R", "G", "B"}, [](Imf::Header& h) {
        h.insert("jitter", Imf::V2fAttribute(Imath::V2f(std::numeric_limits<float>::quiet_NaN(), 0.0f)));
    });
    expectIoError(folder / "jitter.exr", "attribute jitter");
}

/// A header by hand: the magic number, version 2 (single-part scanline), then each attribute as name, type,
/// declared size and value bytes, then the header's end. OpenEXR parses it before any pixel is read.
std::vector<unsigned char>
rawHeader(const std::vector<std::tuple<std::string, std::string, std::vector<unsigned char>>>& attributes,
          std::uint32_t declaredSizeOfLast = UINT32_MAX) {
    std::vector<unsigned char> bytes{0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    for (std::size_t i = 0; i < attributes.size(); ++i) {
        const auto& [name, type, value] = attributes[i];
        bytes.insert(bytes.end(), name.begin(), name.end());
        bytes.push_back(0);
        bytes.insert(bytes.end(), type.begin(), type.end());
        bytes.push_back(0);
        const std::uint32_t size = i + 1 == attributes.size() && declaredSizeOfLast != UINT32_MAX
                                       ? declaredSizeOfLast
                                       : std::uint32_t(value.size());
        for (int b = 0; b < 4; ++b)
            bytes.push_back(static_cast<unsigned char>(size >> (8 * b)));
        bytes.insert(bytes.end(), value.begin(), value.end());
    }
    bytes.push_back(0);
    bytes.resize(bytes.size() + 64, 0); // room that a misread size could claim
    return bytes;
}

void expectDecodeError(const std::vector<unsigned char>& bytes, const std::string& fragment) {
    for (const bool frame : {true, false}) {
        try {
            if (frame)
                (void)decodeExrFrame(bytes, "hand.exr");
            else
                (void)decodeImage(bytes, "hand.exr");
            ADD_FAILURE() << "no error";
        } catch (const IoError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("hand.exr"), std::string::npos) << what;
            EXPECT_NE(what.find(fragment), std::string::npos) << what;
        }
    }
}

// OpenEXR reads a fixed-size value or a channel list by its own length, not the declared size: a size that
// differs puts it out of step, and it then trusts a size read from the middle of a value (it allocated 1.2
// GB for a 29-byte file). Such headers are refused before OpenEXR sees them.
TEST(ExrFrame, HeaderValuesOfAnotherSizeThanDeclaredAreRefused) {
    expectDecodeError(rawHeader({{"gain", "float", {0, 0, 0x80, 0x3f, 0, 0x7f}}}), "a float has 4");
    expectDecodeError(rawHeader({{"window", "box2i", std::vector<unsigned char>(16, 0)}}, 0),
                      "a box2i has 16");
    // A channel list whose empty name comes after its declared size ends: OpenEXR reads on to it.
    expectDecodeError(rawHeader({{"s", "chlist", {}}}), "does not end where");
    std::vector<unsigned char> channel{'R', 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0};
    expectDecodeError(rawHeader({{"channels", "chlist", channel}}, std::uint32_t(channel.size() - 1)),
                      "does not end where");
}

// OpenEXR's reader merges a second channel list into the first, its core library keeps one of them: the
// pixels would be read with one set of channels and laid out by the other.
TEST(ExrFrame, AttributeNamedTwiceIsRefused) {
    const std::vector<unsigned char> red{'R', 0, 2, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0};
    const std::vector<unsigned char> alpha{'A', 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0};
    expectDecodeError(rawHeader({{"channels", "chlist", red}, {"channels", "chlist", alpha}}),
                      "attribute \"channels\" appears twice");
}

// An attribute of the wrong type for one OpenEXR predefines (`channels`) fails in OpenEXR's own header
// parse: an IoError naming the file, not OpenEXR's exception.
TEST(ExrFrame, PredefinedAttributeOfAnotherTypeIsAnErrorNamingTheFile) {
    const std::vector<unsigned char> bytes = rawHeader({{"channels", "float", {0, 0, 0x80, 0x3f}}});
    expectDecodeError(bytes, "channels");
    const test::TempFolder folder;
    std::ofstream(folder / "typed.exr", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    expectIoError(folder / "typed.exr", "Unexpected type for image attribute \"channels\"");
}

/// A 16 x 1 file of one half channel Y of constant value (so that RLE and ZIP shrink it), compressed with
/// `compression`, as bytes.
std::vector<unsigned char> constantLine(Imf::Compression compression) {
    const test::TempFolder folder;
    const fs::path path = folder / "line.exr";
    Imf::Header header(16, 1);
    header.compression() = compression;
    header.channels().insert("Y", Imf::Channel(Imf::HALF));
    std::vector<half> values(16, half(0.5f));
    Imf::FrameBuffer frameBuffer;
    frameBuffer.insert(
        "Y", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(values.data()), sizeof(half), 16 * sizeof(half)));
    {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(1);
    }
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Where the first chunk's leader (line number, then data size, 32 bits each) starts: after the header's
/// attributes and the offset table, here of one entry.
std::size_t firstChunk(const std::vector<unsigned char>& bytes) {
    std::size_t pos = 8;
    const auto skipString = [&] {
        const std::size_t start = pos;
        while (bytes.at(pos) != 0)
            ++pos;
        ++pos;
        return pos - start > 1;
    };
    while (skipString()) {
        skipString();
        const std::uint32_t size = std::uint32_t(bytes[pos]) | std::uint32_t(bytes[pos + 1]) << 8 |
                                   std::uint32_t(bytes[pos + 2]) << 16 | std::uint32_t(bytes[pos + 3]) << 24;
        pos += 4 + size;
    }
    return pos + 8;
}

// OpenEXR 3.1 fills the part of a line a short chunk lacks from its buffers' earlier contents: whatever
// the process held there, different from run to run. Each such chunk is refused, naming the line.
TEST(ExrFrame, ChunksShorterThanTheirLinesAreRefused) {
    // Stored: the leader claims 4 bytes fewer than the line's 32 (the file keeps its length).
    std::vector<unsigned char> stored = constantLine(Imf::NO_COMPRESSION);
    stored[firstChunk(stored) + 4] -= 4;
    expectDecodeError(stored, "the chunk of line 0 holds 28 of the 32 bytes its lines need");

    // RLE: the first run repeats its byte fewer times, so the runs decode to fewer bytes than the line.
    std::vector<unsigned char> rle = constantLine(Imf::RLE_COMPRESSION);
    std::size_t run = firstChunk(rle) + 8;
    while (run < rle.size() && static_cast<signed char>(rle[run]) < 2) // past literal runs and short repeats
        run +=
            static_cast<signed char>(rle[run]) < 0 ? 1 + std::size_t(-static_cast<signed char>(rle[run])) : 2;
    ASSERT_LT(run, rle.size());
    rle[run] -= 2;
    expectDecodeError(rle, "the chunk of line 0 decodes to 30 of the 32 bytes its lines need");

    // ZIP: a valid zlib stream, but of 30 bytes, in place of the line's (zlib inflates it without a word).
    std::vector<unsigned char> zip = constantLine(Imf::ZIPS_COMPRESSION);
    const std::size_t leader = firstChunk(zip);
    const std::vector<unsigned char> thirty(30, 0x80);
    std::vector<unsigned char> stream(64);
    uLongf length = stream.size();
    ASSERT_EQ(compress(stream.data(), &length, thirty.data(), thirty.size()), Z_OK);
    ASSERT_LT(length, 32u);
    zip.resize(leader + 8);
    for (int b = 0; b < 4; ++b)
        zip[leader + 4 + std::size_t(b)] = static_cast<unsigned char>(length >> (8 * b));
    zip.insert(zip.end(), stream.begin(), stream.begin() + std::ptrdiff_t(length));
    expectDecodeError(zip, "the chunk of line 0 does not inflate to the 32 bytes its lines need");

    // The same files unchanged read whole.
    for (const Imf::Compression c : {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION})
        EXPECT_EQ(decodeExrFrame(constantLine(c), "line.exr").color.rgba[0], 0.5f);
}

TEST(ExrFrame, DecodeFromMemoryMatchesTheFile) {
    const test::TempFolder folder;
    writeExrFrame(folder / "frame.exr", testFrame());
    const std::string bytes = encodeExrFrame(testFrame(), "frame.exr");
    const ExrFrame fromFile = readExrFrame(folder / "frame.exr");
    const ExrFrame fromMemory =
        decodeExrFrame({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, "frame.exr");
    EXPECT_EQ(fromMemory.color.rgba, fromFile.color.rgba);
    EXPECT_EQ(fromMemory.depth, fromFile.depth);
    EXPECT_EQ(fromMemory.normals, fromFile.normals);
    EXPECT_EQ(fromMemory.motion, fromFile.motion);
    EXPECT_EQ(fromMemory.attributes, fromFile.attributes);
    EXPECT_EQ(fromMemory.camera.worldToNDC, fromFile.camera.worldToNDC);
}

// A sequence reader's frame after an error is empty, not the earlier frame's layers under a new size, and
// the next read into the same storage is whole again.
TEST(ExrFrame, FailedReadLeavesTheFrameEmptyAndTheReaderUsable) {
    const test::TempFolder folder;
    writeExrFrame(folder / "good.exr", testFrame());
    writeRaw(folder / "bad.exr", {"R", "G", "B", "N.X"});
    ExrFrameReader reader;
    ExrFrame frame;
    reader.read(folder / "good.exr", frame);
    EXPECT_THROW(reader.read(folder / "bad.exr", frame), IoError);
    EXPECT_TRUE(frame.color.empty());
    EXPECT_TRUE(frame.color.rgba.empty());
    EXPECT_TRUE(frame.depth.empty() && frame.normals.empty() && frame.motion.empty());
    EXPECT_FALSE(frame.camera.worldToCamera);
    EXPECT_TRUE(frame.channels.empty());
    EXPECT_EQ(frame.displaySize, glm::ivec2(0, 0));
    reader.read(folder / "good.exr", frame);
    const ExrFrame alone = readExrFrame(folder / "good.exr");
    EXPECT_EQ(frame.color.rgba, alone.color.rgba);
    EXPECT_EQ(frame.normals, alone.normals);
    EXPECT_EQ(frame.camera.jitter, alone.camera.jitter);
}

/// `frame`'s colour kept as halves, widened to floats.
std::vector<float> widenedColor(const ExrFrame& frame) {
    std::vector<float> out(frame.colorHalves.rgba.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        half h;
        h.setBits(frame.colorHalves.rgba[i]);
        out[i] = float(h);
    }
    return out;
}

/// A 6x4 file of `mode` (Imf::WRITE_Y: luminance alone; WRITE_YC: luminance/chroma, subsampled by 2)
/// through OpenEXR's RGBA interface, in half.
void writeRgbaFile(const fs::path& path, Imf::RgbaChannels mode) {
    std::vector<Imf::Rgba> pixels(24);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = Imf::Rgba(half(0.5f + float(i)), half(0.25f * float(i)), half(2.0f), half(1.0f));
    Imf::RgbaOutputFile file(path.c_str(), 6, 4, mode);
    file.setFrameBuffer(pixels.data(), 1, 6);
    file.writePixels(4);
}

// A reader that keeps half colour as halves gives a half file's colour as stored, in `colorHalves` (`color`
// empty), the same values as the floats a reader of floats gives, and every other field the same; a file
// whose colour is not halves as stored (float channels, luminance/chroma, other primaries: converted in
// float) keeps floats. In a sequence, each frame empties the colour it does not use.
TEST(ExrFrame, AReaderKeepingHalvesGivesTheStoredHalves) {
    const test::TempFolder folder;
    writeExrFrame(folder / "half.exr", testFrame()); // colour in half, Z and motion in float
    writeRaw(folder / "float.exr", {"R", "G", "B"});
    writeRgbaFile(folder / "y.exr", Imf::WRITE_Y);
    writeRgbaFile(folder / "yc.exr", Imf::WRITE_YC);
    writeRaw(folder / "rec2020.exr", {"R", "G", "B"}, [](Imf::Header& header) {
        Imf::addChromaticities(header,
                               Imf::Chromaticities(Imath::V2f(0.708f, 0.292f), Imath::V2f(0.170f, 0.797f),
                                                   Imath::V2f(0.131f, 0.046f), Imath::V2f(0.3127f, 0.3290f)));
    });
    ExrFrameReader reader(ExrFrameReader::Color::HalvesWhenStored);
    ExrFrame frame;
    struct Case {
        const char* name;
        bool halves;
    };
    // Twice over, so that each file is read into storage every other kind left.
    for (int round = 0; round < 2; ++round) {
        for (const Case c : {Case{"half.exr", true}, Case{"float.exr", false}, Case{"y.exr", true},
                             Case{"yc.exr", false}, Case{"half.exr", true}}) {
            reader.read(folder / c.name, frame);
            const ExrFrame floats = readExrFrame(folder / c.name);
            EXPECT_EQ(frame.width(), floats.color.width) << c.name;
            EXPECT_EQ(frame.height(), floats.color.height) << c.name;
            if (c.halves) {
                EXPECT_TRUE(frame.color.empty() && frame.color.rgba.empty()) << c.name;
                EXPECT_EQ(frame.colorHalves.rgba.size(), floats.color.rgba.size()) << c.name;
                EXPECT_EQ(widenedColor(frame), floats.color.rgba) << c.name;
            } else {
                EXPECT_TRUE(frame.colorHalves.empty() && frame.colorHalves.rgba.empty()) << c.name;
                EXPECT_EQ(frame.color.width, floats.color.width) << c.name;
                EXPECT_EQ(frame.color.rgba, floats.color.rgba) << c.name;
            }
            EXPECT_EQ(frame.halfColor, floats.halfColor) << c.name;
            EXPECT_EQ(frame.depth, floats.depth) << c.name;
            EXPECT_EQ(frame.normals, floats.normals) << c.name;
            EXPECT_EQ(frame.motion, floats.motion) << c.name;
            EXPECT_EQ(frame.channels, floats.channels) << c.name;
            EXPECT_EQ(frame.camera.worldToNDC, floats.camera.worldToNDC) << c.name;
            const std::optional<Camera> camera = frameCamera(frame);
            const std::optional<Camera> expected = frameCamera(floats);
            ASSERT_EQ(camera.has_value(), expected.has_value()) << c.name;
            if (camera)
                EXPECT_EQ(camera->projection, expected->projection) << c.name;
        }
    }
    // Y alone is copied to G and B, as halves too; alpha absent is 1.
    reader.read(folder / "y.exr", frame);
    ASSERT_FALSE(frame.colorHalves.empty());
    EXPECT_EQ(frame.colorHalves.rgba[1], frame.colorHalves.rgba[0]);
    EXPECT_EQ(frame.colorHalves.rgba[2], frame.colorHalves.rgba[0]);
    EXPECT_EQ(frame.colorHalves.rgba[3], 0x3C00);
    // Other primaries are converted in float: floats, as a reader of floats gives them.
    reader.read(folder / "rec2020.exr", frame);
    EXPECT_TRUE(frame.colorHalves.empty());
    EXPECT_EQ(frame.color.rgba, readExrFrame(folder / "rec2020.exr").color.rgba);
}

// Layers left out are empty in the frames read after, still listed among the channels and still checked (a
// layer missing a component is an error either way); asked for again, they are read again.
TEST(ExrFrame, LayersLeftOutAreNotReadButStillChecked) {
    const test::TempFolder folder;
    writeExrFrame(folder / "frame.exr", testFrame());
    writeRaw(folder / "bad.exr", {"R", "G", "B", "N.X", "N.Y"});
    const ExrFrame whole = readExrFrame(folder / "frame.exr");
    ExrFrameReader reader;
    ExrFrame frame;
    reader.setLayers({.depth = false, .normals = true, .motion = false});
    reader.read(folder / "frame.exr", frame);
    EXPECT_TRUE(frame.depth.empty());
    EXPECT_TRUE(frame.motion.empty());
    EXPECT_EQ(frame.normals, whole.normals);
    EXPECT_EQ(frame.color.rgba, whole.color.rgba);
    EXPECT_EQ(frame.channels, whole.channels);
    reader.setLayers({.depth = false, .normals = false, .motion = false});
    EXPECT_THROW(reader.read(folder / "bad.exr", frame), IoError);
    reader.setLayers({});
    reader.read(folder / "frame.exr", frame);
    EXPECT_EQ(frame.depth, whole.depth);
    EXPECT_EQ(frame.normals, whole.normals);
    EXPECT_EQ(frame.motion, whole.motion);
}

// A frame whose colour is held as halves is written as they are, and reads back the same.
TEST(ExrFrame, ColourHeldAsHalvesIsWrittenAsItIs) {
    const test::TempFolder folder;
    writeExrFrame(folder / "half.exr", testFrame());
    ExrFrameReader reader(ExrFrameReader::Color::HalvesWhenStored);
    ExrFrame frame;
    reader.read(folder / "half.exr", frame);
    ASSERT_FALSE(frame.colorHalves.empty());
    writeExrFrame(folder / "again.exr", frame);
    ExrFrame again;
    reader.read(folder / "again.exr", again);
    EXPECT_EQ(again.colorHalves.rgba, frame.colorHalves.rgba);
    EXPECT_EQ(again.depth, frame.depth);
    frame.colorHalves.rgba.pop_back();
    EXPECT_THROW(writeExrFrame(folder / "bad.exr", frame), IoError);
    EXPECT_FALSE(fs::exists(folder / "bad.exr"));
}

TEST(ExrFrame, NotAnExrIsAnError) {
    const test::TempFolder folder;
    writePng(folder / "x.exr", Image8(2, 2));
    expectIoError(folder / "x.exr", "not an OpenEXR");
    expectIoError(folder / "missing.exr", "does not exist");
}

TEST(ExrFrame, BadCameraMatricesAreInvalidArguments) {
    ExrCameraAttributes a = exrFromCamera(testCamera(), kWidth, kHeight);
    ExrCameraAttributes nan = a;
    (*nan.worldToNDC)[1][2] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW((void)cameraFromExr(nan, kWidth, kHeight), std::invalid_argument);
    ExrCameraAttributes singular = a;
    *singular.worldToCamera = glm::mat4(0.0f);
    EXPECT_THROW((void)cameraFromExr(singular, kWidth, kHeight), std::invalid_argument);
    ExrCameraAttributes affine = a;
    *affine.worldToNDC = glm::mat4(1.0f) * *affine.worldToCamera; // w no longer follows depth
    EXPECT_THROW((void)cameraFromExr(affine, kWidth, kHeight), std::invalid_argument);
    ExrCameraAttributes badLens = a;
    badLens.aperture = 0.0f;
    EXPECT_THROW((void)cameraFromExr(badLens, kWidth, kHeight), std::invalid_argument);
}

TEST(ExrFrame, WriteRejectsMismatchedLayers) {
    const test::TempFolder folder;
    ExrFrame frame = testFrame();
    frame.depth.pop_back();
    EXPECT_THROW(writeExrFrame(folder / "bad.exr", frame), IoError);
    EXPECT_FALSE(fs::exists(folder / "bad.exr"));
}

} // namespace
} // namespace photopic
