#include "gl/TextureIo.h"

#include <algorithm>

namespace photopic {

namespace {
template <class T>
void flipRows(std::vector<T>& data, int width, int height) {
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y) {
        std::swap_ranges(data.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         data.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         data.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row));
    }
}
} // namespace

Texture makeTexture(const ImageF& image, std::string_view debugName) {
    Texture t({.extent = {image.width, image.height}, .format = GL_RGBA32F, .debugName = debugName});
    t.uploadRgba32f(image.rgba.data());
    return t;
}

ImageF readTextureF(const Texture& texture) {
    ImageF image;
    readTextureF(texture, image);
    return image;
}

void readTextureF(const Texture& texture, ImageF& image) {
    image.width = texture.extent().width;
    image.height = texture.extent().height;
    image.rgba.resize(image.pixelCount() * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(image.rgba.size() * sizeof(float)),
                      image.rgba.data());
    flipRows(image.rgba, image.width, image.height);
}

std::vector<float> readDepthTexture(const Texture& texture) {
    const Extent e = texture.extent();
    std::vector<float> depth(std::size_t(e.width) * std::size_t(e.height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)),
                      depth.data());
    const auto row = std::size_t(e.width);
    for (int y = 0; y < e.height / 2; ++y) {
        std::swap_ranges(depth.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         depth.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         depth.begin() + std::ptrdiff_t(std::size_t(e.height - 1 - y) * row));
    }
    return depth;
}

Image8 readTexture8(const Texture& texture) {
    Image8 image;
    readTexture8(texture, image);
    return image;
}

void readTexture8(const Texture& texture, Image8& image) {
    image.width = texture.extent().width;
    image.height = texture.extent().height;
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(image.rgba.size()),
                      image.rgba.data());
    flipRows(image.rgba, image.width, image.height);
}

Image16 readTexture16(const Texture& texture) {
    Image16 image;
    readTexture16(texture, image);
    return image;
}

void readTexture16(const Texture& texture, Image16& image) {
    image.width = texture.extent().width;
    image.height = texture.extent().height;
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_SHORT,
                      GLsizei(image.rgba.size() * sizeof(std::uint16_t)), image.rgba.data());
    flipRows(image.rgba, image.width, image.height);
}

} // namespace photopic
