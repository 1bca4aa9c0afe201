#include "HueSweep.h"

#include "Oklab.h"

#include "core/Color.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace looks {

namespace {

glm::vec3 fromSrgb8(int r, int g, int b) {
    return photopic::srgbDecode(glm::vec3(float(r), float(g), float(b)) / 255.0f);
}

// A primary or secondary with a tenth of white added: pure primaries are fixed points of every per-channel
// curve (their zero channels stay zero), so they would hide the hue skew that per-channel curves give any
// colour whose minor channels are not zero.
glm::vec3 highChroma(glm::vec3 primary) {
    return 0.9f * primary + glm::vec3(0.1f);
}

// Chroma over lightness: how colourful against how bright, so a curve that only renders mid grey brighter
// (more chroma at the same saturation) is not counted as saturating.
float saturation(glm::vec3 lab) {
    return lab.x > 0.0f ? oklabChroma(lab) / lab.x : 0.0f;
}

} // namespace

std::vector<TestColour> testColours() {
    // Skin and sky: the ColorChecker Classic's published sRGB values (X-Rite/BabelColor, D65), patches 1, 2
    // and 3, linearised with the sRGB EOTF.
    return {
        {"red", highChroma({1, 0, 0})},           {"yellow", highChroma({1, 1, 0})},
        {"green", highChroma({0, 1, 0})},         {"cyan", highChroma({0, 1, 1})},
        {"blue", highChroma({0, 0, 1})},          {"magenta", highChroma({1, 0, 1})},
        {"light skin", fromSrgb8(194, 150, 130)}, {"dark skin", fromSrgb8(115, 82, 68)},
        {"blue sky", fromSrgb8(98, 122, 157)},
    };
}

std::vector<TestColour> referenceColours() {
    // ColorChecker Classic patches 7 (orange), 13 (blue), 14 (green), 15 (red), 16 (yellow), 17 (magenta),
    // 18 (cyan), from the same published sRGB values.
    return {
        {"pure red", {1, 0, 0}},
        {"pure green", {0, 1, 0}},
        {"pure blue", {0, 0, 1}},
        {"cc red", fromSrgb8(175, 54, 60)},
        {"cc orange", fromSrgb8(214, 126, 44)},
        {"cc yellow", fromSrgb8(231, 199, 31)},
        {"cc green", fromSrgb8(70, 148, 73)},
        {"cc cyan", fromSrgb8(8, 133, 161)},
        {"cc blue", fromSrgb8(56, 61, 150)},
        {"cc magenta", fromSrgb8(187, 86, 149)},
    };
}

HueShift measureHueShift(const Variant& variant, glm::vec3 colour) {
    const float inputHue = oklabHueDeg(linearSrgbToOklab(colour));
    const float toMid = 0.18f / photopic::luma709(colour);
    const photopic::ToneCurveParams params{.agxLook = variant.look};
    struct Point {
        float ev, chroma, saturation, shift;
    };
    std::vector<Point> ramp;
    float peak = 0.0f;
    for (float ev = kRampFirstEv; ev <= kRampLastEv + 1e-3f; ev += kRampStepEv) {
        const glm::vec3 display = photopic::toneMap(variant.mapper, colour * toMid * std::exp2(ev), params);
        const glm::vec3 lab = linearSrgbToOklab(display);
        ramp.push_back({ev, oklabChroma(lab), saturation(lab), hueDifferenceDeg(oklabHueDeg(lab), inputHue)});
        peak = std::max(peak, ramp.back().chroma);
    }
    HueShift result;
    result.whiteAtEv = kRampLastEv + kRampStepEv;
    bool white = false;
    for (const Point& p : ramp) {
        if (std::abs(p.ev) < 1e-3f) {
            result.atMidDeg = p.shift;
            result.saturationKeptAtMid = p.saturation / saturation(linearSrgbToOklab(colour * toMid));
        }
        // Once the colour has gone (nearly) white its hue is noise, and a curve that never comes back to
        // colour above that exposure is not judged past it.
        white = white || p.chroma < kCountedChromaShare * peak;
        if (white) {
            result.whiteAtEv = std::min(result.whiteAtEv, p.ev);
            continue;
        }
        if (std::abs(p.shift) > std::abs(result.worstDeg)) {
            result.worstDeg = p.shift;
            result.worstAtEv = p.ev;
        }
    }
    return result;
}

void checkOklab() {
    // Reference values from Ottosson's post: white is (1, 0, 0); sRGB red is L 0.62796, a 0.22486, b 0.12585.
    const glm::vec3 white = linearSrgbToOklab({1, 1, 1});
    const glm::vec3 red = linearSrgbToOklab({1, 0, 0});
    const bool ok = std::abs(white.x - 1.0f) < 1e-4f && oklabChroma(white) < 1e-4f &&
                    std::abs(red.x - 0.62796f) < 1e-4f && std::abs(red.y - 0.22486f) < 1e-4f &&
                    std::abs(red.z - 0.12585f) < 1e-4f;
    if (!ok) {
        throw std::runtime_error("photopic_looks: the Oklab matrices miss Ottosson's reference values");
    }
}

} // namespace looks
