#pragma once
// A pass's temporal history: two textures used ping-pong (read last frame's, write this frame's), owned by
// the pass that keeps it. The pipeline invalidates every pass's history on resize, on a camera cut and on
// Pipeline::reset(); an invalid history must not be read (the pass takes the current frame alone).

#include "gl/Objects.h"

#include <array>
#include <string>

namespace photopic {

class HistoryTexture {
public:
    HistoryTexture() = default;
    /// Makes (or remakes, when the size or format changed) both textures; the history is invalid after.
    void ensure(Extent extent, GLenum format, std::string_view debugName);
    /// Last frame's output, or nullptr when there is none to reuse (first frame, resize, cut, reset).
    [[nodiscard]] const Texture* previous() const { return mValid ? &mTextures[mCurrent ^ 1] : nullptr; }
    /// This frame's output target.
    [[nodiscard]] const Texture& current() const { return mTextures[mCurrent]; }
    /// Call once this frame's output is written: it becomes next frame's previous().
    void advance() {
        mCurrent ^= 1;
        mValid = true;
    }
    void invalidate() { mValid = false; }
    [[nodiscard]] bool valid() const { return mValid; }

private:
    std::array<Texture, 2> mTextures;
    int mCurrent = 0;
    bool mValid = false;
};

} // namespace photopic
