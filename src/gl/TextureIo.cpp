#include "gl/TextureIo.h"

#include <algorithm>

namespace photopic {

namespace {
/// Turns GL's bottom-up rows of `channels` values into top-down rows, in place.
template <class T>
void flipRows(std::vector<T>& data, int width, int height, int channels) {
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height / 2; ++y) {
        std::swap_ranges(data.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         data.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         data.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row));
    }
}

/// Level 0 of `texture` as RGBA samples of GL type `type` into `image` (its storage kept when the size
/// matches), rows top to bottom.
template <class Image>
void readRgba(const Texture& texture, GLenum type, Image& image) {
    image.width = texture.extent().width;
    image.height = texture.extent().height;
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, type, GLsizei(image.rgba.size() * sizeof(image.rgba[0])),
                      image.rgba.data());
    flipRows(image.rgba, image.width, image.height, 4);
}
} // namespace

Texture makeTexture(const ImageF& image, std::string_view debugName, GLenum format) {
    Texture t({.extent = {image.width, image.height}, .format = format, .debugName = debugName});
    t.uploadRgba32f(image.rgba.data());
    return t;
}

ImageF readTextureF(const Texture& texture) {
    ImageF image;
    readTextureF(texture, image);
    return image;
}

void readTextureF(const Texture& texture, ImageF& image) {
    readRgba(texture, GL_FLOAT, image);
}

std::vector<float> readDepthTexture(const Texture& texture) {
    const Extent e = texture.extent();
    std::vector<float> depth(std::size_t(e.width) * std::size_t(e.height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)),
                      depth.data());
    flipRows(depth, e.width, e.height, 1);
    return depth;
}

std::vector<std::uint32_t> readTextureU32(const Texture& texture, int channels) {
    static constexpr GLenum kLayouts[] = {GL_RED_INTEGER, GL_RG_INTEGER, GL_RGB_INTEGER, GL_RGBA_INTEGER};
    const Extent e = texture.extent();
    std::vector<std::uint32_t> words(std::size_t(e.width) * std::size_t(e.height) * std::size_t(channels));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, kLayouts[channels - 1], GL_UNSIGNED_INT,
                      GLsizei(words.size() * sizeof(std::uint32_t)), words.data());
    flipRows(words, e.width, e.height, channels);
    return words;
}

Image8 readTexture8(const Texture& texture) {
    Image8 image;
    readTexture8(texture, image);
    return image;
}

void readTexture8(const Texture& texture, Image8& image) {
    readRgba(texture, GL_UNSIGNED_BYTE, image);
}

Image16 readTexture16(const Texture& texture) {
    Image16 image;
    readTexture16(texture, image);
    return image;
}

void readTexture16(const Texture& texture, Image16& image) {
    readRgba(texture, GL_UNSIGNED_SHORT, image);
}

} // namespace photopic
