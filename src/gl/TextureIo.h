#pragma once
// CPU images <-> GL textures. Rows are flipped on the way in and out so image pixel (x, y) (top-left origin)
// is texel (x, height-1-y) (GL's bottom-left origin) and images read back as they went in.

#include "core/Image.h"
#include "gl/Objects.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace photopic {

/// A texture holding `image` (sampling only; no render-target capability needed): RGBA32F, or `format`
/// (e.g. GL_RGBA16F, which the upload rounds to).
Texture makeTexture(const ImageF& image, std::string_view debugName, GLenum format = GL_RGBA32F);
/// Blocking read of level 0 as float RGBA (offline paths: CLI, tests).
ImageF readTextureF(const Texture& texture);
/// Blocking read of level 0 of a depth texture (GL_DEPTH_COMPONENT*): width*height window depths, rows top
/// to bottom like the images.
std::vector<float> readDepthTexture(const Texture& texture);
/// Blocking read of level 0 of an unsigned integer texture (R32UI, RG32UI, ...) as `channels` (1 to 4) words
/// a texel, rows top to bottom like the images.
std::vector<std::uint32_t> readTextureU32(const Texture& texture, int channels);
/// Blocking read of level 0 as 8-bit RGBA.
Image8 readTexture8(const Texture& texture);
/// Blocking read of level 0 as 16-bit RGBA (unorm: 65535 is 1.0). Of an RGBA16 texture, the stored values; of
/// an RGBA8 one, each value times 257.
Image16 readTexture16(const Texture& texture);
/// readTextureF, readTexture8 and readTexture16 into an image whose storage is kept when it already has the
/// texture's size, so a sequence read back frame after frame allocates nothing after its first frame.
void readTextureF(const Texture& texture, ImageF& into);
void readTexture8(const Texture& texture, Image8& into);
void readTexture16(const Texture& texture, Image16& into);

} // namespace photopic
