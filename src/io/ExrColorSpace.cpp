// An OpenEXR file's `chromaticities` attribute names the primaries and white its RGB values are in (OpenEXR
// Technical Introduction, "Standard attributes"); absent, they are Rec.709 with a D65 white. The pipeline's
// working space is linear Rec.709, so other primaries (ACES AP0, Rec.2020, ...) are converted on load: file
// RGB -> XYZ (the file's primaries), a Bradford adaptation from the file's white to D65 when the two differ
// (Lam 1985, in the linear form colour-management systems use), then XYZ -> Rec.709.

#include "io/ExrDetail.h"

#include "core/Log.h"

#include <ImfChromaticities.h>
#include <ImfStandardAttributes.h>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <mutex>
#include <set>
#include <string>

namespace photopic {

namespace fs = std::filesystem;

namespace {

/// Chromaticity coordinates closer than this are the same: files round xy to 4 decimals or keep floats.
constexpr float kSameXy = 1e-3f;

bool sameXy(const Imath::V2f& a, const Imath::V2f& b) {
    return std::abs(a.x - b.x) <= kSameXy && std::abs(a.y - b.y) <= kSameXy;
}

bool isRec709D65(const Imf::Chromaticities& c) {
    const Imf::Chromaticities rec709; // OpenEXR's default: Rec.709 primaries, D65 white
    return sameXy(c.red, rec709.red) && sameXy(c.green, rec709.green) && sameXy(c.blue, rec709.blue) &&
           sameXy(c.white, rec709.white);
}

/// Imath's matrices act on row vectors (v * M); glm's on column vectors (M * v): element [j][i] is the
/// same number in both (glm indexes column first).
glm::dmat3 toColumnVectorMatrix(const Imath::M44f& m) {
    glm::dmat3 out(0.0);
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            out[j][i] = double(m[j][i]);
        }
    }
    return out;
}

glm::dvec3 whiteXyz(const Imath::V2f& xy) {
    return {double(xy.x) / double(xy.y), 1.0, (1.0 - double(xy.x) - double(xy.y)) / double(xy.y)};
}

/// Von Kries scaling in Bradford cone space from the `from` white to the `to` white (XYZ -> XYZ).
glm::dmat3 bradford(const Imath::V2f& from, const Imath::V2f& to) {
    // Rows of the Bradford matrix, written as glm's columns.
    const glm::dmat3 cone{0.8951, -0.7502, 0.0389, 0.2664, 1.7135, -0.0685, -0.1614, 0.0367, 1.0296};
    const glm::dvec3 source = cone * whiteXyz(from);
    const glm::dvec3 target = cone * whiteXyz(to);
    glm::dmat3 scale(0.0);
    for (int c = 0; c < 3; ++c) {
        scale[c][c] = target[c] / source[c];
    }
    return glm::inverse(cone) * scale * cone;
}

/// Logs once per process for each set of primaries, naming the first file that had them: a sequence of a
/// thousand frames says it once. Readers run on decode threads, hence the lock.
void logConversionOnce(const fs::path& path, const Imf::Chromaticities& c) {
    static std::mutex mutex;
    static std::set<std::string> seen;
    const std::string key = fmt::format("{} {} {} {} {} {} {} {}", c.red.x, c.red.y, c.green.x, c.green.y,
                                        c.blue.x, c.blue.y, c.white.x, c.white.y);
    {
        const std::lock_guard lock(mutex);
        if (!seen.insert(key).second) {
            return;
        }
    }
    logInfo("\"{}\": converting from the file's chromaticities (red {:.4f},{:.4f} green {:.4f},{:.4f} blue "
            "{:.4f},{:.4f} white {:.4f},{:.4f}) to linear Rec.709 with a D65 white{}",
            path.string(), c.red.x, c.red.y, c.green.x, c.green.y, c.blue.x, c.blue.y, c.white.x, c.white.y,
            sameXy(c.white, Imf::Chromaticities().white) ? "" : " (Bradford adaptation)");
}

} // namespace

std::optional<glm::mat3> detail::exrToRec709(const Imf::Header& header) {
    if (!Imf::hasChromaticities(header)) {
        return std::nullopt;
    }
    const Imf::Chromaticities& file = Imf::chromaticities(header);
    if (isRec709D65(file)) {
        return std::nullopt;
    }
    const Imf::Chromaticities rec709;
    glm::dmat3 m = toColumnVectorMatrix(Imf::RGBtoXYZ(file, 1.0f));
    if (!sameXy(file.white, rec709.white)) {
        m = bradford(file.white, rec709.white) * m;
    }
    return glm::mat3(toColumnVectorMatrix(Imf::XYZtoRGB(rec709, 1.0f)) * m);
}

void detail::convertExrToRec709(const fs::path& path, const Imf::Header& header, ImageF& image) {
    const std::optional<glm::mat3> m = exrToRec709(header);
    if (!m) {
        return;
    }
    logConversionOnce(path, Imf::chromaticities(header));
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        float* p = image.rgba.data() + i * 4;
        const glm::vec3 rgb = *m * glm::vec3(p[0], p[1], p[2]);
        p[0] = rgb.r;
        p[1] = rgb.g;
        p[2] = rgb.b;
    }
}

} // namespace photopic
