// Benchmark frames: a natural image mirrored to any size.

#include "scenes/SyntheticHdr.h"

#include <gtest/gtest.h>

namespace photopic {
namespace {

/// A 3x2 image whose texels are all different: value 10 x + y in every channel.
ImageF numbered() {
    ImageF image(3, 2);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 4; ++c) {
                image.at(x, y)[c] = float(10 * x + y) + 0.25f * float(c);
            }
        }
    }
    return image;
}

} // namespace

TEST(BenchFrames, MirroredImageRepeatsWithEveryOtherCopyFlipped) {
    const ImageF image = numbered();
    const ImageF out = mirroredTo(image, 8, 5);
    ASSERT_EQ(out.width, 8);
    ASSERT_EQ(out.height, 5);
    // Along x: 0 1 2 | 2 1 0 | 0 1; along y: 0 1 | 1 0 | 0.
    const int xs[8] = {0, 1, 2, 2, 1, 0, 0, 1};
    const int ys[5] = {0, 1, 1, 0, 0};
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            for (int c = 0; c < 4; ++c) {
                EXPECT_EQ(out.at(x, y)[c], image.at(xs[x], ys[y])[c]) << x << "," << y << " channel " << c;
            }
        }
    }
}

TEST(BenchFrames, MirroredImageSmallerThanTheSourceIsItsCorner) {
    const ImageF image = numbered();
    const ImageF out = mirroredTo(image, 2, 1);
    ASSERT_EQ(out.width, 2);
    ASSERT_EQ(out.height, 1);
    EXPECT_EQ(out.at(0, 0)[0], image.at(0, 0)[0]);
    EXPECT_EQ(out.at(1, 0)[3], image.at(1, 0)[3]);
}

} // namespace photopic
