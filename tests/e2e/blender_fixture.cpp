// Fixture of blender.sh: figures of photopic image's outputs on Blender's (Cycles') files against Blender's
// own passes and renders, each printed as a line and held to its bound by the exit status.
//
//   photopic_blender_fixture geometry TRACK AUXDIR N...   the decoded normals and motion (--write-aux) of
//   frames
//                                                          N against the depth and the camera track: normals
//                                                          from the depth's own surface, motion of the static
//                                                          scene reprojected through the track's two cameras
//   photopic_blender_fixture effect NAME OURS NONE TRUTH MAX [PASSES]   RMSE of OURS and of NONE (the
//   pinhole,
//                                                          still frame) against TRUTH (Cycles' own DoF or
//                                                          motion blur): exit 0 when OURS's is at most MAX of
//                                                          NONE's; with PASSES, the same by region of its
//                                                          depth
//   photopic_blender_fixture ao OURS PASSES MAXBIAS MAXOPEN   GTAO's visibility (--debug ao EXR) against
//                                                          Cycles' AO pass on the surfaces: mean absolute
//                                                          error and bias (ours - Cycles'), and the error of
//                                                          9 x 9 means over open surfaces; exit 0 when |bias|
//                                                          <= MAXBIAS and that error <= MAXOPEN
//   photopic_blender_fixture reflections OURS AMPLE MINSHARE   pixels with a reflection (confidence above 0)
//                                                          in SSR's view (--debug ssr EXR) at a step budget
//                                                          and at an ample one; exit 0 when OURS has at
//                                                          least MINSHARE of AMPLE's
//   photopic_blender_fixture mirror OURS MIRROR MINCOVERED MINWITHIN MAXFALSE   SSR's view (--debug ssr
//                                                          EXR of the mirror variant's frame) against
//                                                          Cycles' reflected radiance on the mirror ground:
//                                                          the share of the ground reflecting an object that
//                                                          SSR covers, of that the share within 10%, and the
//                                                          share of the ground reflecting the sky that SSR
//                                                          gives a reflection

#include "CameraJson.h"
#include "InputError.h"

#include "io/ExrFrame.h"
#include "io/ImageIO.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace photopic;

double percentile(std::vector<double> values, double p) {
    if (values.empty())
        return 0.0;
    const std::size_t i = std::min(values.size() - 1, std::size_t(p * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(i), values.end());
    return values[i];
}

/// View-space position of pixel (x, y) (rows top to bottom) at planar depth `depth`.
glm::vec3 viewPosition(const glm::mat4& inverseProjection, int x, int y, int width, int height, float depth) {
    const glm::vec4 ndc(2.0f * (float(x) + 0.5f) / float(width) - 1.0f,
                        1.0f - 2.0f * (float(y) + 0.5f) / float(height), 0.5f, 1.0f);
    const glm::vec4 p = inverseProjection * ndc;
    const glm::vec3 ray = glm::vec3(p) / -p.z;
    return ray * depth;
}

std::string auxName(int frame) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%04d.aux.exr", frame);
    return name;
}

int geometry(const fs::path& trackPath, const fs::path& auxDir, const std::vector<int>& frames) {
    const cli::CameraTrack track = cli::loadCameraTrack(trackPath);
    bool ok = true;
    for (const int f : frames) {
        const ExrFrame aux = readExrFrame(auxDir / auxName(f));
        const int w = aux.width();
        const int h = aux.height();
        const Camera camera = track.at(f, auxName(f)).camera(w, h);
        const Camera previous = track.at(f - 1, auxName(f - 1)).camera(w, h);
        const glm::mat4 inverseProjection = glm::inverse(camera.projection);
        const glm::mat4 viewToWorld = glm::inverse(camera.view);
        const glm::mat4 previousViewProjection = previous.viewProjection();
        if (aux.depth.empty() || aux.normals.empty() || aux.motion.empty()) {
            std::fprintf(stderr, "%s lacks depth, normals or motion\n", auxName(f).c_str());
            return 1;
        }
        const auto depth = [&](int x, int y) {
            return aux.depth[std::size_t(y) * std::size_t(w) + std::size_t(x)];
        };
        std::vector<double> angles;
        std::vector<double> motionErrors;
        for (int y = 1; y + 1 < h; ++y) {
            for (int x = 1; x + 1 < w; ++x) {
                const float d = depth(x, y);
                if (!(d < 1e4f))
                    continue; // the sky
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                // The motion the static scene has at this pixel, through the two cameras.
                const glm::vec3 view = viewPosition(inverseProjection, x, y, w, h, d);
                const glm::vec4 world = viewToWorld * glm::vec4(view, 1.0f);
                const glm::vec4 clip = previousViewProjection * world;
                const glm::vec2 uvPrevious = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
                const glm::vec2 uv((float(x) + 0.5f) / float(w), 1.0f - (float(y) + 0.5f) / float(h));
                const glm::vec2 expected = (uv - uvPrevious) * glm::vec2(w, h); // pixels, y up
                const glm::vec2 decoded(aux.motion[2 * i] * float(w), aux.motion[2 * i + 1] * float(h));
                motionErrors.push_back(double(glm::length(decoded - expected)));
                // Normals where the surface is flat around the pixel: the cross product of its neighbours.
                float spread = 0.0f;
                for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                    spread = std::max(spread, std::abs(depth(x + dx, y + dy) - d) / d);
                if (spread > 0.05f)
                    continue;
                const glm::vec3 right = viewPosition(inverseProjection, x + 1, y, w, h, depth(x + 1, y)) -
                                        viewPosition(inverseProjection, x - 1, y, w, h, depth(x - 1, y));
                const glm::vec3 up = viewPosition(inverseProjection, x, y - 1, w, h, depth(x, y - 1)) -
                                     viewPosition(inverseProjection, x, y + 1, w, h, depth(x, y + 1));
                const glm::vec3 fromDepth = glm::normalize(glm::cross(right, up));
                const glm::vec3 n(aux.normals[3 * i], aux.normals[3 * i + 1], aux.normals[3 * i + 2]);
                if (glm::dot(n, n) < 0.5f)
                    continue;
                angles.push_back(glm::degrees(
                    std::acos(std::clamp(double(glm::dot(glm::normalize(n), fromDepth)), -1.0, 1.0))));
            }
        }
        const double angleMedian = percentile(angles, 0.5);
        const double motionMedian = percentile(motionErrors, 0.5);
        const double motion80 = percentile(motionErrors, 0.8);
        std::printf(
            "frame %d normals vs depth: median %.2f deg, 90%% %.2f deg (%zu px); motion vs the track's "
            "reprojection: median %.4f px, 80%% %.4f px (%zu px)\n",
            f, angleMedian, percentile(angles, 0.9), angles.size(), motionMedian, motion80,
            motionErrors.size());
        ok = ok && angleMedian < 3.0 && motionMedian < 0.05 && motion80 < 0.2;
    }
    return ok ? 0 : 1;
}

double rmse(const ImageF& a, const ImageF& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.rgba[4 * i + std::size_t(c)]) - double(b.rgba[4 * i + std::size_t(c)]);
            sum += d * d;
        }
    }
    return std::sqrt(sum / double(3 * a.pixelCount()));
}

/// The errors of `ours` and `none` against `truth` by region of `passes`' depth: within 8 pixels of a depth
/// edge (a neighbour 10% nearer or farther) or not, the sky or not.
void breakdown(const ImageF& ours, const ImageF& none, const ImageF& truth, const fs::path& passes) {
    const ExrFrame frame = readExrFrame(passes);
    const int w = truth.width;
    const int h = truth.height;
    std::vector<bool> edge(truth.pixelCount(), false);
    const auto depth = [&](int x, int y) {
        return double(frame.depth[std::size_t(std::clamp(y, 0, h - 1)) * std::size_t(w) +
                                  std::size_t(std::clamp(x, 0, w - 1))]);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int d = -8; d <= 8 && !edge[std::size_t(y * w + x)]; ++d)
                for (int e = -8; e <= 8; ++e) {
                    const double a = std::min(depth(x, y), 1e4);
                    const double b = std::min(depth(x + d, y + e), 1e4);
                    if (std::abs(a - b) > 0.1 * std::min(a, b)) {
                        edge[std::size_t(y * w + x)] = true;
                        break;
                    }
                }
    for (const auto& [label, wantEdge, wantSky] : {std::tuple{"surfaces away from depth edges", false, false},
                                                   std::tuple{"within 8 px of a depth edge", true, false},
                                                   std::tuple{"sky away from edges", false, true}}) {
        double sumOurs = 0.0, sumNone = 0.0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < truth.pixelCount(); ++i) {
            const bool sky = !(frame.depth[i] < 1e4f);
            if (edge[i] != wantEdge || (!wantEdge && sky != wantSky))
                continue;
            for (int c = 0; c < 3; ++c) {
                const std::size_t k = 4 * i + std::size_t(c);
                sumOurs += std::pow(double(ours.rgba[k]) - double(truth.rgba[k]), 2.0);
                sumNone += std::pow(double(none.rgba[k]) - double(truth.rgba[k]), 2.0);
            }
            ++n;
        }
        if (n > 0)
            std::printf("  %s (%zu px): RMSE %.5f with, %.5f without\n", label, n,
                        std::sqrt(sumOurs / double(3 * n)), std::sqrt(sumNone / double(3 * n)));
    }
}

int effect(const char* name, const fs::path& ours, const fs::path& none, const fs::path& truth,
           double maxRatio, const char* passes) {
    const ImageF reference = readExrFrame(truth).color;
    const ImageF withEffect = readExrFrame(ours).color;
    const ImageF without = readExrFrame(none).color;
    if (withEffect.width != reference.width || without.width != reference.width ||
        withEffect.height != reference.height || without.height != reference.height) {
        std::fprintf(stderr, "%s: the images differ in size\n", name);
        return 1;
    }
    const double effectError = rmse(withEffect, reference);
    const double noneError = rmse(without, reference);
    std::printf("%s against Cycles' own: RMSE %.5f with the effect, %.5f without (%.0f%%)\n", name,
                effectError, noneError, 100.0 * effectError / noneError);
    if (passes != nullptr)
        breakdown(withEffect, without, reference, passes);
    return effectError <= maxRatio * noneError ? 0 : 1;
}

/// Means over the (2r+1) x (2r+1) window around each pixel, of `value` where `inside` holds, with the count
/// of such pixels in the window (summed-area tables; the window clipped at the frame's edges).
struct WindowMeans {
    std::vector<double> mean;
    std::vector<int> count;
};

WindowMeans windowMeans(int w, int h, int r, const std::vector<double>& value,
                        const std::vector<char>& inside) {
    const std::size_t stride = std::size_t(w) + 1;
    std::vector<double> sums(stride * std::size_t(h + 1), 0.0);
    std::vector<int> counts(sums.size(), 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const std::size_t s = std::size_t(y + 1) * stride + std::size_t(x + 1);
            sums[s] = (inside[i] ? value[i] : 0.0) + sums[s - 1] + sums[s - stride] - sums[s - stride - 1];
            counts[s] = (inside[i] ? 1 : 0) + counts[s - 1] + counts[s - stride] - counts[s - stride - 1];
        }
    }
    WindowMeans out{std::vector<double>(value.size(), 0.0), std::vector<int>(value.size(), 0)};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t x0 = std::size_t(std::max(x - r, 0)), x1 = std::size_t(std::min(x + r + 1, w));
            const std::size_t y0 = std::size_t(std::max(y - r, 0)), y1 = std::size_t(std::min(y + r + 1, h));
            const auto box = [&](const auto& t) {
                return t[y1 * stride + x1] - t[y0 * stride + x1] - t[y1 * stride + x0] + t[y0 * stride + x0];
            };
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            out.count[i] = box(counts);
            out.mean[i] = out.count[i] > 0 ? box(sums) / double(out.count[i]) : 0.0;
        }
    }
    return out;
}

int ambientOcclusion(const fs::path& ours, const fs::path& passes, double maxBias, double maxOpenError) {
    const ImageF visibility = readExrFrame(ours).color;
    AovRequest request;
    request.overrides.push_back(parseAovOverride("color=AO"));
    const ExrFrame blender = readExrFrame(passes, {}, request);
    const std::size_t pixels = visibility.pixelCount();
    if (blender.depth.size() != pixels) {
        std::fprintf(stderr, "the passes have no depth of the visibility's size\n");
        return 1;
    }
    const int w = visibility.width;
    const int h = visibility.height;
    // Bias by Cycles' value and by place: the frame's border, and the neighbourhood of a depth edge (a
    // neighbour within 4 px 10% nearer or farther), where a depth buffer holds least of the scene.
    struct Band {
        const char* label;
        double sum = 0.0;
        std::size_t n = 0;
    };
    Band bands[] = {{"Cycles < 0.5"},
                    {"Cycles 0.5-0.8"},
                    {"Cycles 0.8-0.95"},
                    {"Cycles >= 0.95"},
                    {"within 8 px of the frame's border"},
                    {"within 4 px of a depth edge"},
                    {"elsewhere"}};
    const auto depthAt = [&](int x, int y) {
        return std::min(double(blender.depth[std::size_t(std::clamp(y, 0, h - 1)) * std::size_t(w) +
                                             std::size_t(std::clamp(x, 0, w - 1))]),
                        1e4);
    };
    double sum = 0.0;
    double absolute = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (!(blender.depth[i] < 1e4f))
            continue; // the sky: Cycles writes 0, GTAO 1
        const double reference = double(blender.color.rgba[4 * i]);
        const double d = double(visibility.rgba[4 * i]) - reference;
        sum += d;
        absolute += std::abs(d);
        ++n;
        Band& value = bands[reference < 0.5 ? 0 : reference < 0.8 ? 1 : reference < 0.95 ? 2 : 3];
        value.sum += d;
        ++value.n;
        const int x = int(i % std::size_t(w));
        const int y = int(i / std::size_t(w));
        bool edge = false;
        for (int dy = -4; dy <= 4 && !edge; ++dy)
            for (int dx = -4; dx <= 4 && !edge; ++dx)
                edge = std::abs(depthAt(x + dx, y + dy) - depthAt(x, y)) >
                       0.1 * std::min(depthAt(x + dx, y + dy), depthAt(x, y));
        const bool border = x < 8 || y < 8 || x >= w - 8 || y >= h - 8;
        Band& place = bands[border ? 4 : edge ? 5 : 6];
        place.sum += d;
        ++place.n;
    }
    const double bias = sum / double(n);
    std::printf("GTAO visibility against Cycles' AO pass over %zu surface pixels: mean absolute error %.4f, "
                "bias %+.4f\n",
                n, absolute / double(n), bias);
    for (const Band& band : bands) {
        if (band.n > 0)
            std::printf("  %s: bias %+.4f over %zu px\n", band.label, band.sum / double(band.n), band.n);
    }

    // Structure on open surfaces: both images averaged over 9 x 9 pixels (Cycles' sampling noise and GTAO's
    // grain average out; what is left is shading that varies over tens of pixels), compared where the window
    // holds only surface and Cycles' mean is at least 0.9. Bands that GTAO draws on open ground near objects,
    // and Cycles does not, show here rather than in the bias.
    const int r = 4;
    std::vector<char> surface(pixels);
    std::vector<double> gtao(pixels), cycles(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        surface[i] = blender.depth[i] < 1e4f ? 1 : 0;
        gtao[i] = double(visibility.rgba[4 * i]);
        cycles[i] = double(blender.color.rgba[4 * i]);
    }
    const WindowMeans gtaoMeans = windowMeans(w, h, r, gtao, surface);
    const WindowMeans cyclesMeans = windowMeans(w, h, r, cycles, surface);
    double openError = 0.0;
    std::size_t open = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        // A full count: the window lies inside the frame (the edges clip it) and holds only surface.
        const bool whole = cyclesMeans.count[i] == (2 * r + 1) * (2 * r + 1);
        if (whole && cyclesMeans.mean[i] >= 0.9) {
            openError += std::abs(gtaoMeans.mean[i] - cyclesMeans.mean[i]);
            ++open;
        }
    }
    openError = open > 0 ? openError / double(open) : 0.0;
    std::printf(
        "  open surfaces (Cycles' 9 x 9 mean >= 0.9): mean absolute error of the 9 x 9 means %.4f over %zu "
        "px (at most %.4f)\n",
        openError, open, maxOpenError);
    return std::abs(bias) <= maxBias && open > 0 && openError <= maxOpenError ? 0 : 1;
}

/// Pixels with a reflection in an `ssr` view: alpha (the confidence) above 0.
std::size_t reflectedPixels(const fs::path& view) {
    const ImageF image = readExrFrame(view).color;
    std::size_t n = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        n += image.rgba[i * 4 + 3] > 0.0f ? 1 : 0;
    }
    return n;
}

int reflections(const fs::path& ours, const fs::path& ample, double minShare) {
    const std::size_t found = reflectedPixels(ours);
    const std::size_t all = reflectedPixels(ample);
    const double share = all > 0 ? double(found) / double(all) : 0.0;
    std::printf(
        "  pixels with a reflection: %zu within the budget, %zu with an ample one: %.4f (at least %.4f)\n",
        found, all, share, minShare);
    return all > 0 && share >= minShare ? 0 : 1;
}

/// One RGB pass of a Blender file (`ViewLayer.<name>.R G B`) read as the colour.
ImageF blenderPass(const fs::path& file, const std::string& name) {
    AovRequest request;
    request.overrides.push_back(parseAovOverride("color=" + name));
    return readExrFrame(file, {}, request).color;
}

double luminance(const float* c) {
    return 0.2126 * double(c[0]) + 0.7152 * double(c[1]) + 0.0722 * double(c[2]);
}

/// SSR's reflected radiance against the mirror variant's ground, where Cycles' reflected radiance is
/// (GlossDir + GlossInd) / GlossCol. The ground is where the file's normal is straight up. Ground pixels
/// whose truth is the world's constant colour reflect the sky, the others an object: of those, the share SSR
/// covers (confidence above 0) and, of what it covers, the share within 10% in luminance; of the sky's, the
/// share SSR gives a reflection (a false hit).
int mirror(const fs::path& ours, const fs::path& passes, double minCovered, double minWithin,
           double maxFalse) {
    const ImageF view = readExrFrame(ours).color;
    const ImageF direct = blenderPass(passes, "GlossDir");
    const ImageF indirect = blenderPass(passes, "GlossInd");
    const ImageF weight = blenderPass(passes, "GlossCol");
    const std::vector<float> normals = readExrFrame(passes).normals; // world space, Y up
    const std::size_t pixels = view.pixelCount();
    if (direct.pixelCount() != pixels || indirect.pixelCount() != pixels || weight.pixelCount() != pixels ||
        normals.size() != pixels * 3) {
        std::fprintf(stderr, "the mirror passes and the ssr view differ in size\n");
        return 1;
    }
    constexpr float kSky[3] = {0.35f, 0.45f, 0.6f}; // the scene's world colour, strength 1
    std::size_t objects = 0, covered = 0, within = 0, sky = 0, falseHits = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const float* w = &weight.rgba[i * 4];
        if (normals[i * 3 + 1] < 0.999f || std::min({w[0], w[1], w[2]}) <= 0.0f) {
            continue; // not the ground (or a pixel without glossy weight)
        }
        float truth[3];
        bool isSky = true;
        for (int c = 0; c < 3; ++c) {
            truth[c] = (direct.rgba[i * 4 + std::size_t(c)] + indirect.rgba[i * 4 + std::size_t(c)]) / w[c];
            isSky = isSky && std::abs(truth[c] - kSky[c]) < 0.01f;
        }
        const float* v = &view.rgba[i * 4];
        const bool reflected = v[3] > 0.0f;
        if (isSky) {
            ++sky;
            falseHits += reflected ? 1 : 0;
            continue;
        }
        ++objects;
        if (reflected) {
            ++covered;
            const double t = luminance(truth);
            within += std::abs(luminance(v) - t) <= 0.1 * t ? 1 : 0;
        }
    }
    const double coveredShare = objects ? double(covered) / double(objects) : 0.0;
    const double withinShare = covered ? double(within) / double(covered) : 0.0;
    const double falseShare = sky ? double(falseHits) / double(sky) : 1.0;
    std::printf(
        "  mirror ground reflecting an object: %zu px, covered %.4f (at least %.4f), within 10%% of Cycles' "
        "%.4f (at least %.4f)\n",
        objects, coveredShare, minCovered, withinShare, minWithin);
    std::printf("  mirror ground reflecting the sky: %zu px, with a reflection %.4f (at most %.4f)\n", sky,
                falseShare, maxFalse);
    return objects > 0 && sky > 0 && coveredShare >= minCovered && withinShare >= minWithin &&
                   falseShare <= maxFalse
               ? 0
               : 1;
}

} // namespace

int main(int argc, char** argv) {
    try {
        if (argc >= 5 && std::strcmp(argv[1], "geometry") == 0) {
            std::vector<int> frames;
            for (int i = 4; i < argc; ++i)
                frames.push_back(std::atoi(argv[i]));
            return geometry(argv[2], argv[3], frames);
        }
        if ((argc == 7 || argc == 8) && std::strcmp(argv[1], "effect") == 0)
            return effect(argv[2], argv[3], argv[4], argv[5], std::atof(argv[6]),
                          argc == 8 ? argv[7] : nullptr);
        if (argc >= 5 && std::strcmp(argv[1], "probe") == 0) {
            // probe FILE X Y [X Y ...]: the colour at pixels (rows top to bottom), for looking into a
            // failure.
            const ImageF image = readExrFrame(argv[2]).color;
            for (int i = 3; i + 1 < argc; i += 2) {
                const int x = std::atoi(argv[i]);
                const int y = std::atoi(argv[i + 1]);
                const float* v =
                    &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
                std::printf("(%d, %d): %.5f %.5f %.5f %.5f\n", x, y, double(v[0]), double(v[1]), double(v[2]),
                            double(v[3]));
            }
            return 0;
        }
        if (argc == 6 && std::strcmp(argv[1], "ao") == 0)
            return ambientOcclusion(argv[2], argv[3], std::atof(argv[4]), std::atof(argv[5]));
        if (argc == 5 && std::strcmp(argv[1], "reflections") == 0)
            return reflections(argv[2], argv[3], std::atof(argv[4]));
        if (argc == 7 && std::strcmp(argv[1], "mirror") == 0)
            return mirror(argv[2], argv[3], std::atof(argv[4]), std::atof(argv[5]), std::atof(argv[6]));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    std::fprintf(
        stderr,
        "usage: %s geometry TRACK AUXDIR N... | effect NAME OURS NONE TRUTH MAX | ao OURS PASSES "
        "MAXBIAS MAXOPEN | reflections OURS AMPLE MINSHARE | mirror OURS MIRROR MINCOVERED MINWITHIN "
        "MAXFALSE\n",
        argv[0]);
    return 2;
}
