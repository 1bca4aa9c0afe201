#include "passes/HistoryTexture.h"

namespace photopic {

void HistoryTexture::ensure(Extent extent, GLenum format, std::string_view debugName) {
    if (mTextures[0].valid() && mTextures[0].extent() == extent && mTextures[0].format() == format) {
        return;
    }
    const std::string name(debugName);
    for (int i = 0; i < 2; ++i) {
        mTextures[std::size_t(i)] = Texture(
            {.extent = extent, .format = format, .debugName = name + (i == 0 ? " (ping)" : " (pong)")});
    }
    mCurrent = 0;
    mValid = false;
}

} // namespace photopic
