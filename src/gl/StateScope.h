#pragma once
// The host's GL state around a Pipeline call. A host calls Photopic from inside its own renderer, with its
// own framebuffer, program, viewport, culling, masks and bindings in place; the pipeline's passes draw
// full-screen triangles and dispatch compute shaders that assume the GL defaults. GlStateScope saves what
// the pipeline touches or depends on, sets the defaults the passes need, and puts the host's state back when
// it goes out of scope, so a call neither breaks under the host's state nor leaves the host's state changed.
//
// Saved and restored: draw and read framebuffers, viewport, scissor box, program, program pipeline, vertex
// array, active texture unit, the 2D texture and sampler bound to units [0, kUnits), image units
// [0, kUnits), indexed and generic uniform and shader-storage buffers [0, kUnits), the array, pixel pack
// and unpack, copy and dispatch-indirect buffers, pack/unpack alignment and row length, colour write mask
// (per draw buffer), depth write mask, polygon mode, clear colour; and these capabilities, which the scope
// switches off while it lives: scissor test, face culling, rasterizer discard, sRGB framebuffer writes,
// blending, depth test, stencil test, colour logic op, sample mask, alpha to coverage, primitive restart,
// depth clamp.

#include "gl/Gl.h"

#include <array>

namespace photopic {

class GlStateScope {
public:
    /// Texture, image and buffer binding points saved: every binding a pass uses is below this.
    static constexpr int kUnits = 16;

    GlStateScope();
    ~GlStateScope();
    GlStateScope(const GlStateScope&) = delete;
    GlStateScope& operator=(const GlStateScope&) = delete;

private:
    struct ImageUnit {
        GLint name = 0, level = 0, layered = 0, layer = 0, access = GL_READ_ONLY, format = GL_R8;
    };
    struct IndexedBuffer {
        GLint name = 0;
        GLint64 start = 0, size = 0;
    };

    /// How many of the kUnits image, uniform-buffer and storage-buffer binding points this context has
    /// (NVIDIA's driver has 8 image units; reaching past the limit is GL_INVALID_VALUE).
    int mImageUnits = 0, mUniformBufferUnits = 0, mStorageBufferUnits = 0;
    GLint mDrawFramebuffer = 0, mReadFramebuffer = 0;
    std::array<GLint, 4> mViewport{}, mScissorBox{};
    GLint mProgram = 0, mProgramPipeline = 0, mVertexArray = 0, mActiveTexture = GL_TEXTURE0;
    std::array<GLint, kUnits> mTextures{}, mSamplers{};
    std::array<ImageUnit, kUnits> mImages{};
    std::array<IndexedBuffer, kUnits> mUniformBuffers{}, mStorageBuffers{};
    GLint mUniformBuffer = 0, mStorageBuffer = 0, mArrayBuffer = 0, mPackBuffer = 0, mUnpackBuffer = 0;
    GLint mCopyReadBuffer = 0, mCopyWriteBuffer = 0, mDispatchIndirectBuffer = 0;
    GLint mPackAlignment = 4, mUnpackAlignment = 4, mPackRowLength = 0, mUnpackRowLength = 0;
    std::array<std::array<GLboolean, 4>, 8> mColorMasks{};
    GLint mDrawBuffers = 1;
    GLboolean mDepthMask = GL_TRUE;
    std::array<GLint, 2> mPolygonMode{GL_FILL, GL_FILL};
    std::array<GLfloat, 4> mClearColor{};
    std::array<GLboolean, 12> mCapabilities{};
};

} // namespace photopic
