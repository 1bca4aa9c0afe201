#include "io/ExrFrame.h"

#include "io/ExrDetail.h"

#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMatrixAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfVecAttribute.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

// Writing a frame (encodeExrFrame, writeExrFrame): RGBA halves, depth, normals and motion, and the camera
// attributes.
namespace photopic {

namespace fs = std::filesystem;

namespace {

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

/// Throws IoError naming `path` unless the frame's colour holds width*height RGBA values and each layer it
/// has one value per component for each of its `pixels`.
void checkSizes(const ExrFrame& frame, bool fromHalves, std::size_t pixels, const fs::path& path) {
    const ImageF& color = frame.color;
    const ImageH& halves = frame.colorHalves;
    if (fromHalves ? halves.rgba.size() != halves.pixelCount() * 4
                   : color.empty() || color.rgba.size() != color.pixelCount() * 4)
        throw IoError(path, "cannot write a frame without a colour image of width*height RGBA values");
    const auto requireSize = [&](const std::vector<float>& layer, std::size_t components, const char* name) {
        if (!layer.empty() && layer.size() != pixels * components)
            throw IoError(path, std::string(name) + " holds " + std::to_string(layer.size()) +
                                    " values, expected " + std::to_string(pixels * components));
    };
    requireSize(frame.depth, 1, "depth");
    requireSize(frame.normals, 3, "normals");
    requireSize(frame.motion, 2, "motion");
}

/// The colour as halves, the file's type for it: colour held as halves as it is, floats with finite values
/// clamped to the largest half, as writeExr does.
std::vector<half> halfRgba(const ExrFrame& frame, bool fromHalves, std::size_t pixels) {
    static constexpr float kHalfMax = 65504.0f;
    std::vector<half> rgba(pixels * 4);
    if (fromHalves) {
        std::transform(frame.colorHalves.rgba.begin(), frame.colorHalves.rgba.end(), rgba.begin(),
                       [](std::uint16_t bits) {
                           half h;
                           h.setBits(bits);
                           return h;
                       });
    } else {
        std::transform(frame.color.rgba.begin(), frame.color.rgba.end(), rgba.begin(), [](float v) {
            return half(std::isfinite(v) ? std::clamp(v, -kHalfMax, kHalfMax) : v);
        });
    }
    return rgba;
}

/// Each channel of the file, added to the header and the frame buffer in its file type.
class FrameChannels {
public:
    FrameChannels(Imf::Header& header, int width)
        : mHeader(header)
        , mWidth(width) {}

    /// The writer only reads the slices; OpenEXR's Slice takes a non-const pointer.
    template <class Sample>
    void add(const std::string& name, const Sample* base, std::size_t count) {
        const Imf::PixelType type = std::is_same_v<Sample, half> ? Imf::HALF : Imf::FLOAT;
        mHeader.channels().insert(name, Imf::Channel(type));
        const std::size_t xStride = count * sizeof(Sample);
        mFrameBuffer.insert(name, Imf::Slice(type, reinterpret_cast<char*>(const_cast<Sample*>(base)),
                                             xStride, xStride * std::size_t(mWidth)));
    }

    const Imf::FrameBuffer& frameBuffer() const { return mFrameBuffer; }

private:
    Imf::Header& mHeader;
    int mWidth;
    Imf::FrameBuffer mFrameBuffer;
};

/// The file's bytes: ZIP-compressed RGBA halves, then Z, N.XYZ (halves) and motion.XY where the frame has
/// them.
std::string encodeChannels(const ExrFrame& frame, const std::vector<half>& rgba, int width, int height) {
    const std::vector<half> normals(frame.normals.begin(), frame.normals.end());
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    writeCameraAttributes(header, frame.camera);
    FrameChannels channels(header, width);
    const std::array<const char*, 4> rgbaNames{"R", "G", "B", "A"};
    for (std::size_t c = 0; c < 4; ++c)
        channels.add(rgbaNames[c], rgba.data() + c, 4);
    if (!frame.depth.empty())
        channels.add("Z", frame.depth.data(), 1);
    const std::array<const char*, 3> xyz{"X", "Y", "Z"};
    for (std::size_t c = 0; c < 3 && !normals.empty(); ++c)
        channels.add(std::string("N.") + xyz[c], normals.data() + c, 3);
    for (std::size_t c = 0; c < 2 && !frame.motion.empty(); ++c)
        channels.add(std::string("motion.") + xyz[c], frame.motion.data() + c, 2);

    Imf::StdOSStream stream;
    {
        // The offset table is written when the file object goes: close it before taking the bytes.
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(channels.frameBuffer());
        file.writePixels(height);
    }
    return stream.str();
}

} // namespace

std::string encodeExrFrame(const ExrFrame& frame, const fs::path& path) {
    const bool fromHalves = frame.color.empty() && !frame.colorHalves.empty();
    const int width = fromHalves ? frame.colorHalves.width : frame.color.width;
    const int height = fromHalves ? frame.colorHalves.height : frame.color.height;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    checkSizes(frame, fromHalves, pixels, path);
    const std::vector<half> rgba = halfRgba(frame, fromHalves, pixels);
    try {
        return encodeChannels(frame, rgba, width, height);
    } catch (const std::exception& e) {
        throw IoError(path, std::string("cannot encode OpenEXR: ") + e.what());
    }
}

void writeExrFrame(const fs::path& path, const ExrFrame& frame) {
    const std::string bytes = encodeExrFrame(frame, path);
    detail::writeAtomically(path,
                            std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

} // namespace photopic
