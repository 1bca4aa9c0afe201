// An EXR whose `chromaticities` attribute names other primaries than Rec.709 is converted to the linear
// Rec.709 working space on load, by readImage and by the sequence reader alike. The expected matrices are
// computed here from the xy coordinates (SMPTE RP 177's normalised primary matrix, Bradford adaptation),
// not with OpenEXR's helpers the reader uses.

#include "core/Log.h"
#include "io/ExrFrame.h"
#include "io/ImageIO.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfChromaticities.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <glm/glm.hpp>
#include <unistd.h>

#include <array>
#include <string>
#include <vector>

namespace photopic {
namespace {

namespace fs = std::filesystem;

struct Xy {
    double x;
    double y;
};

struct Primaries {
    Xy red, green, blue, white;
};

constexpr Primaries kRec709{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}};
constexpr Primaries kRec2020{{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, {0.3127, 0.3290}};
constexpr Primaries kAp0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}, {0.32168, 0.33767}};

glm::dvec3 xyz(Xy c) {
    return {c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y};
}

/// RGB -> XYZ: the primaries' XYZ as columns, scaled so that RGB (1, 1, 1) is the white with Y = 1.
glm::dmat3 rgbToXyz(const Primaries& p) {
    const glm::dmat3 m(xyz(p.red), xyz(p.green), xyz(p.blue));
    const glm::dvec3 s = glm::inverse(m) * xyz(p.white);
    return glm::dmat3(m[0] * s.x, m[1] * s.y, m[2] * s.z);
}

glm::dmat3 bradford(Xy from, Xy to) {
    const glm::dmat3 b =
        glm::transpose(glm::dmat3(0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296));
    const glm::dvec3 s = b * xyz(from);
    const glm::dvec3 d = b * xyz(to);
    return glm::inverse(b) * glm::dmat3(d.x / s.x, 0, 0, 0, d.y / s.y, 0, 0, 0, d.z / s.z) * b;
}

glm::dmat3 toRec709(const Primaries& p) {
    return glm::inverse(rgbToXyz(kRec709)) * bradford(p.white, kRec709.white) * rgbToXyz(p);
}

Imf::Chromaticities chromaticities(const Primaries& p) {
    const auto v = [](Xy c) { return Imath::V2f(float(c.x), float(c.y)); };
    return {v(p.red), v(p.green), v(p.blue), v(p.white)};
}

/// Pixels a float RGBA EXR with `primaries` holds: red, green, blue, grey, a mixed colour, black.
const std::vector<glm::vec3> kPixels = {{1, 0, 0},          {0, 1, 0},          {0, 0, 1},
                                        {0.5f, 0.5f, 0.5f}, {0.2f, 0.7f, 0.4f}, {0, 0, 0}};

fs::path writeTaggedExr(const std::string& name, const Primaries* primaries,
                        Imf::PixelType type = Imf::FLOAT) {
    const fs::path path =
        fs::temp_directory_path() / ("photopic-chroma-" + std::to_string(::getpid()) + name);
    const int width = int(kPixels.size());
    Imf::Header header(width, 1);
    if (primaries) {
        Imf::addChromaticities(header, chromaticities(*primaries));
    }
    for (const char* c : {"R", "G", "B"}) {
        header.channels().insert(c, Imf::Channel(type));
    }
    std::vector<float> rgb;
    for (const glm::vec3& p : kPixels) {
        rgb.insert(rgb.end(), {p.r, p.g, p.b});
    }
    const std::vector<half> halves(rgb.begin(), rgb.end());
    const bool isHalf = type == Imf::HALF;
    const std::size_t size = isHalf ? sizeof(half) : sizeof(float);
    char* base = isHalf ? reinterpret_cast<char*>(const_cast<half*>(halves.data()))
                        : reinterpret_cast<char*>(rgb.data());
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < 3; ++c) {
        frameBuffer.insert(std::string(1, "RGB"[c]),
                           Imf::Slice(type, base + std::size_t(c) * size, 3 * size, rgb.size() * size));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frameBuffer);
    file.writePixels(1);
    return path;
}

void expectConverted(const ImageF& image, const glm::dmat3& m, const char* reader) {
    ASSERT_EQ(image.width, int(kPixels.size())) << reader;
    for (std::size_t i = 0; i < kPixels.size(); ++i) {
        const glm::dvec3 want = m * glm::dvec3(kPixels[i]);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.at(int(i), 0)[c], want[c], 2e-4)
                << reader << " pixel " << i << " channel " << c;
        }
        EXPECT_EQ(image.at(int(i), 0)[3], 1.0f) << reader; // alpha is not colour
    }
}

TEST(ExrChromaticities, Rec2020RedMapsToTheKnownRec709ValuesAndGreyStaysGrey) {
    const fs::path path = writeTaggedExr("2020.exr", &kRec2020);
    const ImageF image = readImage(path);
    // ITU-R BT.2087's Rec.2020 -> Rec.709 matrix, first column.
    EXPECT_NEAR(image.at(0, 0)[0], 1.6605, 1e-3);
    EXPECT_NEAR(image.at(0, 0)[1], -0.1246, 1e-3);
    EXPECT_NEAR(image.at(0, 0)[2], -0.0182, 1e-3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.at(3, 0)[c], 0.5f, 1e-5); // same white: grey is untouched
    }
    expectConverted(image, toRec709(kRec2020), "readImage");
    expectConverted(readExrFrame(path).color, toRec709(kRec2020), "readExrFrame");
    fs::remove(path);
}

TEST(ExrChromaticities, Ap0IsAdaptedToD65OnEveryReaderAndLoggedOnce) {
    const fs::path path = writeTaggedExr("ap0.exr", &kAp0);
    std::vector<std::string> infos;
    const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Info) {
            infos.emplace_back(message);
        }
    });
    const ImageF image = readImage(path);
    ExrFrame frame;
    ExrFrameReader reader;
    reader.read(path, frame);
    reader.read(path, frame);
    setLogSink(previous);
    expectConverted(image, toRec709(kAp0), "readImage");
    expectConverted(frame.color, toRec709(kAp0), "ExrFrameReader");
    // The ACES white is not D65: the adaptation takes an ACES grey to a Rec.709 grey.
    EXPECT_NEAR(image.at(3, 0)[0], image.at(3, 0)[1], 1e-4);
    EXPECT_NEAR(image.at(3, 0)[2], image.at(3, 0)[1], 1e-4);
    ASSERT_EQ(infos.size(), 1u) << "three reads, one message";
    EXPECT_NE(infos[0].find(path.string()), std::string::npos) << infos[0];
    EXPECT_NE(infos[0].find("Rec.709"), std::string::npos) << infos[0];
    fs::remove(path);
}

TEST(ExrChromaticities, Rec709AndAbsentAttributesLeaveThePixelsAsStored) {
    for (const Primaries* p : {&kRec709, static_cast<const Primaries*>(nullptr)}) {
        const fs::path path = writeTaggedExr(p ? "709.exr" : "none.exr", p);
        const ImageF image = readImage(path);
        expectConverted(image, glm::dmat3(1.0), p ? "Rec.709" : "no attribute");
        fs::remove(path);
    }
}

TEST(ExrChromaticities, HalfChannelsAreHalvesExactlyOnlyWhenNotConverted) {
    // The CLI keeps a half EXR's colour in a half-float texture only while each value is a half exactly.
    for (const Primaries* p : {&kRec709, &kRec2020, static_cast<const Primaries*>(nullptr)}) {
        const fs::path path = writeTaggedExr(p ? "half.exr" : "half-none.exr", p, Imf::HALF);
        const ExrFrame frame = readExrFrame(path);
        EXPECT_EQ(frame.halfColor, p != &kRec2020) << (p ? "with primaries" : "no attribute");
        fs::remove(path);
    }
    const fs::path path = writeTaggedExr("float.exr", &kRec709);
    EXPECT_FALSE(readExrFrame(path).halfColor);
    fs::remove(path);
}

} // namespace
} // namespace photopic
