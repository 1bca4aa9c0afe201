#include "ImageInputs.h"

#include "Commands.h"

#include "core/HalfFloat.h"
#include "core/Log.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"

#include <fmt/format.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace photopic::cli {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------------------------
// Decoding

namespace {

/// World-space normals into view space with the view's normal matrix, in place; zero or non-finite normals
/// (no surface) become zero.
void viewSpaceNormals(std::vector<float>& normals, const glm::mat4& view) {
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view)));
    for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
        const glm::vec3 n = normalMatrix * glm::vec3(normals[i], normals[i + 1], normals[i + 2]);
        const float length = glm::length(n);
        const bool surface = length > 0.0f && std::isfinite(length);
        normals[i] = surface ? n.x / length : 0.0f;
        normals[i + 1] = surface ? n.y / length : 0.0f;
        normals[i + 2] = surface ? n.z / length : 0.0f;
    }
}

/// Gives back the storage of the layers `layers` leaves out.
void freeUnreadLayers(ExrFrameReader::Layers layers, std::vector<float>& depth, std::vector<float>& normals,
                      std::vector<float>& motion) {
    for (auto [layer, read] : {std::pair{&depth, layers.depth}, std::pair{&normals, layers.normals},
                               std::pair{&motion, layers.motion}}) {
        if (!read)
            *layer = std::vector<float>();
    }
}

/// Pixels (x right, y down, current minus previous, samples jittered) -> UV (y up), jitter removed, in
/// place: a jittered sample of the current frame sits at p + j_current, of the previous frame at
/// p' + j_previous, so the surface's own motion is m - j_current + j_previous.
void uvMotion(std::vector<float>& motion, int width, int height, glm::vec2 jitter, glm::vec2 previousJitter) {
    const glm::vec2 unjitter = previousJitter - jitter;
    for (std::size_t i = 0; i + 1 < motion.size(); i += 2) {
        motion[i] = (motion[i] + unjitter.x) / float(width);
        motion[i + 1] = -(motion[i + 1] + unjitter.y) / float(height);
    }
}

bool isExr(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[4] = {};
    in.read(reinterpret_cast<char*>(magic), 4);
    return in.gcount() == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

} // namespace

InputDecoder::InputDecoder(std::optional<CameraJson> cameraJson, int haltonCycle, std::int64_t maxPixels)
    : mCameraJson(std::move(cameraJson))
    , mHaltonCycle(haltonCycle)
    , mMaxPixels(maxPixels) {}

DecodedFrame InputDecoder::decode(const fs::path& path) {
    DecodedFrame out;
    if (!isExr(path)) { // HDR, PNG, or a missing file: colour only, through readImage's errors
        try {
            out.color = readImage(path, {.maxPixels = mMaxPixels});
        } catch (const IoError& e) {
            throw InputError(e.what());
        }
        if (mCameraJson) {
            out.camera = mCameraJson->camera(out.color.width, out.color.height);
            out.camera->cut = mFirst;
        }
        mPrevious.reset();
        mFirst = false;
        return out;
    }
    ExrFrame& frame = mFrame; // storage kept from the frame before (recycle())
    const ExrFrameReader::Layers layers = layersRead();
    mReader.setLayers(layers);
    // Storage kept for a layer no longer read (the frames decoded before readLayers() had it) goes back.
    freeUnreadLayers(layers, frame.depth, frame.normals, frame.motion);
    try {
        mReader.read(path, frame, {.maxPixels = mMaxPixels});
    } catch (const IoError& e) {
        throw InputError(e.what());
    }
    const int width = frame.width();
    const int height = frame.height();
    const glm::ivec2 dataEnd = frame.dataOrigin + glm::ivec2(width, height);
    if (frame.dataOrigin.x < 0 || frame.dataOrigin.y < 0 || dataEnd.x > frame.displaySize.x ||
        dataEnd.y > frame.displaySize.y) {
        // Overscan (or a window entirely elsewhere): every stored pixel is processed and written, as the
        // data window's size, like a crop within the display window.
        warnOnce("cli.dataWindowOutsideDisplay",
                 fmt::format("{}: its data window ({}x{} at {},{}) reaches outside its display window ({}x{} "
                             "at 0,0): the whole data window is processed and written, at {}x{}",
                             path.string(), width, height, frame.dataOrigin.x, frame.dataOrigin.y,
                             frame.displaySize.x, frame.displaySize.y, width, height));
    }
    try {
        out.camera = frameCamera(frame, mPrevious ? &*mPrevious : nullptr);
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("\"{}\": bad camera attributes: {}", path.string(), e.what()));
    }
    if (!out.camera && mCameraJson)
        out.camera = mCameraJson->camera(width, height);
    if (out.camera)
        out.camera->cut = mFirst;

    out.depth = std::move(frame.depth);
    if (!frame.normals.empty()) {
        if (out.camera) {
            out.normals = std::move(frame.normals);
            viewSpaceNormals(out.normals, out.camera->view);
        } else {
            warnOnce("cli.normalsWithoutCamera",
                     fmt::format("{}: normals skipped: turning world-space normals into view space needs a "
                                 "camera (worldToCamera/worldToNDC attributes or --camera FILE.json)",
                                 path.string()));
        }
    }
    // The file's jitter attribute, else the sample offset of the Halton jitter Photopic would have handed
    // out: moving the image by j (x right, y up) samples it at the pixel centre - j, which in the file's
    // y-down convention is (-j.x, j.y).
    std::optional<glm::vec2> jitter = frame.camera.jitter;
    if (!jitter && mHaltonCycle > 0) {
        const glm::vec2 halton = haltonJitter(mIndex, mHaltonCycle);
        jitter = glm::vec2(-halton.x, halton.y);
    }
    out.jittered = jitter.has_value();
    if (const std::optional<glm::vec3> sun = frame.camera.sunDirection) {
        if (!std::isfinite(sun->x) || !std::isfinite(sun->y) || !std::isfinite(sun->z) ||
            glm::dot(*sun, *sun) <= 0.0f)
            throw InputError(
                fmt::format("\"{}\": attribute sunDirection ({}, {}, {}) is not a finite, non-zero "
                            "direction",
                            path.string(), sun->x, sun->y, sun->z));
        out.sunDirection = sun;
    }
    if (!frame.motion.empty()) {
        out.motion = std::move(frame.motion);
        uvMotion(out.motion, width, height, jitter.value_or(glm::vec2(0.0f)),
                 mPreviousJitter.value_or(glm::vec2(0.0f)));
    }
    out.color = std::move(frame.color);
    out.colorHalves = std::move(frame.colorHalves);
    mPrevious = frame.camera;
    mPreviousJitter = jitter;
    ++mIndex;
    mFirst = false;
    return out;
}

void InputDecoder::readLayers(ExrFrameReader::Layers layers) {
    const std::lock_guard lock(mLayersMutex);
    mLayers = layers;
}

ExrFrameReader::Layers InputDecoder::layersRead() {
    const std::lock_guard lock(mLayersMutex);
    return mLayers;
}

void InputDecoder::leaveOutUnread(DecodedFrame& frame) {
    freeUnreadLayers(layersRead(), frame.depth, frame.normals, frame.motion);
}

void InputDecoder::recycle(DecodedFrame&& frame) {
    if (frame.color.rgba.capacity() > mFrame.color.rgba.capacity())
        mFrame.color = std::move(frame.color);
    if (frame.colorHalves.rgba.capacity() > mFrame.colorHalves.rgba.capacity())
        mFrame.colorHalves = std::move(frame.colorHalves);
    if (frame.depth.capacity() > mFrame.depth.capacity())
        mFrame.depth = std::move(frame.depth);
    if (frame.normals.capacity() > mFrame.normals.capacity())
        mFrame.normals = std::move(frame.normals);
    if (frame.motion.capacity() > mFrame.motion.capacity())
        mFrame.motion = std::move(frame.motion);
}

// ---------------------------------------------------------------------------------------------------------------
// Textures

namespace {

/// Makes `texture` `extent` x `format` unless it already is.
void ensure(Texture& texture, Extent extent, GLenum format, std::string_view name) {
    if (!texture.valid() || texture.extent() != extent || texture.format() != format)
        texture = Texture({.extent = extent, .format = format, .debugName = name});
}

/// Where each layer's texels sit in an upload slot (offsets in bytes, each on a 256-byte boundary, so that
/// every layer starts on a cache line and a multiple of any value's size), and the bytes the slot needs.
struct SlotLayout {
    std::size_t color = 0;
    std::size_t depth = 0;
    std::size_t normals = 0;
    std::size_t motion = 0;
    std::size_t bytes = 0;
};

SlotLayout slotLayout(const DecodedFrame& frame, bool halfColor) {
    const std::size_t pixels = std::size_t(frame.width()) * std::size_t(frame.height());
    SlotLayout layout;
    const auto place = [&](std::size_t& offset, std::size_t texelBytes) {
        offset = layout.bytes;
        layout.bytes += (pixels * texelBytes + 255) / 256 * 256;
    };
    place(layout.color, halfColor ? 4 * sizeof(std::uint16_t) : 4 * sizeof(float));
    if (!frame.depth.empty())
        place(layout.depth, sizeof(float));
    if (!frame.normals.empty())
        place(layout.normals, 4 * sizeof(std::uint16_t));
    if (!frame.motion.empty())
        place(layout.motion, 2 * sizeof(std::uint16_t));
    return layout;
}

// The writers below fill slot memory (write-only, front to back) with image rows bottom to top, GL's order,
// so that texel (x, y) is image pixel (x, height - 1 - y), as Texture::uploadRgba32f has it.

/// `components` values a pixel as they are: floats for a 32F texture (a float colour, the depth), halves for
/// a 16F one (a half colour).
template <class Value>
void copyRows(std::byte* out, const Value* values, Extent extent, int components) {
    const std::size_t row = std::size_t(extent.width) * std::size_t(components);
    for (int y = 0; y < extent.height; ++y) {
        std::memcpy(out + std::size_t(y) * row * sizeof(Value),
                    values + std::size_t(extent.height - 1 - y) * row, row * sizeof(Value));
    }
}

/// `components` floats a pixel as halves, rounded to nearest with ties to even (core/HalfFloat.h), for a
/// 16F texture: the motion. The rounding is
/// done here because GL's conversion of floats is the driver's own: Mesa's RGBA16F store rounds toward
/// zero and clamps, and NVIDIA's rounds floats from an unpack buffer otherwise than from client memory.
void writeHalfRows(std::byte* out, const float* values, Extent extent, int components) {
    const std::size_t row = std::size_t(extent.width) * std::size_t(components);
    auto* halves = reinterpret_cast<std::uint16_t*>(out);
    for (int y = 0; y < extent.height; ++y) {
        floatToHalf(values + std::size_t(extent.height - 1 - y) * row, halves + std::size_t(y) * row, row);
    }
}

/// RGBA halves widened to floats (exactly), for a 32F texture; `scratch` holds a row.
void writeHalvesAsFloatRows(std::byte* out, const std::uint16_t* halves, Extent extent,
                            std::vector<float>& scratch) {
    const std::size_t row = std::size_t(extent.width) * 4;
    scratch.resize(row);
    for (int y = 0; y < extent.height; ++y) {
        // Widened in cached memory, then copied: the slot may be write-combined.
        halfToFloat(halves + std::size_t(extent.height - 1 - y) * row, scratch.data(), row);
        std::memcpy(out + std::size_t(y) * row * sizeof(float), scratch.data(), row * sizeof(float));
    }
}

/// Three floats a pixel as four halves (alpha 0), rounded as writeHalfRows rounds; `scratch` holds a row.
void writeNormalRows(std::byte* out, const float* normals, Extent extent,
                     std::vector<std::uint16_t>& scratch) {
    const std::size_t width = std::size_t(extent.width);
    scratch.resize(width * 3);
    auto* texel = reinterpret_cast<std::uint16_t*>(out);
    for (int y = 0; y < extent.height; ++y) {
        floatToHalf(normals + std::size_t(extent.height - 1 - y) * width * 3, scratch.data(), width * 3);
        for (std::size_t x = 0; x < width; ++x, texel += 4) {
            const std::uint16_t four[4] = {scratch[3 * x], scratch[3 * x + 1], scratch[3 * x + 2], 0};
            std::memcpy(texel, four, sizeof(four));
        }
    }
}

} // namespace

FrameInputs InputTextures::upload(const DecodedFrame& frame, bool halfTexture) {
    const Extent extent{frame.width(), frame.height()};
    const bool halfColor = halfTexture && frame.halfColor();
    const SlotLayout layout = slotLayout(frame, halfColor);
    // Made anew when a frame needs more, or under half of it (a sequence whose later frames lack a layer).
    if (!mRing.valid() || mRing.bytes() < layout.bytes || layout.bytes < mRing.bytes() / 2) {
        mRing = UploadRing(); // the old slot goes first: never both at once
        mRing = UploadRing(layout.bytes, kUploadSlots, "cli.input");
    }
    std::byte* slot = mRing.begin().data();
    FrameInputs inputs{.color = &mColor};

    ensure(mColor, extent, halfColor ? GL_RGBA16F : GL_RGBA32F, "cli.input.color");
    if (halfColor) {
        copyRows(slot + layout.color, frame.colorHalves.rgba.data(), extent, 4);
        mRing.upload(mColor, layout.color, GL_RGBA, GL_HALF_FLOAT);
    } else {
        if (frame.halfColor())
            writeHalvesAsFloatRows(slot + layout.color, frame.colorHalves.rgba.data(), extent, mFloatRow);
        else
            copyRows(slot + layout.color, frame.color.rgba.data(), extent, 4);
        mRing.upload(mColor, layout.color, GL_RGBA, GL_FLOAT);
    }
    if (!frame.depth.empty()) {
        ensure(mDepth, extent, GL_R32F, "cli.input.depth");
        copyRows(slot + layout.depth, frame.depth.data(), extent, 1);
        mRing.upload(mDepth, layout.depth, GL_RED, GL_FLOAT);
        inputs.depth = &mDepth;
        inputs.depthKind = DepthKind::LinearView;
    }
    if (!frame.normals.empty()) {
        ensure(mNormals, extent, GL_RGBA16F, "cli.input.normals");
        writeNormalRows(slot + layout.normals, frame.normals.data(), extent, mHalfRow);
        mRing.upload(mNormals, layout.normals, GL_RGBA, GL_HALF_FLOAT);
        inputs.normals = &mNormals;
        inputs.normalEncoding = NormalEncoding::ViewXyz;
    }
    if (!frame.motion.empty()) {
        ensure(mMotion, extent, GL_RG16F, "cli.input.motion");
        writeHalfRows(slot + layout.motion, frame.motion.data(), extent, 2);
        mRing.upload(mMotion, layout.motion, GL_RG, GL_HALF_FLOAT);
        inputs.motion = &mMotion;
    }
    mRing.end();
    // A layer this frame lacks gives its texture back.
    for (auto [texture, present] :
         {std::pair{&mDepth, !frame.depth.empty()}, std::pair{&mNormals, !frame.normals.empty()},
          std::pair{&mMotion, !frame.motion.empty()}}) {
        if (!present && texture->valid())
            *texture = Texture();
    }
    if (frame.camera) {
        mCamera = *frame.camera;
        inputs.camera = &mCamera;
    }
    inputs.sunDirection = frame.sunDirection;
    return inputs;
}

// ---------------------------------------------------------------------------------------------------------------
// --info and --write-aux

namespace {

std::string channelUse(const std::string& name) {
    if (name == "R" || name == "G" || name == "B" || name == "A" || name == "Y" || name == "RY" ||
        name == "BY")
        return "colour";
    if (name == "Z" || name == "depth.Z")
        return "depth (linear view depth)";
    if (name.starts_with("N.") || name.starts_with("normal."))
        return "normals (world space, turned into view space with the camera)";
    if (name == "motion.X" || name == "motion.Y")
        return "motion (pixels, turned into UV, y up, current minus previous, jitter removed)";
    return "not used";
}

std::string attributeUse(const std::string& name) {
    static const std::vector<std::pair<std::string, std::string>> uses{
        {"worldToCamera", "camera view"},
        {"worldToNDC", "camera projection"},
        {"nearClipPlane", "camera near plane"},
        {"farClipPlane", "camera far plane"},
        {"focus", "lens focus distance"},
        {"aperture", "lens f-number"},
        {"expTime", "lens exposure time"},
        {"isoSpeed", "lens ISO"},
        {"pinholeFocalLength", "lens focal length"},
        {"sensorOverallDimensions", "lens sensor height"},
        {"shutterAngle", "lens shutter angle"},
        {"jitter", "motion unjitter"},
        {"sunDirection", "sun direction (contact shadows, volumetric light)"},
        {"dataWindow", "pixels read"},
        {"displayWindow", "NDC frame of the camera"},
        {"channels", "the channels above"},
        {"compression", "file structure"},
        {"lineOrder", "file structure"},
    };
    for (const auto& [attribute, use] : uses) {
        if (name == attribute)
            return use;
    }
    return "not used";
}

void printInfo(const fs::path& path, const std::optional<CameraJson>& cameraJson) {
    const ExrFrame frame = readExrFrame(path);
    std::printf("%s: %dx%d", path.string().c_str(), frame.color.width, frame.color.height);
    if (frame.displaySize != glm::ivec2(frame.color.width, frame.color.height) ||
        frame.dataOrigin != glm::ivec2(0))
        std::printf(" (data window at %d,%d of a %dx%d display window)", frame.dataOrigin.x,
                    frame.dataOrigin.y, frame.displaySize.x, frame.displaySize.y);
    std::printf("\nchannels:\n");
    for (const auto& name : frame.channels)
        std::printf("  %s -> %s\n", name.c_str(), channelUse(name).c_str());
    std::printf("attributes:\n");
    for (const auto& attribute : frame.attributes) {
        const std::string name = attribute.substr(0, attribute.find(' '));
        std::printf("  %s -> %s\n", attribute.c_str(), attributeUse(name).c_str());
    }
    std::optional<Camera> camera;
    try {
        camera = frameCamera(frame);
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("\"{}\": bad camera attributes: {}", path.string(), e.what()));
    }
    const char* source = camera ? "file attributes" : "--camera";
    if (!camera && cameraJson)
        camera = cameraJson->camera(frame.color.width, frame.color.height);
    if (!camera) {
        std::printf("camera: none (no worldToCamera/worldToNDC; normals will be skipped)\n");
        return;
    }
    std::printf(
        "camera (%s): near %g, far %g, vertical fov %.3g deg, focal length %.4g mm, sensor height %.4g mm, "
        "f/%.3g, focus %g\n",
        source, double(camera->nearPlane), double(camera->farPlane),
        double(glm::degrees(camera->verticalFov)), double(camera->lens.focalLengthMm),
        double(camera->lens.sensorHeightMm), double(camera->lens.fNumber),
        double(camera->lens.focusDistance));
}

} // namespace

int runImageInfo(const std::vector<fs::path>& inputs, const fs::path& cameraJsonPath) {
    const std::optional<CameraJson> cameraJson =
        cameraJsonPath.empty() ? std::nullopt : std::optional<CameraJson>(loadCameraJson(cameraJsonPath));
    for (const auto& path : inputs) {
        if (!isExr(path)) {
            try {
                const ImageF image = readImage(path);
                std::printf("%s: %dx%d, colour only (not an OpenEXR file)\n", path.string().c_str(),
                            image.width, image.height);
            } catch (const IoError& e) {
                throw InputError(e.what());
            }
            continue;
        }
        try {
            printInfo(path, cameraJson);
        } catch (const IoError& e) {
            throw InputError(e.what());
        }
    }
    return kOk;
}

fs::path writeAux(const fs::path& folder, const fs::path& input, const DecodedFrame& frame) {
    ExrFrame aux;
    aux.color = frame.color;
    aux.colorHalves = frame.colorHalves;
    aux.depth = frame.depth;
    aux.normals = frame.normals;
    aux.motion = frame.motion;
    if (frame.camera)
        aux.camera = exrFromCamera(*frame.camera, frame.width(), frame.height());
    const fs::path path = folder / (input.stem().string() + ".aux.exr");
    writeExrFrame(path, aux);
    return path;
}

void readOnlyLayersRead(InputDecoder& decoder, Pipeline& pipeline, const DecodedFrame& first) {
    constexpr Resource kOptional[] = {Resource::Depth, Resource::Normals, Resource::Motion, Resource::Camera,
                                      Resource::SunDirection};
    std::bitset<kResourceCount> read;
    for (unsigned mask = 0; mask < 1u << std::size(kOptional); ++mask) {
        std::bitset<kResourceCount> inputs;
        for (std::size_t i = 0; i < std::size(kOptional); ++i)
            inputs.set(std::size_t(kOptional[i]), (mask >> i & 1u) != 0);
        read |= pipeline.plannedReads(inputs);
    }
    const ExrFrameReader::Layers layers{.depth = read[std::size_t(Resource::Depth)],
                                        .normals = read[std::size_t(Resource::Normals)],
                                        .motion = read[std::size_t(Resource::Motion)]};
    std::string unread;
    for (const auto& [name, had, kept] : {std::tuple{"depth", !first.depth.empty(), layers.depth},
                                          std::tuple{"normals", !first.normals.empty(), layers.normals},
                                          std::tuple{"motion", !first.motion.empty(), layers.motion}}) {
        if (had && !kept)
            unread += std::string(unread.empty() ? "" : ", ") + name;
    }
    if (!unread.empty())
        logDebug("image: no pass reads the input's {}: left out (decoded for the first frame only)", unread);
    decoder.readLayers(layers);
}

} // namespace photopic::cli
