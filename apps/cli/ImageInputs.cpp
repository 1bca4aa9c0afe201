#include "ImageInputs.h"

#include "Commands.h"
#include "InputSequence.h"

#include "core/HalfFloat.h"
#include "core/Log.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"

#include <fmt/format.h>

#include <algorithm>
#include <bitset>
#include <charconv>
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

/// Camera-space normals made unit length in place; zero or non-finite normals (no surface) become zero.
void unitNormals(std::vector<float>& normals) {
    viewSpaceNormals(normals, glm::mat4(1.0f));
}

/// Radial depth (distance from the camera's centre) -> planar (along the view axis), in place: each pixel
/// centre's view ray d, scaled to unit depth, is |d| times longer than its depth.
void planarDepth(std::vector<float>& depth, int width, int height, const Camera& camera) {
    const glm::mat4 inverse = glm::inverse(camera.projection);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec4 ndc(2.0f * (float(x) + 0.5f) / float(width) - 1.0f,
                                1.0f - 2.0f * (float(y) + 0.5f) / float(height), 0.5f, 1.0f);
            const glm::vec4 p = inverse * ndc;
            const glm::vec3 ray = glm::vec3(p) / -p.z; // p.w cancels out: only the direction counts
            depth[std::size_t(y) * std::size_t(width) + std::size_t(x)] /= glm::length(ray);
        }
    }
}

/// Gives back the storage of the layers `layers` leaves out.
void freeUnreadLayers(ExrFrameReader::Layers layers, std::vector<float>& depth, std::vector<float>& normals,
                      std::vector<float>& motion, std::vector<float>& objectId) {
    for (auto [layer, read] : {std::pair{&depth, layers.depth}, std::pair{&normals, layers.normals},
                               std::pair{&motion, layers.motion}, std::pair{&objectId, layers.objectId}}) {
        if (!read)
            *layer = std::vector<float>();
    }
}

/// Pixels (x right, y down, current minus previous) -> UV (y up), in place. Motion measured between the
/// frames' jittered samples (`unjitter` = previous jitter - current jitter, else zero) has the jitter taken
/// out: a jittered sample of the current frame sits at p + j_current, of the previous frame at
/// p' + j_previous, so the surface's own motion is m - j_current + j_previous.
void uvMotion(std::vector<float>& motion, int width, int height, glm::vec2 unjitter) {
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

LensOverride parseLensOverride(const std::string& text) {
    LensOverride lens;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        const std::size_t equals = item.find('=');
        const std::string key = item.substr(0, equals);
        float value = 0.0f;
        const char* first = item.data() + (equals == std::string::npos ? item.size() : equals + 1);
        const char* last = item.data() + item.size();
        const auto [ptr, ec] = std::from_chars(first, last, value);
        if (equals == std::string::npos || ec != std::errc() || ptr != last || !std::isfinite(value))
            throw InputError(fmt::format(
                "--lens {}: \"{}\" is not KEY=NUMBER (keys: fNumber, focus, shutter)", text, item));
        const auto range = [&](float lo, float hi, const char* unit) {
            if (!(value >= lo && value <= hi) || (key == "focus" && !(value > 0.0f)))
                throw InputError(fmt::format("--lens {}: {} = {} is outside {}", text, key, value, unit));
            return value;
        };
        if (key == "fNumber")
            lens.fNumber = range(0.5f, 256.0f, "[0.5, 256]");
        else if (key == "focus")
            lens.focusDistance = range(0.0f, 3.0e38f, "(0, inf) scene units");
        else if (key == "shutter")
            lens.shutterAngleDeg = range(0.0f, 360.0f, "[0, 360] degrees");
        else
            throw InputError(
                fmt::format("--lens {}: unknown key \"{}\" (keys: fNumber, focus, shutter)", text, key));
        start = end + 1;
    }
    return lens;
}

InputDecoder::InputDecoder(std::optional<CameraTrack> cameras, int haltonCycle, std::int64_t maxPixels)
    : mCameras(std::move(cameras))
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
        out.camera = trackCamera(path, out.color.width, out.color.height, out.sunDirection);
        if (out.camera) {
            out.camera->cut = mFirst;
            applyLens(*out.camera);
        }
        mPrevious.reset();
        mFirst = false;
        return out;
    }
    ExrFrame& frame = mFrame; // storage kept from the frame before (recycle())
    const ExrFrameReader::Layers layers = layersRead();
    mReader.setLayers(layers);
    // Storage kept for a layer no longer read (the frames decoded before readLayers() had it) goes back.
    freeUnreadLayers(layers, frame.depth, frame.normals, frame.motion, frame.objectId);
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
    std::optional<glm::vec3> trackSun;
    if (!out.camera)
        out.camera = trackCamera(path, width, height, trackSun);
    else
        mPreviousTrackViewProjection.reset();
    if (out.camera) {
        out.camera->cut = mFirst;
        applyLens(*out.camera);
    }

    const AovConventions& conventions = frame.aovs.conventions;
    out.depth = std::move(frame.depth);
    if (!out.depth.empty() && conventions.depth == AovConventions::Depth::Radial) {
        if (out.camera) {
            planarDepth(out.depth, width, height, *out.camera);
        } else {
            warnOnce(
                "cli.radialDepthWithoutCamera",
                fmt::format("{}: depth skipped: turning radial depth planar needs a camera (worldToCamera/"
                            "worldToNDC attributes or --camera)",
                            path.string()));
            out.depth.clear();
        }
    }
    out.objectId = std::move(frame.objectId);
    if (!frame.normals.empty() && conventions.normals == AovConventions::Normals::Camera) {
        out.normals = std::move(frame.normals);
        unitNormals(out.normals);
    } else if (!frame.normals.empty()) {
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
    } else {
        out.sunDirection = trackSun;
    }
    if (!frame.motion.empty()) {
        out.motion = std::move(frame.motion);
        const glm::vec2 unjitter = conventions.motionJittered ? mPreviousJitter.value_or(glm::vec2(0.0f)) -
                                                                    jitter.value_or(glm::vec2(0.0f))
                                                              : glm::vec2(0.0f);
        uvMotion(out.motion, width, height, unjitter);
    }
    out.color = std::move(frame.color);
    out.colorHalves = std::move(frame.colorHalves);
    mPrevious = frame.camera;
    mPreviousJitter = jitter;
    ++mIndex;
    mFirst = false;
    return out;
}

void InputDecoder::applyLens(Camera& camera) const {
    if (mLens.fNumber)
        camera.lens.fNumber = *mLens.fNumber;
    if (mLens.focusDistance)
        camera.lens.focusDistance = *mLens.focusDistance;
    if (mLens.shutterAngleDeg)
        camera.lens.shutterAngleDeg = *mLens.shutterAngleDeg;
}

std::optional<Camera> InputDecoder::trackCamera(const fs::path& path, int width, int height,
                                                std::optional<glm::vec3>& sun) {
    if (!mCameras) {
        mPreviousTrackViewProjection.reset();
        return std::nullopt;
    }
    const CameraJson& json = mCameras->at(frameNumberOf(mFrameNumbers, path), path);
    Camera camera = json.camera(width, height);
    if (mPreviousTrackViewProjection)
        camera.prevViewProjection = *mPreviousTrackViewProjection;
    mPreviousTrackViewProjection = camera.viewProjection();
    sun = json.sunDirection;
    return camera;
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
    freeUnreadLayers(layersRead(), frame.depth, frame.normals, frame.motion, frame.objectId);
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
    if (frame.objectId.capacity() > mFrame.objectId.capacity())
        mFrame.objectId = std::move(frame.objectId);
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
    std::size_t objectId = 0;
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
    if (!frame.objectId.empty())
        place(layout.objectId, sizeof(std::uint32_t));
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

/// Object ids stored as floats (Cycles' IndexOB) as unsigned integers, rounded; negative or non-finite: 0.
void writeIdRows(std::byte* out, const float* ids, Extent extent) {
    const std::size_t width = std::size_t(extent.width);
    for (int y = 0; y < extent.height; ++y) {
        const float* row = ids + std::size_t(extent.height - 1 - y) * width;
        for (std::size_t x = 0; x < width; ++x) {
            const float id = row[x];
            const std::uint32_t value =
                id >= 0.5f && id < 4.0e9f ? std::uint32_t(std::lround(double(id))) : 0u;
            std::memcpy(out + (std::size_t(y) * width + x) * sizeof(value), &value, sizeof(value));
        }
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
    if (!frame.objectId.empty()) {
        ensure(mObjectId, extent, GL_R32UI, "cli.input.objectId");
        writeIdRows(slot + layout.objectId, frame.objectId.data(), extent);
        mRing.upload(mObjectId, layout.objectId, GL_RED_INTEGER, GL_UNSIGNED_INT);
        inputs.objectId = &mObjectId;
    }
    mRing.end();
    // A layer this frame lacks gives its texture back.
    for (auto [texture, present] :
         {std::pair{&mDepth, !frame.depth.empty()}, std::pair{&mNormals, !frame.normals.empty()},
          std::pair{&mMotion, !frame.motion.empty()}, std::pair{&mObjectId, !frame.objectId.empty()}}) {
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

std::string motionUse(const AovConventions& c) {
    using C = AovConventions;
    const char* units = c.motionUnits == C::MotionUnits::Pixels ? "pixels"
                        : c.motionUnits == C::MotionUnits::Ndc  ? "NDC units"
                                                                : "UV units";
    const char* sense = c.motionSense == C::MotionSense::CurrentMinusPrevious   ? "current minus previous"
                        : c.motionSense == C::MotionSense::PreviousMinusCurrent ? "previous minus current"
                        : c.motionSense == C::MotionSense::NextMinusCurrent
                            ? "next minus current, read as constant velocity"
                            : "current minus next, read as constant velocity";
    return fmt::format("motion ({}, {}, y {}, {}; turned into UV, y up, current minus previous{})", units,
                       sense, c.motionYUp ? "up" : "down",
                       c.motionJittered ? "between jittered samples" : "unjittered",
                       c.motionJittered ? ", jitter removed" : "");
}

/// What `name` feeds under `aovs`, in words.
std::string channelUse(const std::string& name, const AovChannels& aovs) {
    const std::optional<Aov> aov = aovs.feeds(name);
    if (!aov) {
        if (name == "RY" || name == "BY")
            return aovs.has(Aov::Color) && aovs.of(Aov::Color)[0] == "Y" ? "colour (chroma)" : "not used";
        const std::vector<std::string>& other = aovs.otherMotionPair;
        if (std::find(other.begin(), other.end(), name) != other.end())
            return "not used (motion's other pair: --aov motion=:pair=" +
                   std::string(aovs.conventions.motionPair == 2 ? "1" : "2") + " reads it)";
        return "not used";
    }
    const AovConventions& c = aovs.conventions;
    switch (*aov) {
    case Aov::Color:
        return "colour";
    case Aov::Depth:
        return c.depth == AovConventions::Depth::Planar
                   ? "depth (linear view depth, planar)"
                   : "depth (linear view depth, radial: made planar with the camera)";
    case Aov::Normals:
        return c.normals == AovConventions::Normals::Camera ? "normals (camera space)"
               : c.normals == AovConventions::Normals::WorldZUp
                   ? "normals (world space, Z up: turned Y up, then into view space with the camera)"
                   : "normals (world space, turned into view space with the camera)";
    case Aov::Motion:
        return motionUse(c);
    case Aov::Ao:
        return "ambient occlusion: not read (Photopic computes its own; --debug ao writes it)";
    case Aov::ObjectId:
        return "object ids (contactShadows.mask)";
    }
    return "not used";
}

std::string attributeUse(const std::string& name) {
    static const std::vector<std::pair<std::string, std::string>> uses{
        {"BlenderMultiChannel", "the blender preset, unless --aovs says otherwise"},
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
        {"jitter", "sample jitter (TAA; the motion unjitter with --aov motion=:jittered)"},
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

void printInfo(const fs::path& path, const std::optional<CameraTrack>& cameras,
               std::optional<std::int64_t> number, const AovRequest& request) {
    const ExrFrame frame = readExrFrame(path, {}, request);
    std::printf("%s: %dx%d", path.string().c_str(), frame.color.width, frame.color.height);
    if (frame.displaySize != glm::ivec2(frame.color.width, frame.color.height) ||
        frame.dataOrigin != glm::ivec2(0))
        std::printf(" (data window at %d,%d of a %dx%d display window)", frame.dataOrigin.x,
                    frame.dataOrigin.y, frame.displaySize.x, frame.displaySize.y);
    const AovChannels& aovs = frame.aovs;
    std::string layers;
    for (const std::string& layer : aovLayers(frame.channels, aovs.preset))
        layers += (layers.empty() ? "" : ", ") + (layer.empty() ? std::string("(unprefixed)") : layer);
    std::printf("\nchannels: the %s preset%s, layer %s (layers: %s)\n", aovPresetName(aovs.preset),
                request.preset ? " (--aovs)" : " (the file's)",
                aovs.layer.empty() ? "(unprefixed)" : aovs.layer.c_str(),
                layers.empty() ? "none" : layers.c_str());
    if (!frame.parts.empty()) {
        std::string parts;
        for (const std::string& part : frame.parts)
            parts += (parts.empty() ? "" : ", ") + part;
        std::printf("parts: %zu (%s); another part's channels are named PART.CHANNEL\n", frame.parts.size(),
                    parts.c_str());
    }
    std::vector<std::string> unused;
    for (const auto& name : frame.channels) {
        const std::string use = channelUse(name, aovs);
        std::printf("  %s -> %s\n", name.c_str(), use.c_str());
        if (use.starts_with("not used"))
            unused.push_back(name);
    }
    std::string unusedList;
    for (const std::string& name : unused)
        unusedList += (unusedList.empty() ? "" : ", ") + name;
    std::printf("unused channels: %s\n", unused.empty() ? "none" : unusedList.c_str());
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
    if (!camera && cameras)
        camera = cameras->at(number, path).camera(frame.color.width, frame.color.height);
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

AovRequest aovRequest(const std::string& preset, const std::string& layer,
                      const std::vector<std::string>& overrides) {
    AovRequest request;
    try {
        if (!preset.empty())
            request.preset = parseAovPreset(preset);
        request.layer = layer;
        for (const std::string& text : overrides)
            request.overrides.push_back(parseAovOverride(text));
    } catch (const AovError& e) {
        throw InputError(e.what());
    }
    return request;
}

int runImageInfo(const std::vector<fs::path>& inputs, const fs::path& cameraJsonPath, const AovRequest& aovs,
                 const std::map<fs::path, std::int64_t>& numbers) {
    const std::optional<CameraTrack> cameras =
        cameraJsonPath.empty() ? std::nullopt : std::optional<CameraTrack>(loadCameraTrack(cameraJsonPath));
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
            printInfo(path, cameras, frameNumberOf(numbers, path), aovs);
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
    constexpr Resource kOptional[] = {Resource::Depth,  Resource::Normals,      Resource::Motion,
                                      Resource::Camera, Resource::SunDirection, Resource::ObjectId};
    std::bitset<kResourceCount> read;
    for (unsigned mask = 0; mask < 1u << std::size(kOptional); ++mask) {
        std::bitset<kResourceCount> inputs;
        for (std::size_t i = 0; i < std::size(kOptional); ++i)
            inputs.set(std::size_t(kOptional[i]), (mask >> i & 1u) != 0);
        read |= pipeline.plannedReads(inputs);
    }
    const ExrFrameReader::Layers layers{.depth = read[std::size_t(Resource::Depth)],
                                        .normals = read[std::size_t(Resource::Normals)],
                                        .motion = read[std::size_t(Resource::Motion)],
                                        .objectId = read[std::size_t(Resource::ObjectId)]};
    std::string unread;
    for (const auto& [name, had, kept] :
         {std::tuple{"depth", !first.depth.empty(), layers.depth},
          std::tuple{"normals", !first.normals.empty(), layers.normals},
          std::tuple{"motion", !first.motion.empty(), layers.motion},
          std::tuple{"object ids", !first.objectId.empty(), layers.objectId}}) {
        if (had && !kept)
            unread += std::string(unread.empty() ? "" : ", ") + name;
    }
    if (!unread.empty())
        logDebug("image: no pass reads the input's {}: left out (decoded for the first frame only)", unread);
    decoder.readLayers(layers);
}

} // namespace photopic::cli
