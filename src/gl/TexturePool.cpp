#include "gl/TexturePool.h"

namespace photopic {

namespace {
bool sameDescription(const TextureCreateInfo& a, const TextureCreateInfo& b) noexcept {
    return a.extent == b.extent && a.format == b.format && a.levels == b.levels &&
           a.minFilter == b.minFilter && a.magFilter == b.magFilter && a.wrap == b.wrap;
}
} // namespace

const Framebuffer& PooledTexture::framebuffer() {
    if (mFramebuffer.id() == 0) {
        mFramebuffer = Framebuffer(mTexture, 0, "pooled target");
    }
    return mFramebuffer;
}

PooledTexture& TexturePool::acquire(const TextureCreateInfo& info) {
    for (std::size_t i = 0; i < mEntries.size(); ++i) {
        if (!mEntries[i]->mInUse && sameDescription(mInfos[i], info)) {
            mEntries[i]->mInUse = true;
            return *mEntries[i];
        }
    }
    mEntries.push_back(std::make_unique<PooledTexture>(info));
    TextureCreateInfo key = info;
    key.debugName = {};
    mInfos.push_back(key);
    mEntries.back()->mInUse = true;
    return *mEntries.back();
}

void TexturePool::beginFrame() noexcept {
    for (auto& e : mEntries) {
        e->mInUse = false;
    }
}

} // namespace photopic
