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
#include <ImfVecAttribute.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

// Reading a frame: colour, the 3D layers and the camera attributes (ExrFrameWrite.cpp writes one,
// ExrFrameCamera.cpp turns its camera attributes into a Camera and back).
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

/// Every channel of a multi-part file by its full name (a later part's channel prefixed with its part's name
/// unless it has a layer already), the first one of a name kept; `frame`'s channel and part names listed.
std::map<std::string, PartChannel> partChannels(Imf::MultiPartInputFile& file, ExrFrame& frame) {
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
    return where;
}

/// The float slices of a multi-part read, by part, each into the colour part's data window.
class PartSlices {
public:
    PartSlices(const fs::path& path, Imf::MultiPartInputFile& file, const ExrFrame& frame,
               const std::map<std::string, PartChannel>& where, int colorPart)
        : mPath(path)
        , mFile(file)
        , mFrame(frame)
        , mWhere(where)
        , mColorPart(colorPart)
        , mData(file.header(colorPart).dataWindow()) {}

    /// Channel `full` into every `stride`-th float from `base`, `fill` where its part lacks it.
    void add(const std::string& full, float* base, std::size_t stride, double fill) {
        const PartChannel& c = mWhere.at(full);
        const Imf::Header& h = mFile.header(c.part);
        if (h.dataWindow() != mData)
            throw IoError(mPath, "channel " + full + " is in part " + mFrame.parts[std::size_t(c.part)] +
                                     ", whose data window differs from the colour's part " +
                                     mFrame.parts[std::size_t(mColorPart)] +
                                     ": the parts read must share one");
        const std::size_t width = std::size_t(mData.max.x - mData.min.x + 1);
        mBuffers[c.part].insert(c.name, Imf::Slice::Make(Imf::FLOAT, base, mData, stride * sizeof(float),
                                                         stride * sizeof(float) * width, 1, 1, fill));
    }

    /// Reads every part that has a slice, each checked first.
    void read(std::span<const unsigned char> bytes) {
        for (auto& [part, buffer] : mBuffers) {
            detail::checkExrChunks(mPath, bytes, part);
            Imf::InputPart input(mFile, part);
            if (!input.isComplete())
                throw IoError(mPath, "OpenEXR part " + mFrame.parts[std::size_t(part)] +
                                         " is truncated or incomplete (pixel blocks are missing)");
            input.setFrameBuffer(buffer);
            input.readPixels(mData.min.y, mData.max.y);
        }
    }

private:
    const fs::path& mPath;
    Imf::MultiPartInputFile& mFile;
    const ExrFrame& mFrame;
    const std::map<std::string, PartChannel>& mWhere;
    int mColorPart;
    Imath::Box2i mData;
    std::map<int, Imf::FrameBuffer> mBuffers;
};

/// The colour's slices (four floats a pixel, absent components their fill: alpha 1 when there is none), into
/// `frame.color` sized `width` x `height`; true for luminance (Y, optionally with A), whose Y goes to red.
bool addColorSlices(const fs::path& path, PartSlices& slices, const std::map<std::string, PartChannel>& where,
                    ExrFrame& frame, int width, int height) {
    const std::vector<std::string>& colorNames = frame.aovs.of(Aov::Color);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    frame.color.width = width;
    frame.color.height = height;
    frame.color.rgba.assign(pixels * 4, 0.0f);
    const bool luminance = colorNames.size() <= 2;
    if (luminance && (where.contains("RY") || where.contains("BY")))
        throw IoError(path, "luminance/chroma colour (Y, RY, BY) is read from single-part files only");
    for (std::size_t c = 0; c < colorNames.size(); ++c) {
        const std::size_t component = luminance ? (c == 0 ? 0 : 3) : c;
        slices.add(colorNames[c], frame.color.rgba.data() + component, 4, component == 3 ? 1.0 : 0.0);
    }
    if (colorNames.size() == 1 || colorNames.size() == 3) {
        for (std::size_t i = 0; i < pixels; ++i)
            frame.color.rgba[i * 4 + 3] = 1.0f;
    }
    return luminance;
}

/// The frame in a multi-part file's parts, already checked by detail::checkExrBytes, into `frame`: every
/// channel the mapping names read from its part (each such part's data window the colour's), colour as
/// floats.
void readMultipartFrame(const fs::path& path, std::span<const unsigned char> bytes,
                        Imf::MultiPartInputFile& file, ExrFrame& frame, ExrFrameReader::Layers wanted,
                        const AovRequest& request) {
    const std::map<std::string, PartChannel> where = partChannels(file, frame);
    frame.aovs = resolveFrameAovs(path, frame.channels, file.header(0), request);
    const int colorPart = where.at(frame.aovs.of(Aov::Color).front()).part;
    const Imf::Header& header = file.header(colorPart);
    describeHeader(header, frame);
    const Imath::Box2i data = header.dataWindow();
    frame.camera = readCameraAttributes(path, header);
    const int width = data.max.x - data.min.x + 1;
    const int height = data.max.y - data.min.y + 1;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);

    PartSlices slices(path, file, frame, where, colorPart);
    const bool luminance = addColorSlices(path, slices, where, frame, width, height);
    for (const auto& [aov, values, read] : layerTargets(frame, wanted)) {
        const std::vector<std::string>& names = frame.aovs.of(aov);
        if (names.empty() || !read)
            continue;
        values->assign(pixels * names.size(), 0.0f);
        for (std::size_t c = 0; c < names.size(); ++c)
            slices.add(names[c], values->data() + c, names.size(), 0.0);
    }
    slices.read(bytes);
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

} // namespace photopic
