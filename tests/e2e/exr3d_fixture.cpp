// Test fixture for exr3d.sh: writes a small 3D EXR sequence (colour, Z, world-space N, pixel motion
// and the camera attributes) plus malformed files, and checks the files `photopic image --write-aux` writes
// back against the values the sequence was built from, in the pipeline's conventions.
//
//   photopic_exr3d_fixture write DIR       DIR/seq/frame_000N.exr, DIR/plain/plain.exr, DIR/bad/..., cameras
//   photopic_exr3d_fixture check-aux DIR   DIR/frame_000N.aux.exr: exit 0 when every value matches

#include "io/ExrFrame.h"
#include "io/ImageIO.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace photopic;
namespace fs = std::filesystem;

constexpr int kWidth = 32;
constexpr int kHeight = 24;
constexpr int kFrames = 10;

Camera frameCamera(int f) {
    Camera camera;
    const glm::vec3 eye(0.2f * float(f), 1.0f, 5.0f);
    camera.view = glm::lookAt(eye, eye + glm::vec3(0.0f, -0.2f, -1.0f), glm::vec3(0, 1, 0));
    camera.verticalFov = 0.9f;
    camera.nearPlane = 0.1f;
    camera.farPlane = 100.0f;
    camera.projection = perspectiveProjection(camera.verticalFov, float(kWidth) / float(kHeight),
                                              camera.nearPlane, camera.farPlane);
    camera.lens.focalLengthMm = 30.0f;
    camera.lens.sensorHeightMm = 2.0f * 30.0f * std::tan(0.45f);
    camera.lens.fNumber = 5.6f;
    camera.lens.focusDistance = 4.0f;
    return camera;
}

/// The sample jitter of frame f in pixels, x right, y down (none before the first frame).
glm::vec2 frameJitter(int f) {
    if (f < 0)
        return glm::vec2(0.0f);
    const glm::vec2 j = haltonJitter(std::uint64_t(f), 8);
    return {j.x, -j.y};
}

float depthAt(std::size_t i) {
    return i + 1 == std::size_t(kWidth) * kHeight ? std::numeric_limits<float>::infinity()
                                                  : 2.0f + 0.01f * float(i);
}
glm::vec3 worldNormalAt(std::size_t i) {
    return glm::normalize(glm::vec3(std::sin(0.1f * float(i)), 1.0f, std::cos(0.07f * float(i))));
}
/// The surface's own motion in pixels (x right, y down), without jitter.
glm::vec2 trueMotion(int f) {
    return {0.5f + 0.1f * float(f), -0.25f};
}

/// Frame f; `jitteredMotion`: its motion measured between the frames' jittered samples, as a renderer that
/// says so (--aov motion=:jittered) writes it, instead of the surfaces' own.
ExrFrame makeFrame(int f, bool jitteredMotion = false) {
    ExrFrame frame;
    frame.color = ImageF(kWidth, kHeight);
    const std::size_t pixels = std::size_t(kWidth) * kHeight;
    frame.depth.resize(pixels);
    frame.normals.resize(pixels * 3);
    frame.motion.resize(pixels * 2);
    const glm::vec2 motion =
        jitteredMotion ? trueMotion(f) + frameJitter(f) - frameJitter(f - 1) : trueMotion(f);
    for (std::size_t i = 0; i < pixels; ++i) {
        frame.color.rgba[i * 4 + 0] = 0.1f + 0.02f * float(i % kWidth);
        frame.color.rgba[i * 4 + 1] = 0.2f;
        frame.color.rgba[i * 4 + 2] = 0.3f + 0.05f * float(f);
        frame.color.rgba[i * 4 + 3] = 1.0f;
        frame.depth[i] = depthAt(i);
        const glm::vec3 n = worldNormalAt(i);
        frame.normals[i * 3 + 0] = n.x;
        frame.normals[i * 3 + 1] = n.y;
        frame.normals[i * 3 + 2] = n.z;
        frame.motion[i * 2 + 0] = motion.x;
        frame.motion[i * 2 + 1] = motion.y;
    }
    frame.camera = exrFromCamera(frameCamera(f), kWidth, kHeight);
    frame.camera.jitter = frameJitter(f);
    return frame;
}

std::string frameName(int f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d", f);
    return name;
}

/// A file whose normal layer lacks N.Z (writeExrFrame only writes whole layers).
void writeMissingNz(const fs::path& path) {
    Imf::Header header(kWidth, kHeight);
    std::vector<float> values(std::size_t(kWidth) * kHeight, 0.5f);
    Imf::FrameBuffer frameBuffer;
    for (const char* name : {"R", "G", "B", "N.X", "N.Y"}) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                            sizeof(float) * kWidth));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frameBuffer);
    file.writePixels(kHeight);
}

void writeAll(const fs::path& dir) {
    fs::create_directories(dir / "seq");
    fs::create_directories(dir / "seq-jittered-motion");
    fs::create_directories(dir / "plain");
    fs::create_directories(dir / "bad");
    for (int f = 0; f < kFrames; ++f) {
        writeExrFrame(dir / "seq" / (frameName(f) + ".exr"), makeFrame(f));
        writeExrFrame(dir / "seq-jittered-motion" / (frameName(f) + ".exr"), makeFrame(f, true));
    }

    ExrFrame plain = makeFrame(0); // normals but no camera: --camera supplies it
    plain.camera = {};
    writeExrFrame(dir / "plain" / "plain.exr", plain);

    ExrFrame nan = makeFrame(0);
    (*nan.camera.worldToNDC)[2][1] = std::numeric_limits<float>::quiet_NaN();
    writeExrFrame(dir / "bad" / "nan_ndc.exr", nan);
    writeMissingNz(dir / "bad" / "missing_nz.exr");

    writeTextFile(dir / "camera.json", R"({"position": [0, 1, 5], "target": [0, 0.8, 4], "up": [0, 1, 0],
 "verticalFovDeg": 50, "near": 0.1, "far": 100, "lens": {"fNumber": 8, "focusDistance": 3}})");
    writeTextFile(dir / "bad" / "camera.json", R"({"position": [0, 1, 5], "target": [0, 0, 0],
 "verticalFovDeg": 190})");
    writeTextFile(dir / "bad" / "camera_key.json",
                  R"({"position": [0, 1, 5], "target": [0, 0, 0], "fov": 50})");
}

int failures = 0;
void expectNear(const char* what, int f, std::size_t i, float got, float want, float tolerance) {
    const bool same = (std::isinf(want) && got == want) || std::abs(got - want) <= tolerance;
    if (!same && failures++ < 10)
        std::fprintf(stderr, "frame %d pixel %zu %s: got %.7g, want %.7g (tolerance %g)\n", f, i, what,
                     double(got), double(want), double(tolerance));
}

int checkAux(const fs::path& dir) {
    for (int f = 0; f < kFrames; ++f) {
        const ExrFrame aux = readExrFrame(dir / (frameName(f) + ".aux.exr"));
        const std::size_t pixels = std::size_t(kWidth) * kHeight;
        if (aux.depth.size() != pixels || aux.normals.size() != pixels * 3 ||
            aux.motion.size() != pixels * 2) {
            std::fprintf(stderr, "frame %d: aux file lacks a layer\n", f);
            return 1;
        }
        const glm::mat3 view(frameCamera(f).view);
        // UV motion: x / width, y flipped to point up, jitter of both frames removed.
        const glm::vec2 uv(trueMotion(f).x / float(kWidth), -trueMotion(f).y / float(kHeight));
        for (std::size_t i = 0; i < pixels; ++i) {
            expectNear("depth", f, i, aux.depth[i], depthAt(i), 1e-3f);
            const glm::vec3 n = view * worldNormalAt(i); // a rigid view: its rotation is its normal matrix
            for (int c = 0; c < 3; ++c)
                expectNear("view normal", f, i, aux.normals[i * 3 + std::size_t(c)], n[c], 2e-3f); // half
            expectNear("motion u", f, i, aux.motion[i * 2 + 0], uv.x, 1e-6f);
            expectNear("motion v", f, i, aux.motion[i * 2 + 1], uv.y, 1e-6f);
        }
        if (!aux.camera.worldToCamera) {
            std::fprintf(stderr, "frame %d: aux file has no camera\n", f);
            return 1;
        }
        const glm::mat4 expected = *exrFromCamera(frameCamera(f), kWidth, kHeight).worldToCamera;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                expectNear("worldToCamera", f, std::size_t(c * 4 + r), (*aux.camera.worldToCamera)[c][r],
                           expected[c][r], 1e-5f);
    }
    std::printf("%d frames checked, %d mismatches\n", kFrames, failures);
    return failures == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s write DIR | check-aux DIR\n", argv[0]);
        return 2;
    }
    try {
        if (std::strcmp(argv[1], "write") == 0) {
            writeAll(argv[2]);
            return 0;
        }
        if (std::strcmp(argv[1], "check-aux") == 0)
            return checkAux(argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    std::fprintf(stderr, "unknown mode %s\n", argv[1]);
    return 2;
}
