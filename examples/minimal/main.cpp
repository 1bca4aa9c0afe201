// The smallest host: makes its own headless GL context, creates its own HDR texture (a horizontal ramp over
// 0..8 scene-linear), hands it to the pipeline by id (adopted, not owned), and reads the display image back.

#include <photopic/gl/Context.h>
#include <photopic/gl/TextureIo.h>
#include <photopic/pipeline/Pipeline.h>

#include <cstdio>
#include <vector>

int main() {
    try {
        photopic::HeadlessContext context; // a real host would have its own context current instead
        constexpr int kWidth = 64, kHeight = 16;
        std::vector<float> pixels(kWidth * kHeight * 4);
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                float* p = &pixels[(y * kWidth + x) * 4];
                p[0] = p[1] = p[2] = 8.0f * float(x) / float(kWidth - 1);
                p[3] = 1.0f;
            }
        }
        // The host's texture, created with plain GL: the pipeline only borrows it.
        GLuint hostTexture = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &hostTexture);
        glTextureStorage2D(hostTexture, 1, GL_RGBA32F, kWidth, kHeight);
        glTextureSubImage2D(hostTexture, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, pixels.data());
        const auto input = photopic::Texture::adopt(hostTexture, {kWidth, kHeight}, GL_RGBA32F);

        photopic::Settings settings;
        settings.tonemapping.mode = photopic::ToneMapper::Neutral;
        // The check below is of the curve's range; bloom (on by default) spreads the ramp's light as veiling
        // glare and would lift its black end.
        settings.bloom.enabled = false;
        photopic::Pipeline pipeline({.settings = settings});
        const photopic::Texture& display =
            pipeline.execute({.color = &input}, {.dt = 1.0f / 60, .frameIndex = 0});
        const photopic::Image8 out = photopic::readTexture8(display);

        const unsigned char* dark = out.at(0, 0);
        const unsigned char* bright = out.at(kWidth - 1, 0);
        std::printf("photopic_minimal: %s, ramp 0..8 -> display %d..%d\n", context.info().renderer.c_str(),
                    dark[0], bright[0]);
        glDeleteTextures(1, &hostTexture); // still valid after the pipeline used it: the host owns it
        return (dark[0] <= 2 && bright[0] >= 230) ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic_minimal: %s\n", e.what());
        return 1;
    }
}
