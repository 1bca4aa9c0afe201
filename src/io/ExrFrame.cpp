#include "io/ExrFrame.h"

#include "io/ExrDetail.h"
#include "io/ImageIO.h"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfHeader.h>
#include <ImfInputPart.h>
#include <ImfMatrixAttribute.h>
#include <ImfMultiPartInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfVecAttribute.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>

namespace photopic {

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Layers

/// Adds each of the layer's channels as a FLOAT slice interleaved into `values` (resized to hold them).
void addLayerSlices(Imf::FrameBuffer& frameBuffer, const std::vector<std::string>& names,
                    std::vector<float>& values, const Imath::Box2i& dataWindow, int width, int height) {
    const std::size_t count = names.size();
    values.assign(std::size_t(width) * std::size_t(height) * count, 0.0f);
    const std::size_t xStride = count * sizeof(float);
    for (std::size_t c = 0; c < count; ++c) {
        frameBuffer.insert(names[c], Imf::Slice::Make(Imf::FLOAT, values.data() + c, dataWindow, xStride,
                                                      xStride * std::size_t(width)));
    }
}

/// Motion as the mapping stores it -> pixels, current minus previous, x right, y down, in place.
/// `size`: the display window's, which NDC and UV units span.
void canonicalMotion(std::vector<float>& motion, const AovConventions& c, glm::ivec2 size) {
    using C = AovConventions;
    glm::vec2 scale(1.0f);
    if (c.motionUnits == C::MotionUnits::Ndc)
        scale = 0.5f * glm::vec2(size);
    else if (c.motionUnits == C::MotionUnits::Uv)
        scale = glm::vec2(size);
    // The way to the previous position is the negated displacement; the way to the next one stands for it
    // at constant velocity, and the way back from there for its negation.
    if (c.motionSense == C::MotionSense::PreviousMinusCurrent ||
        c.motionSense == C::MotionSense::CurrentMinusNext)
        scale = -scale;
    if (c.motionYUp)
        scale.y = -scale.y;
    if (scale == glm::vec2(1.0f))
        return;
    for (std::size_t i = 0; i + 1 < motion.size(); i += 2) {
        motion[i] *= scale.x;
        motion[i + 1] *= scale.y;
    }
}

/// Z-up world normals -> Y-up: (x, y, z) -> (x, z, -y), in place.
void yUpNormals(std::vector<float>& normals) {
    for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
        const float y = normals[i + 1];
        normals[i + 1] = normals[i + 2];
        normals[i + 2] = -y;
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Attributes

std::string wrongType(const std::string& name, const Imf::Attribute& attribute, const char* expected) {
    return "attribute " + name + " is of type " + attribute.typeName() + ", expected " + expected;
}

const Imf::Attribute* findAttribute(const Imf::Header& header, const std::string& name) {
    const auto it = header.find(name);
    return it == header.end() ? nullptr : &it.attribute();
}

std::optional<float> floatAttribute(const fs::path& path, const Imf::Header& header,
                                    const std::string& name) {
    const Imf::Attribute* attribute = findAttribute(header, name);
    if (attribute == nullptr)
        return std::nullopt;
    if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(attribute))
        return f->value();
    if (const auto* d = dynamic_cast<const Imf::DoubleAttribute*>(attribute))
        return float(d->value());
    throw IoError(path, wrongType(name, *attribute, "float"));
}

std::optional<glm::vec2> vec2Attribute(const fs::path& path, const Imf::Header& header,
                                       const std::string& name) {
    const Imf::Attribute* attribute = findAttribute(header, name);
    if (attribute == nullptr)
        return std::nullopt;
    if (const auto* f = dynamic_cast<const Imf::V2fAttribute*>(attribute))
        return glm::vec2(f->value().x, f->value().y);
    if (const auto* d = dynamic_cast<const Imf::V2dAttribute*>(attribute))
        return glm::vec2(float(d->value().x), float(d->value().y));
    throw IoError(path, wrongType(name, *attribute, "v2f"));
}

std::optional<glm::vec3> vec3Attribute(const fs::path& path, const Imf::Header& header,
                                       const std::string& name) {
    const Imf::Attribute* attribute = findAttribute(header, name);
    if (attribute == nullptr)
        return std::nullopt;
    if (const auto* f = dynamic_cast<const Imf::V3fAttribute*>(attribute))
        return glm::vec3(f->value().x, f->value().y, f->value().z);
    if (const auto* d = dynamic_cast<const Imf::V3dAttribute*>(attribute))
        return glm::vec3(float(d->value().x), float(d->value().y), float(d->value().z));
    throw IoError(path, wrongType(name, *attribute, "v3f"));
}

std::optional<glm::mat4> matrixAttribute(const fs::path& path, const Imf::Header& header,
                                         const std::string& name) {
    const Imf::Attribute* attribute = findAttribute(header, name);
    if (attribute == nullptr)
        return std::nullopt;
    glm::mat4 m(0.0f);
    if (const auto* f = dynamic_cast<const Imf::M44fAttribute*>(attribute)) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                m[i][j] = f->value()[i][j];
        return m;
    }
    if (const auto* d = dynamic_cast<const Imf::M44dAttribute*>(attribute)) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                m[i][j] = float(d->value()[i][j]);
        return m;
    }
    throw IoError(path, wrongType(name, *attribute, "m44f"));
}

ExrCameraAttributes readCameraAttributes(const fs::path& path, const Imf::Header& header) {
    ExrCameraAttributes a;
    a.worldToCamera = matrixAttribute(path, header, "worldToCamera");
    a.worldToNDC = matrixAttribute(path, header, "worldToNDC");
    a.focus = floatAttribute(path, header, "focus");
    a.aperture = floatAttribute(path, header, "aperture");
    a.expTime = floatAttribute(path, header, "expTime");
    a.isoSpeed = floatAttribute(path, header, "isoSpeed");
    a.pinholeFocalLength = floatAttribute(path, header, "pinholeFocalLength");
    a.sensorOverallDimensions = vec2Attribute(path, header, "sensorOverallDimensions");
    a.shutterAngle = floatAttribute(path, header, "shutterAngle");
    a.jitter = vec2Attribute(path, header, "jitter");
    // The motion unjitter adds it to every motion vector: a non-finite one would leave none finite.
    if (a.jitter && !(std::isfinite(a.jitter->x) && std::isfinite(a.jitter->y)))
        throw IoError(path, "attribute jitter (" + std::to_string(a.jitter->x) + ", " +
                                std::to_string(a.jitter->y) + ") is not finite");
    a.nearClip = floatAttribute(path, header, "nearClipPlane");
    a.farClip = floatAttribute(path, header, "farClipPlane");
    a.sunDirection = vec3Attribute(path, header, "sunDirection");
    return a;
}

void writeCameraAttributes(Imf::Header& header, const ExrCameraAttributes& a) {
    const auto matrix = [&](const char* name, const std::optional<glm::mat4>& m) {
        if (!m)
            return;
        Imath::M44f imath;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                imath[i][j] = (*m)[i][j];
        header.insert(name, Imf::M44fAttribute(imath));
    };
    const auto scalar = [&](const char* name, const std::optional<float>& v) {
        if (v)
            header.insert(name, Imf::FloatAttribute(*v));
    };
    const auto vec2 = [&](const char* name, const std::optional<glm::vec2>& v) {
        if (v)
            header.insert(name, Imf::V2fAttribute(Imath::V2f(v->x, v->y)));
    };
    matrix("worldToCamera", a.worldToCamera);
    matrix("worldToNDC", a.worldToNDC);
    scalar("focus", a.focus);
    scalar("aperture", a.aperture);
    scalar("expTime", a.expTime);
    scalar("isoSpeed", a.isoSpeed);
    scalar("pinholeFocalLength", a.pinholeFocalLength);
    vec2("sensorOverallDimensions", a.sensorOverallDimensions);
    scalar("shutterAngle", a.shutterAngle);
    vec2("jitter", a.jitter);
    scalar("nearClipPlane", a.nearClip);
    scalar("farClipPlane", a.farClip);
    if (a.sunDirection)
        header.insert("sunDirection",
                      Imf::V3fAttribute(Imath::V3f(a.sunDirection->x, a.sunDirection->y, a.sunDirection->z)));
}

// ---------------------------------------------------------------------------------------------------------------
// Camera conventions

/// OpenEXR's left-handed camera space (+z forward) <-> GL's right-handed view space (-z forward).
const glm::mat4 kFlipZ =
    glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 0, 1));
constexpr float kFallbackNear = 0.1f;

glm::vec4 row(const glm::mat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}
void setRow(glm::mat4& m, int r, const glm::vec4& v) {
    for (int c = 0; c < 4; ++c)
        m[c][r] = v[c];
}

struct GlCamera {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float nearPlane = kFallbackNear;
    float farPlane = std::numeric_limits<float>::infinity();
    float verticalFov = 1.0f;
};

/// near/far from the clip attributes, else from K's z row read as RenderMan's NDC depth z_ndc = a + b / z
/// (z = camera depth = K's w after normalisation): n = -b / a, f = b / (1 - a), a = 1 for an infinite far.
void nearFar(const ExrCameraAttributes& a, const glm::vec4& zRow, GlCamera& camera) {
    if (a.nearClip && a.farClip) {
        camera.nearPlane = *a.nearClip;
        camera.farPlane = *a.farClip;
        return;
    }
    const float scale = std::max(std::abs(zRow.z), std::abs(zRow.w));
    const bool depthOnly =
        scale > 0.0f && std::abs(zRow.x) <= 1e-6f * scale && std::abs(zRow.y) <= 1e-6f * scale;
    if (depthOnly) {
        // In GL view space the camera depth is -z, so the row is (0, 0, -a, b).
        const double aa = -double(zRow.z);
        const double bb = double(zRow.w);
        const double n = aa != 0.0 ? -bb / aa : 0.0;
        const double f =
            std::abs(1.0 - aa) < 1e-6 ? std::numeric_limits<double>::infinity() : bb / (1.0 - aa);
        if (std::isfinite(n) && n > 0.0 && f > n) {
            camera.nearPlane = float(n);
            camera.farPlane = float(f);
        }
    }
    if (a.nearClip)
        camera.nearPlane = *a.nearClip;
    if (a.farClip)
        camera.farPlane = *a.farClip;
}

GlCamera glCamera(const ExrCameraAttributes& a) {
    const glm::mat4& worldToCamera = *a.worldToCamera;
    const glm::mat4& worldToNdc = *a.worldToNDC;
    if (!allFinite(worldToCamera))
        throw std::invalid_argument("worldToCamera has a non-finite entry");
    if (!allFinite(worldToNdc))
        throw std::invalid_argument("worldToNDC has a non-finite entry");
    const float det = glm::determinant(worldToCamera);
    if (!std::isfinite(det) || std::abs(det) < 1e-12f)
        throw std::invalid_argument("worldToCamera is not invertible");

    GlCamera camera;
    camera.view = kFlipZ * worldToCamera;
    // GL view space -> OpenEXR NDC (homogeneous).
    glm::mat4 k = worldToNdc * glm::inverse(worldToCamera) * kFlipZ;
    const glm::vec4 w = row(k, 3);
    const float wScale = std::max({std::abs(w.x), std::abs(w.y), std::abs(w.z), std::abs(w.w)});
    if (!(w.z < 0.0f) || std::abs(w.x) > 1e-5f * wScale || std::abs(w.y) > 1e-5f * wScale ||
        std::abs(w.w) > 1e-5f * wScale)
        throw std::invalid_argument(
            "worldToNDC is not a perspective projection of worldToCamera's camera space (its w must be "
            "proportional to camera depth)");
    k *= -1.0f / w.z; // w = -z_view, as GL's perspective projections have it
    nearFar(a, row(k, 2), camera);

    const float n = camera.nearPlane;
    const float f = camera.farPlane;
    if (!(std::isfinite(n) && n > 0.0f) || std::isnan(f) || !(f > n))
        throw std::invalid_argument(
            "near/far clip planes must satisfy 0 < near < far (nearClipPlane, farClipPlane)");
    glm::mat4 p(0.0f);
    setRow(p, 0, 2.0f * row(k, 0) - row(k, 3));
    setRow(p, 1, row(k, 3) - 2.0f * row(k, 1));
    setRow(p, 2,
           std::isinf(f) ? glm::vec4(0, 0, -1, -2.0f * n)
                         : glm::vec4(0, 0, -(f + n) / (f - n), -2.0f * f * n / (f - n)));
    setRow(p, 3, glm::vec4(0, 0, -1, 0));
    camera.projection = p;
    if (!(p[1][1] > 0.0f) || !(p[0][0] > 0.0f))
        throw std::invalid_argument("worldToNDC flips the image or is degenerate (x must map right, y down)");
    camera.verticalFov = 2.0f * std::atan(1.0f / p[1][1]);
    return camera;
}

void requireRange(const char* name, float value, float lo, float hi) {
    if (!(value >= lo && value <= hi))
        throw std::invalid_argument("attribute " + std::string(name) + " = " + std::to_string(value) +
                                    " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

Lens lensFromExr(const ExrCameraAttributes& a, float verticalFov) {
    Lens lens;
    const float tanHalf = std::tan(0.5f * verticalFov);
    const std::optional<float> sensorHeight =
        a.sensorOverallDimensions ? std::optional<float>(a.sensorOverallDimensions->y) : std::nullopt;
    if (a.pinholeFocalLength)
        requireRange("pinholeFocalLength", *a.pinholeFocalLength, 1e-3f, 10000.0f);
    if (sensorHeight)
        requireRange("sensorOverallDimensions.y", *sensorHeight, 1e-3f, 1000.0f);
    if (a.pinholeFocalLength && sensorHeight) {
        lens.focalLengthMm = *a.pinholeFocalLength;
        lens.sensorHeightMm = *sensorHeight;
    } else if (a.pinholeFocalLength) {
        lens.focalLengthMm = *a.pinholeFocalLength;
        lens.sensorHeightMm = 2.0f * lens.focalLengthMm * tanHalf;
    } else {
        lens.sensorHeightMm = sensorHeight.value_or(lens.sensorHeightMm);
        lens.focalLengthMm = lens.sensorHeightMm / (2.0f * tanHalf);
    }
    if (a.aperture) {
        requireRange("aperture", *a.aperture, 0.5f, 256.0f);
        lens.fNumber = *a.aperture;
    }
    if (a.focus) {
        if (!(std::isfinite(*a.focus) && *a.focus > 0.0f))
            throw std::invalid_argument("attribute focus must be finite and > 0");
        lens.focusDistance = *a.focus;
    }
    if (a.shutterAngle) {
        requireRange("shutterAngle", *a.shutterAngle, 0.0f, 360.0f);
        lens.shutterAngleDeg = *a.shutterAngle;
    }
    if (a.expTime) {
        requireRange("expTime", *a.expTime, 0.0f, 60.0f);
        lens.exposureTimeS = *a.expTime;
    }
    if (a.isoSpeed) {
        requireRange("isoSpeed", *a.isoSpeed, 1.0f, 1e6f);
        lens.iso = *a.isoSpeed;
    }
    return lens;
}

// ---------------------------------------------------------------------------------------------------------------
// Reading

/// `image` (ImageF or ImageH) made empty, its storage's capacity kept.
template <class Image>
void emptyKeepingStorage(Image& image) {
    image.width = 0;
    image.height = 0;
    image.rgba.clear();
}

/// The header's attributes as "name (type)", its display window's size and the data window's origin in it.
void describeHeader(const Imf::Header& header, ExrFrame& frame) {
    frame.attributes.clear();
    for (auto it = header.begin(); it != header.end(); ++it)
        frame.attributes.push_back(std::string(it.name()) + " (" + it.attribute().typeName() + ")");
    const Imath::Box2i display = header.displayWindow();
    const Imath::Box2i data = header.dataWindow();
    frame.displaySize = {display.max.x - display.min.x + 1, display.max.y - display.min.y + 1};
    frame.dataOrigin = {data.min.x - display.min.x, data.min.y - display.min.y};
}

/// The mapping of a file with these channels, its first header saying whether Blender wrote it; a mapping
/// that does not fit is an IoError naming the file.
AovChannels resolveFrameAovs(const fs::path& path, const std::vector<std::string>& channels,
                             const Imf::Header& header, const AovRequest& request) {
    try {
        return resolveAovs(channels, findAttribute(header, "BlenderMultiChannel") != nullptr, request);
    } catch (const AovError& e) {
        throw IoError(path, e.what());
    }
}

/// Each 3D layer of `frame`, the kind of channels that fill it and whether it is read.
std::array<std::tuple<Aov, std::vector<float>*, bool>, 4> layerTargets(ExrFrame& frame,
                                                                       ExrFrameReader::Layers wanted) {
    return {std::tuple{Aov::Depth, &frame.depth, wanted.depth},
            std::tuple{Aov::Normals, &frame.normals, wanted.normals},
            std::tuple{Aov::Motion, &frame.motion, wanted.motion},
            std::tuple{Aov::ObjectId, &frame.objectId, wanted.objectId}};
}

/// The 3D layers emptied (a layer this file lacks is empty, whatever an earlier frame read into the same
/// storage), their capacity kept.
void clearLayers(ExrFrame& frame) {
    for (const auto& [aov, values, read] : layerTargets(frame, {}))
        values->clear();
}

/// The conventions the reader applies once the pixels are read: motion into pixels, current minus previous,
/// y down; Z-up normals turned Y up.
void applyReaderConventions(ExrFrame& frame) {
    canonicalMotion(frame.motion, frame.aovs.conventions, frame.displaySize);
    if (frame.aovs.conventions.normals == AovConventions::Normals::WorldZUp)
        yUpNormals(frame.normals);
}

/// A channel of a multi-part file: the part that holds it and its name there.
struct PartChannel {
    int part = 0;
    std::string name;
};

/// The frame in a multi-part file's parts, already checked by detail::checkExrBytes, into `frame`: every
/// channel the mapping names read from its part (each such part's data window the colour's), colour as
/// floats.
void readMultipartFrame(const fs::path& path, std::span<const unsigned char> bytes,
                        Imf::MultiPartInputFile& file, ExrFrame& frame, ExrFrameReader::Layers wanted,
                        const AovRequest& request) {
    std::map<std::string, PartChannel> where;
    frame.channels.clear();
    frame.parts.clear();
    for (int k = 0; k < file.parts(); ++k) {
        const Imf::Header& header = file.header(k);
        const std::string part = header.hasName() ? header.name() : "";
        frame.parts.push_back(part.empty() ? "(part " + std::to_string(k) + ")" : part);
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            const std::string name = it.name();
            const std::string full =
                k > 0 && !part.empty() && name.find('.') == std::string::npos ? part + "." + name : name;
            if (where.emplace(full, PartChannel{k, name}).second)
                frame.channels.push_back(full);
        }
    }
    frame.aovs = resolveFrameAovs(path, frame.channels, file.header(0), request);
    const AovChannels& aovs = frame.aovs;
    const std::vector<std::string>& colorNames = aovs.of(Aov::Color);
    const int colorPart = where.at(colorNames.front()).part;
    const Imf::Header& header = file.header(colorPart);
    describeHeader(header, frame);
    const Imath::Box2i data = header.dataWindow();
    frame.camera = readCameraAttributes(path, header);
    const int width = data.max.x - data.min.x + 1;
    const int height = data.max.y - data.min.y + 1;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);

    // The slices, by part: colour (four floats a pixel, absent components their fill) and each layer.
    std::map<int, Imf::FrameBuffer> buffers;
    const auto insert = [&](const std::string& full, float* base, std::size_t stride, double fill) {
        const PartChannel& c = where.at(full);
        const Imf::Header& h = file.header(c.part);
        if (h.dataWindow() != data)
            throw IoError(path, "channel " + full + " is in part " + frame.parts[std::size_t(c.part)] +
                                    ", whose data window differs from the colour's part " +
                                    frame.parts[std::size_t(colorPart)] + ": the parts read must share one");
        buffers[c.part].insert(c.name,
                               Imf::Slice::Make(Imf::FLOAT, base, data, stride * sizeof(float),
                                                stride * sizeof(float) * std::size_t(width), 1, 1, fill));
    };
    frame.color.width = width;
    frame.color.height = height;
    frame.color.rgba.assign(pixels * 4, 0.0f);
    const bool luminance = colorNames.size() <= 2;
    if (luminance && (where.contains("RY") || where.contains("BY")))
        throw IoError(path, "luminance/chroma colour (Y, RY, BY) is read from single-part files only");
    for (std::size_t c = 0; c < colorNames.size(); ++c) {
        const std::size_t component = luminance ? (c == 0 ? 0 : 3) : c;
        insert(colorNames[c], frame.color.rgba.data() + component, 4, component == 3 ? 1.0 : 0.0);
    }
    if (colorNames.size() == 1 || colorNames.size() == 3) {
        for (std::size_t i = 0; i < pixels; ++i)
            frame.color.rgba[i * 4 + 3] = 1.0f;
    }
    for (const auto& [aov, values, read] : layerTargets(frame, wanted)) {
        const std::vector<std::string>& names = aovs.of(aov);
        if (names.empty() || !read)
            continue;
        values->assign(pixels * names.size(), 0.0f);
        for (std::size_t c = 0; c < names.size(); ++c)
            insert(names[c], values->data() + c, names.size(), 0.0);
    }
    for (auto& [part, buffer] : buffers) {
        detail::checkExrChunks(path, bytes, part);
        Imf::InputPart input(file, part);
        if (!input.isComplete())
            throw IoError(path, "OpenEXR part " + frame.parts[std::size_t(part)] +
                                    " is truncated or incomplete (pixel blocks are missing)");
        input.setFrameBuffer(buffer);
        input.readPixels(data.min.y, data.max.y);
    }
    if (luminance) {
        for (std::size_t i = 0; i < pixels; ++i)
            frame.color.rgba[i * 4 + 1] = frame.color.rgba[i * 4 + 2] = frame.color.rgba[i * 4];
    }
    detail::convertExrToRec709(path, header, frame.color);
    emptyKeepingStorage(frame.colorHalves);
    frame.halfColor = false;
    applyReaderConventions(frame);
}

/// The frame in `bytes`, already checked by detail::checkExrBytes, into `frame`'s storage.
void readCheckedFrame(const fs::path& path, std::span<const unsigned char> bytes, ExrFrame& frame,
                      const ImageReadLimits& limits, ExrFrameReader::Color color,
                      ExrFrameReader::Layers wanted, const AovRequest& request) {
    try {
        detail::MemoryIStream stream(path, bytes);
        if (detail::isMultiPartExr(bytes)) {
            Imf::MultiPartInputFile parts(stream);
            if (parts.parts() > 1) {
                clearLayers(frame);
                readMultipartFrame(path, bytes, parts, frame, wanted, request);
                return;
            }
            stream.seekg(0);
        }
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        frame.parts.clear();
        const Imf::ChannelList& channels = header.channels();

        frame.channels.clear();
        for (auto it = channels.begin(); it != channels.end(); ++it)
            frame.channels.emplace_back(it.name());
        describeHeader(header, frame);

        frame.aovs = resolveFrameAovs(path, frame.channels, header, request);
        const AovChannels& aovs = frame.aovs;
        const detail::ExrColorChannels colorNames = detail::ExrColorChannels::of(aovs.of(Aov::Color));
        frame.camera = readCameraAttributes(path, header);
        frame.halfColor = true;
        for (const std::string& name : aovs.of(Aov::Color)) {
            const Imf::Channel* channel = channels.findChannel(name);
            frame.halfColor = frame.halfColor && (channel == nullptr || channel->type == Imf::HALF);
        }
        // Other primaries are converted to Rec.709 in float: the values are halves no longer.
        frame.halfColor = frame.halfColor && !detail::exrToRec709(header);
        clearLayers(frame);

        const auto layers = [&](Imf::FrameBuffer& frameBuffer, const Imath::Box2i& dataWindow, int width,
                                int height) {
            for (const auto& [aov, values, read] : layerTargets(frame, wanted)) {
                if (aovs.has(aov) && read)
                    addLayerSlices(frameBuffer, aovs.of(aov), *values, dataWindow, width, height);
            }
        };
        // The colour not read is emptied, its storage kept for a later frame that reads it.
        if (color == ExrFrameReader::Color::HalvesWhenStored &&
            detail::exrColorIsHalves(header, colorNames)) {
            emptyKeepingStorage(frame.color);
            detail::readExrColorHalves(path, bytes, file, frame.colorHalves, layers, limits, colorNames);
        } else {
            emptyKeepingStorage(frame.colorHalves);
            detail::readExrColor(path, bytes, file, frame.color, layers, limits, colorNames);
        }
        applyReaderConventions(frame);
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {
        throw IoError(path, std::string("cannot read OpenEXR: ") + e.what());
    }
}

/// Every field of `frame` emptied, its vectors' capacity kept.
void clearFrame(ExrFrame& frame) {
    emptyKeepingStorage(frame.color);
    emptyKeepingStorage(frame.colorHalves);
    clearLayers(frame);
    frame.camera = {};
    frame.aovs = {};
    frame.channels.clear();
    frame.parts.clear();
    frame.attributes.clear();
    frame.displaySize = {0, 0};
    frame.dataOrigin = {0, 0};
    frame.halfColor = false;
}

} // namespace

ExrFrame readExrFrame(const fs::path& path, const ImageReadLimits& limits, const AovRequest& aovs) {
    ExrFrameReader reader;
    reader.setAovs(aovs);
    ExrFrame frame;
    reader.read(path, frame, limits);
    return frame;
}

ExrFrame decodeExrFrame(std::span<const unsigned char> bytes, const fs::path& name,
                        const ImageReadLimits& limits) {
    ExrFrameReader reader;
    ExrFrame frame;
    reader.decode(bytes, name, frame, limits);
    return frame;
}

void ExrFrameReader::read(const fs::path& path, ExrFrame& frame, const ImageReadLimits& limits) {
    try {
        detail::readCheckedExrBytes(path, mBytes, limits);
        readCheckedFrame(path, mBytes, frame, limits, mColor, mLayers, mAovs);
    } catch (const IoError&) {
        clearFrame(frame);
        throw;
    }
}

void ExrFrameReader::decode(std::span<const unsigned char> bytes, const fs::path& name, ExrFrame& frame,
                            const ImageReadLimits& limits) {
    try {
        detail::checkExrBytes(name, bytes, limits);
        readCheckedFrame(name, bytes, frame, limits, mColor, mLayers, mAovs);
    } catch (const IoError&) {
        clearFrame(frame);
        throw;
    }
}

std::string encodeExrFrame(const ExrFrame& frame, const fs::path& path) {
    const ImageF& color = frame.color;
    const ImageH& halves = frame.colorHalves;
    const bool fromHalves = color.empty() && !halves.empty();
    const int width = fromHalves ? halves.width : color.width;
    const int height = fromHalves ? halves.height : color.height;
    if (fromHalves ? halves.rgba.size() != halves.pixelCount() * 4
                   : color.empty() || color.rgba.size() != color.pixelCount() * 4)
        throw IoError(path, "cannot write a frame without a colour image of width*height RGBA values");
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const auto requireSize = [&](const std::vector<float>& layer, std::size_t components, const char* name) {
        if (!layer.empty() && layer.size() != pixels * components)
            throw IoError(path, std::string(name) + " holds " + std::to_string(layer.size()) +
                                    " values, expected " + std::to_string(pixels * components));
    };
    requireSize(frame.depth, 1, "depth");
    requireSize(frame.normals, 3, "normals");
    requireSize(frame.motion, 2, "motion");

    // The writer takes each channel in its file type: half channels are converted here. Colour clamps
    // finite values to the largest half, as writeExr does; colour held as halves is written as it is.
    static constexpr float kHalfMax = 65504.0f;
    std::vector<half> rgba(pixels * 4);
    if (fromHalves) {
        std::transform(halves.rgba.begin(), halves.rgba.end(), rgba.begin(), [](std::uint16_t bits) {
            half h;
            h.setBits(bits);
            return h;
        });
    } else {
        std::transform(color.rgba.begin(), color.rgba.end(), rgba.begin(), [](float v) {
            return half(std::isfinite(v) ? std::clamp(v, -kHalfMax, kHalfMax) : v);
        });
    }
    const std::vector<half> normals(frame.normals.begin(), frame.normals.end());

    std::string bytes;
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        writeCameraAttributes(header, frame.camera);
        Imf::FrameBuffer frameBuffer;
        // The writer only reads the slices; OpenEXR's Slice takes a non-const pointer.
        const auto add = [&](const std::string& name, const auto* base, std::size_t count) {
            using Sample = std::remove_cvref_t<decltype(*base)>;
            const Imf::PixelType type = std::is_same_v<Sample, half> ? Imf::HALF : Imf::FLOAT;
            header.channels().insert(name, Imf::Channel(type));
            const std::size_t xStride = count * sizeof(Sample);
            frameBuffer.insert(name, Imf::Slice(type, reinterpret_cast<char*>(const_cast<Sample*>(base)),
                                                xStride, xStride * std::size_t(width)));
        };
        const std::array<const char*, 4> rgbaNames{"R", "G", "B", "A"};
        for (std::size_t c = 0; c < 4; ++c)
            add(rgbaNames[c], rgba.data() + c, 4);
        if (!frame.depth.empty())
            add("Z", frame.depth.data(), 1);
        const std::array<const char*, 3> xyz{"X", "Y", "Z"};
        for (std::size_t c = 0; c < 3 && !normals.empty(); ++c)
            add(std::string("N.") + xyz[c], normals.data() + c, 3);
        for (std::size_t c = 0; c < 2 && !frame.motion.empty(); ++c)
            add(std::string("motion.") + xyz[c], frame.motion.data() + c, 2);

        Imf::StdOSStream stream;
        {
            // The offset table is written when the file object goes: close it before taking the bytes.
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frameBuffer);
            file.writePixels(height);
        }
        bytes = stream.str();
    } catch (const std::exception& e) {
        throw IoError(path, std::string("cannot encode OpenEXR: ") + e.what());
    }
    return bytes;
}

void writeExrFrame(const fs::path& path, const ExrFrame& frame) {
    const std::string bytes = encodeExrFrame(frame, path);
    detail::writeAtomically(path,
                            std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

std::optional<Camera> cameraFromExr(const ExrCameraAttributes& attributes, int width, int height,
                                    const ExrCameraAttributes* previous) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("cameraFromExr: the frame has no pixels");
    if (!attributes.worldToCamera || !attributes.worldToNDC)
        return std::nullopt;
    const GlCamera current = glCamera(attributes);
    Camera camera;
    camera.view = current.view;
    camera.projection = current.projection;
    camera.nearPlane = current.nearPlane;
    camera.farPlane = current.farPlane;
    camera.verticalFov = current.verticalFov;
    camera.lens = lensFromExr(attributes, current.verticalFov);
    camera.prevViewProjection = camera.viewProjection();
    if (previous != nullptr && previous->worldToCamera && previous->worldToNDC) {
        const GlCamera last = glCamera(*previous);
        camera.prevViewProjection = last.projection * last.view;
    }
    if (const char* reason = invalidCameraReason(camera))
        throw std::invalid_argument(reason);
    return camera;
}

std::optional<Camera> frameCamera(const ExrFrame& frame, const ExrCameraAttributes* previous) {
    std::optional<Camera> camera =
        cameraFromExr(frame.camera, frame.displaySize.x, frame.displaySize.y, previous);
    const glm::ivec2 dataSize(frame.width(), frame.height());
    if (!camera || (frame.dataOrigin == glm::ivec2(0) && frame.displaySize == dataSize))
        return camera;
    const glm::mat4 crop = dataWindowCrop(frame.displaySize, frame.dataOrigin, dataSize);
    camera->projection = crop * camera->projection;
    camera->prevViewProjection = crop * camera->prevViewProjection;
    if (const char* reason = invalidCameraReason(*camera))
        throw std::invalid_argument(std::string("cropped to the data window: ") + reason);
    return camera;
}

ExrCameraAttributes exrFromCamera(const Camera& camera, int width, int height) {
    ExrCameraAttributes a;
    a.worldToCamera = kFlipZ * camera.view;
    const glm::mat4 clip = camera.projection * camera.view;
    const float n = camera.nearPlane;
    const float f = camera.farPlane;
    // RenderMan's NDC depth z_ndc = a + b / z for camera depth z = clip w: 0 at near, 1 at far.
    const float depthA = std::isinf(f) ? 1.0f : f / (f - n);
    const float depthB = std::isinf(f) ? -n : -n * f / (f - n);
    glm::mat4 ndc(0.0f);
    setRow(ndc, 0, 0.5f * (row(clip, 0) + row(clip, 3)));
    setRow(ndc, 1, 0.5f * (row(clip, 3) - row(clip, 1)));
    setRow(ndc, 2, depthA * row(clip, 3) + depthB * glm::vec4(0, 0, 0, 1));
    setRow(ndc, 3, row(clip, 3));
    a.worldToNDC = ndc;
    a.nearClip = n;
    a.farClip = f;
    const Lens& lens = camera.lens;
    a.focus = lens.focusDistance;
    a.aperture = lens.fNumber;
    if (lens.exposureTimeS > 0.0f)
        a.expTime = lens.exposureTimeS;
    a.isoSpeed = lens.iso;
    a.pinholeFocalLength = lens.focalLengthMm;
    a.sensorOverallDimensions =
        glm::vec2(lens.sensorHeightMm * float(width) / float(std::max(height, 1)), lens.sensorHeightMm);
    a.shutterAngle = lens.shutterAngleDeg;
    return a;
}

glm::mat4 dataWindowCrop(glm::ivec2 displaySize, glm::ivec2 dataOrigin, glm::ivec2 dataSize) {
    // Display-window pixels x right and y up: the data window spans [ox, ox + w] x [H - oy - h, H - oy].
    const glm::vec2 display(displaySize);
    const glm::vec2 size(dataSize);
    const glm::vec2 lower(float(dataOrigin.x), display.y - float(dataOrigin.y) - size.y);
    glm::mat4 crop(1.0f);
    crop[0][0] = display.x / size.x;
    crop[1][1] = display.y / size.y;
    // ndc' = ndc * D / d + (D - 2 lower) / d - 1, times clip w.
    crop[3][0] = (display.x - 2.0f * lower.x) / size.x - 1.0f;
    crop[3][1] = (display.y - 2.0f * lower.y) / size.y - 1.0f;
    return crop;
}

} // namespace photopic
