// Debug views (debug.view): scene-value views replace the image before tone mapping and are shown as they
// are; the histogram is an overlay that leaves the image outside its panel alone.

#include "GlTest.h"

#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

namespace photopic::test {

namespace {

/// Five columns of exposed values 0.5, 1.5, 3, 6, 10 (one per false-colour band), 10 px wide, 4 px high.
ImageF bandImage() {
    const float values[5] = {0.5f, 1.5f, 3.0f, 6.0f, 10.0f};
    ImageF image(50, 4, 1.0f);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = values[x / 10];
        }
    }
    return image;
}

Image8 render(DebugView view, const ImageF& image, Settings s = {}) {
    s.debug.view = view;
    s.output.dither = false;
    Pipeline p({.settings = s});
    const Texture input = makeTexture(image, "debug input");
    return readTexture8(p.execute({.color = &input}, {}));
}

} // namespace

TEST_F(GlTest, ExposureFalseColorBands) {
    const Image8 out = render(DebugView::Exposure, bandImage());
    const std::uint8_t expected[4][3] = {{255, 255, 0}, {255, 128, 0}, {255, 0, 255}, {255, 255, 255}};
    const std::uint8_t* below = out.at(5, 1);
    EXPECT_GT(below[2], below[0]) << "below 1: the blue ramp";
    for (int band = 0; band < 4; ++band) {
        const std::uint8_t* p = out.at(15 + 10 * band, 1);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p[c], expected[band][c], 1) << "band " << band << " channel " << c;
        }
    }
}

TEST_F(GlTest, LumaAndEvViewsAreNotToneMapped) {
    ImageF grey(8, 8, 0.18f);
    const Image8 luma = render(DebugView::Luma, grey);
    EXPECT_NEAR(luma.at(3, 3)[0], 118, 1) << "sRGB(0.18), no tone curve";
    const Image8 ev = render(DebugView::Ev, grey);
    EXPECT_NEAR(ev.at(3, 3)[0], 128, 1) << "middle grey is the grey stop";
    EXPECT_EQ(ev.at(3, 3)[0], ev.at(3, 3)[2]);
}

TEST_F(GlTest, MeteringViewShowsTheSpotDisc) {
    Settings s;
    s.debug.view = DebugView::Metering;
    s.autoExposure.metering = MeteringMode::Spot;
    s.autoExposure.spot = {.u = 0.25f, .v = 0.25f, .radius = 0.1f, .taps = 9};
    s.output.dither = false;
    Pipeline p({.settings = s});
    const Texture input = makeTexture(ImageF(64, 64, 0.18f), "grey");
    const Image8 out = readTexture8(p.execute({.color = &input}, {}));
    EXPECT_GT(out.at(16, 16)[0], 200) << "inside the disc (image top-left quadrant)";
    EXPECT_LT(out.at(16, 48)[0], 100) << "the mirrored point below is outside";
}

TEST_F(GlTest, HistogramOverlayLeavesTheImageOutsideItsPanel) {
    const ImageF image(96, 64, 0.3f);
    const Image8 plain = render(DebugView::None, image);
    const Image8 overlay = render(DebugView::Histogram, image);
    EXPECT_EQ(plain.at(50, 5)[0], overlay.at(50, 5)[0]) << "top of the image: untouched";
    int changed = 0;
    for (int x = 0; x < 96; ++x) {
        changed += plain.at(x, 50)[0] != overlay.at(x, 50)[0] ? 1 : 0;
    }
    EXPECT_GT(changed, 40) << "the panel at the bottom";
}

TEST_F(GlTest, BloomViewWithoutBloomIsBlack) {
    Settings s;
    s.bloom.enabled = false;
    const Image8 out = render(DebugView::Bloom, ImageF(8, 8, 2.0f), s);
    EXPECT_EQ(out.at(4, 4)[0], 0);
    EXPECT_EQ(out.at(4, 4)[1], 0);
}

TEST_F(GlTest, BloomViewCoversTheWholeFrame) {
    // The view brings the smaller bloom image up to every pixel (it once read the frame's pixel coordinates
    // in the half-size image, black past its edge on llvmpipe). The bloom of a uniform image is the light
    // arriving from the frame: uniform in the middle, less towards the edges and the same at every corner.
    const Image8 out = render(DebugView::Bloom, ImageF(96, 64, 2.0f), [] {
        Settings s;
        s.bloom.mipCount = 1; // a glow a few pixels wide: the middle is far from every edge
        return s;
    }());
    const std::uint8_t centre = out.at(48, 32)[1];
    EXPECT_GT(centre, 0);
    for (const auto& [x, y] : {std::pair{40, 28}, {56, 36}, {30, 20}}) {
        EXPECT_NEAR(out.at(x, y)[1], centre, 1) << x << "," << y;
    }
    const std::uint8_t corner = out.at(0, 0)[1];
    EXPECT_GT(corner, 0);
    EXPECT_LT(corner, centre);
    for (const auto& [x, y] : {std::pair{95, 0}, {0, 63}, {95, 63}}) {
        EXPECT_NEAR(out.at(x, y)[1], corner, 1) << x << "," << y;
    }
}

} // namespace photopic::test
