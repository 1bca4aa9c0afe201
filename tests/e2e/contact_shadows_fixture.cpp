// Test fixture for contact_shadows.sh: reads the `contact-shadows` debug view's EXR (raw visibility) and the
// testbed's `sun` truths, and prints figures by region for the script to check.
//
//   photopic_contact_shadows_fixture VIEW.exr CONTACT.exr FACING.exr
//
// CONTACT is the sun truth with occluders counted within the contact distance; FACING the sun truth with
// occluders counted within a tenth of a millimetre, which is 0 only where the surface faces away from the
// sun. Regions (R channel): open = CONTACT is 1 (lit, sky included); contact = CONTACT below 0.5 where FACING
// is 1 (shadowed by an occluder within the distance); away = FACING is 0. Prints one line per region, "REGION
// pixels=N mean=M", then "range=ok" or "range=bad" (every view value in [0, 1]).

#include "FixtureMain.h"
#include "io/ImageIO.h"

#include <cmath>
#include <cstdio>
#include <exception>

namespace {

using photopic::ImageF;

struct Region {
    long pixels = 0;
    double sum = 0.0;
    void add(float v) {
        ++pixels;
        sum += double(v);
    }
    void print(const char* name) const {
        std::printf("%s pixels=%ld mean=%.4f\n", name, pixels, pixels ? sum / double(pixels) : 0.0);
    }
};

int run(const char* viewPath, const char* contactPath, const char* facingPath) {
    const ImageF view = photopic::readImage(viewPath);
    const ImageF contact = photopic::readImage(contactPath);
    const ImageF facing = photopic::readImage(facingPath);
    if (view.width != contact.width || view.height != contact.height || view.width != facing.width ||
        view.height != facing.height) {
        std::fprintf(stderr, "the three images differ in size\n");
        return 1;
    }
    Region open, shadowed, away;
    bool inRange = true;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const float v = view.at(x, y)[0];
            inRange = inRange && v >= 0.0f && v <= 1.0f;
            const float c = contact.at(x, y)[0];
            const float f = facing.at(x, y)[0];
            if (f < 0.5f) {
                away.add(v);
            } else if (c >= 1.0f) {
                open.add(v);
            } else if (c < 0.5f) {
                shadowed.add(v);
            }
        }
    }
    open.print("open");
    shadowed.print("contact");
    away.print("away");
    std::printf("range=%s\n", inRange ? "ok" : "bad");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 3, "VIEW.exr CONTACT.exr FACING.exr",
                                       [&] { return run(argv[1], argv[2], argv[3]); });
}
