// The smallest host: plain GL through <GL/gl.h> (its own "loader": the system's GL prototypes), a headless
// context from the library, its own HDR texture (a horizontal ramp over 0..8 scene-linear) handed over by
// name, and the display image delivered into a texture of its own and read back.

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <photopic/photopic.h>

#include <cstdio>
#include <vector>

int main() {
    try {
        photopic::HeadlessGlContext context; // a real host has its own context current instead
        constexpr int kWidth = 64, kHeight = 16;
        std::vector<float> pixels(kWidth * kHeight * 4);
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                float* p = &pixels[(y * kWidth + x) * 4];
                p[0] = p[1] = p[2] = 8.0f * float(x) / float(kWidth - 1);
                p[3] = 1.0f;
            }
        }
        // The host's textures, created with plain GL: the library only borrows them.
        GLuint hdr = 0, display = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &hdr);
        glTextureStorage2D(hdr, 1, GL_RGBA32F, kWidth, kHeight);
        glTextureSubImage2D(hdr, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, pixels.data());
        glCreateTextures(GL_TEXTURE_2D, 1, &display);
        glTextureStorage2D(display, 1, GL_RGBA8, kWidth, kHeight);

        // The check below is of the curve's range; bloom spreads the ramp's light as veiling glare and
        // would lift its black end.
        photopic::PostProcessor post({.settingsJson = R"({"version": 1, "postEffects": {
            "tonemapping": {"mode": "neutral"}, "bloom": {"enabled": false}}})"});
        post.execute({.color = hdr, .dt = 1.0f / 60, .frameIndex = 0}, photopic::TextureTarget{display});
        for (const std::string& e : post.status().inputErrors) {
            std::fprintf(stderr, "photopic_minimal: input error: %s\n", e.c_str());
        }

        std::vector<unsigned char> out(kWidth * kHeight * 4);
        glGetTextureImage(display, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(out.size()), out.data());
        const int dark = out[0], bright = out[(kWidth - 1) * 4];
        std::printf("photopic_minimal: photopic %s on %s, ramp 0..8 -> display %d..%d\n",
                    photopic::versionString(), context.renderer().c_str(), dark, bright);
        glDeleteTextures(1, &hdr);
        glDeleteTextures(1, &display);
        return (dark <= 2 && bright >= 230) ? 0 : 1;
    } catch (const photopic::Error& e) {
        std::fprintf(stderr, "photopic_minimal: %s\n", e.what());
        return 1;
    }
}
