// Test fixture for dof.sh: reads the `coc` debug view's EXR (raw values: red the near CoC radius, blue the
// far one, over dof.maxCocRadius) and the testbed's `depth` truth, and compares the view with the thin-lens
// CoC of the depth for the lens the script rendered with.
//
//   photopic_dof_fixture VIEW.exr DEPTH.exr FNUMBER SENSOR_HEIGHT_MM FOCUS_M MAX_COC_PX
//
// The lens's focal length follows the sensor height and the testbed's 45-degree field of view. Pixels whose
// 3x3 depth neighbourhood varies by more than 1% are left out (an edge, where the rasteriser's depth and the
// truth's pixel-centre depth may belong to different surfaces). Prints "compared=N near=N far=N
// maxError=E" (E in pixels), then "colours=ok" or "colours=bad" (G always 0, never both R and B).

#include "FixtureMain.h"
#include "core/DepthOfField.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

namespace {

using photopic::ImageF;

bool smooth(const ImageF& depth, int x, int y) {
    const float z = depth.at(x, y)[0];
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int qx = std::clamp(x + dx, 0, depth.width - 1),
                      qy = std::clamp(y + dy, 0, depth.height - 1);
            const float q = depth.at(qx, qy)[0];
            if (std::isinf(z) != std::isinf(q) || (!std::isinf(z) && std::abs(q - z) > 0.01f * z)) {
                return false;
            }
        }
    }
    return true;
}

int run(char** argv) {
    const ImageF view = photopic::readImage(argv[1]);
    const ImageF depth = photopic::readImage(argv[2]);
    if (view.width != depth.width || view.height != depth.height) {
        std::fprintf(stderr, "the images differ in size\n");
        return 1;
    }
    photopic::Lens lens;
    lens.fNumber = std::strtof(argv[3], nullptr);
    lens.sensorHeightMm = std::strtof(argv[4], nullptr);
    lens.focusDistance = std::strtof(argv[5], nullptr);
    lens.focalLengthMm = 0.5f * lens.sensorHeightMm / std::tan(0.5f * 0.785398163f);
    photopic::DofSettings settings;
    settings.maxCocRadius = std::strtof(argv[6], nullptr);
    const photopic::CocModel model = photopic::cocModel(settings, lens, view.height);
    long compared = 0, nearCount = 0, farCount = 0;
    double maxError = 0.0;
    bool colours = true;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const float* p = view.at(x, y);
            colours = colours && p[1] == 0.0f && (p[0] == 0.0f || p[2] == 0.0f);
            if (!smooth(depth, x, y)) {
                continue;
            }
            const float expected = model.radius(depth.at(x, y)[0]);
            const float got = (p[2] - p[0]) * settings.maxCocRadius;
            maxError = std::max(maxError, double(std::abs(got - expected)));
            ++compared;
            nearCount += expected < -1.0f ? 1 : 0;
            farCount += expected > 1.0f ? 1 : 0;
        }
    }
    std::printf("compared=%ld near=%ld far=%ld maxError=%.4f\n", compared, nearCount, farCount, maxError);
    std::printf("colours=%s\n", colours ? "ok" : "bad");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 6,
                                       "VIEW.exr DEPTH.exr FNUMBER SENSOR_HEIGHT_MM FOCUS_M MAX_COC_PX",
                                       [&] { return run(argv); });
}
