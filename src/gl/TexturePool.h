#pragma once
// Transient textures for one frame, pooled by description (format, extent, levels, sampling). A pass asks for
// its output when it runs; everything handed out returns to the pool when the next frame begins. After the
// first frame at a size, a steady-state frame creates no texture: the pool only grows when a frame asks for
// more textures of one description than any earlier frame did.

#include "gl/Objects.h"

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

namespace photopic {

/// A pooled texture and, for fragment passes, a framebuffer on its level 0 (made on first use).
class PooledTexture {
public:
    explicit PooledTexture(const TextureCreateInfo& info)
        : mTexture(info) {}
    [[nodiscard]] const Texture& texture() const { return mTexture; }
    /// The framebuffer that renders into level 0 (created the first time it is asked for).
    const Framebuffer& framebuffer();

private:
    friend class TexturePool;
    Texture mTexture;
    Framebuffer mFramebuffer;
    bool mInUse = false;
};

class TexturePool {
public:
    /// A texture matching `info` (its debug name aside) not yet handed out this frame; made only when none
    /// is free. The reference stays valid until clear().
    PooledTexture& acquire(const TextureCreateInfo& info);
    /// acquire()'s texture for one level sampled nearest (what texel fetches and image stores use).
    const Texture& acquireNearest(Extent extent, GLenum format, std::string_view debugName) {
        return acquire({.extent = extent,
                        .format = format,
                        .minFilter = GL_NEAREST,
                        .magFilter = GL_NEAREST,
                        .debugName = debugName})
            .texture();
    }
    /// Every texture handed out is free again (call once per frame, before the first pass).
    void beginFrame() noexcept;
    /// Deletes every texture (resize: the old sizes will not be asked for again).
    void clear() noexcept {
        mEntries.clear();
        mInfos.clear();
    }
    [[nodiscard]] std::size_t size() const noexcept { return mEntries.size(); }

private:
    std::vector<std::unique_ptr<PooledTexture>> mEntries;
    std::vector<TextureCreateInfo> mInfos; ///< parallel to mEntries, debug names dropped
};

} // namespace photopic
