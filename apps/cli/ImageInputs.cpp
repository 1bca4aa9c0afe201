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

} // namespace

bool isExr(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[4] = {};
    in.read(reinterpret_cast<char*>(magic), 4);
    return in.gcount() == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

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
    if (!isExr(path)) {
        return decodeColorOnly(path);
    }
    readExr(path);
    ExrFrame& frame = mFrame;
    DecodedFrame out;
    const std::optional<glm::vec3> trackSun = takeCamera(path, out);
    takeDepthAndNormals(path, out);
    const std::optional<glm::vec2> jitter = frameJitter();
    out.jittered = jitter.has_value();
    out.sunDirection = sunDirection(path, trackSun);
    if (!frame.motion.empty()) {
        out.motion = std::move(frame.motion);
        const glm::vec2 unjitter =
            frame.aovs.conventions.motionJittered
                ? mPreviousJitter.value_or(glm::vec2(0.0f)) - jitter.value_or(glm::vec2(0.0f))
                : glm::vec2(0.0f);
        uvMotion(out.motion, frame.width(), frame.height(), unjitter);
    }
    out.color = std::move(frame.color);
    out.colorHalves = std::move(frame.colorHalves);
    mPrevious = frame.camera;
    mPreviousJitter = jitter;
    ++mIndex;
    mFirst = false;
    return out;
}

DecodedFrame InputDecoder::decodeColorOnly(const fs::path& path) {
    DecodedFrame out;
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

void InputDecoder::readExr(const fs::path& path) {
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
}

std::optional<glm::vec3> InputDecoder::takeCamera(const fs::path& path, DecodedFrame& out) {
    try {
        out.camera = frameCamera(mFrame, mPrevious ? &*mPrevious : nullptr);
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("\"{}\": bad camera attributes: {}", path.string(), e.what()));
    }
    std::optional<glm::vec3> trackSun;
    if (!out.camera)
        out.camera = trackCamera(path, mFrame.width(), mFrame.height(), trackSun);
    else
        mPreviousTrackViewProjection.reset();
    if (out.camera) {
        out.camera->cut = mFirst;
        applyLens(*out.camera);
    }
    return trackSun;
}

void InputDecoder::takeDepthAndNormals(const fs::path& path, DecodedFrame& out) {
    ExrFrame& frame = mFrame;
    const AovConventions& conventions = frame.aovs.conventions;
    out.depth = std::move(frame.depth);
    if (!out.depth.empty() && conventions.depth == AovConventions::Depth::Radial) {
        if (out.camera) {
            planarDepth(out.depth, frame.width(), frame.height(), *out.camera);
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
}

std::optional<glm::vec2> InputDecoder::frameJitter() const {
    // The file's jitter attribute, else the sample offset of the Halton jitter Photopic would have handed
    // out: moving the image by j (x right, y up) samples it at the pixel centre - j, which in the file's
    // y-down convention is (-j.x, j.y).
    std::optional<glm::vec2> jitter = mFrame.camera.jitter;
    if (!jitter && mHaltonCycle > 0) {
        const glm::vec2 halton = haltonJitter(mIndex, mHaltonCycle);
        jitter = glm::vec2(-halton.x, halton.y);
    }
    return jitter;
}

std::optional<glm::vec3> InputDecoder::sunDirection(const fs::path& path,
                                                    std::optional<glm::vec3> trackSun) const {
    const std::optional<glm::vec3> sun = mFrame.camera.sunDirection;
    if (!sun) {
        return trackSun;
    }
    if (!std::isfinite(sun->x) || !std::isfinite(sun->y) || !std::isfinite(sun->z) ||
        glm::dot(*sun, *sun) <= 0.0f)
        throw InputError(fmt::format("\"{}\": attribute sunDirection ({}, {}, {}) is not a finite, non-zero "
                                     "direction",
                                     path.string(), sun->x, sun->y, sun->z));
    return sun;
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
// --aov, --write-aux and the layers read

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
