#include "gl/StateScope.h"

#include <algorithm>

namespace photopic {

namespace {

/// The capabilities the scope switches off while it lives, in the order mCapabilities keeps them.
constexpr std::array<GLenum, 12> kCapabilities{
    GL_SCISSOR_TEST,
    GL_CULL_FACE,
    GL_RASTERIZER_DISCARD,
    GL_FRAMEBUFFER_SRGB,
    GL_BLEND,
    GL_DEPTH_TEST,
    GL_STENCIL_TEST,
    GL_COLOR_LOGIC_OP,
    GL_SAMPLE_MASK,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_PRIMITIVE_RESTART,
    GL_DEPTH_CLAMP,
};

GLint integer(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

GLint integerAt(GLenum name, int index) {
    GLint value = 0;
    glGetIntegeri_v(name, GLuint(index), &value);
    return value;
}

GLint64 integer64At(GLenum name, int index) {
    GLint64 value = 0;
    glGetInteger64i_v(name, GLuint(index), &value);
    return value;
}

/// `name` if it still names an object (`isObject`, a glIs* query), else 0. An object the host had bound can
/// be deleted while the scope lives (a texture the pipeline owned and freed, a program the host deleted while
/// it was current); deleting a bound object unbinds it, so 0 is what the host's binding would be had the
/// scope not been there, and binding a deleted name is an error.
template <class IsObject>
GLuint alive(GLint name, IsObject isObject) {
    return name != 0 && isObject(GLuint(name)) ? GLuint(name) : 0;
}

GLuint aliveBuffer(GLint name) {
    return alive(name, [](GLuint n) { return glIsBuffer(n); });
}

GLuint aliveTexture(GLint name) {
    return alive(name, [](GLuint n) { return glIsTexture(n); });
}

void restoreIndexed(GLenum target, int index, GLint name, GLint64 start, GLint64 size) {
    name = GLint(aliveBuffer(name));
    if (name != 0 && size > 0) {
        glBindBufferRange(target, GLuint(index), GLuint(name), GLintptr(start), GLsizeiptr(size));
    } else {
        glBindBufferBase(target, GLuint(index), GLuint(name));
    }
}

/// Image unit `unit`'s binding, into the scope's record of it.
template <class ImageUnit>
void readImageUnit(ImageUnit& image, int unit) {
    image.name = integerAt(GL_IMAGE_BINDING_NAME, unit);
    image.level = integerAt(GL_IMAGE_BINDING_LEVEL, unit);
    image.layered = integerAt(GL_IMAGE_BINDING_LAYERED, unit);
    image.layer = integerAt(GL_IMAGE_BINDING_LAYER, unit);
    image.access = integerAt(GL_IMAGE_BINDING_ACCESS, unit);
    image.format = integerAt(GL_IMAGE_BINDING_FORMAT, unit);
}

/// An indexed buffer binding (buffer, start, size) of `unit`.
template <class IndexedBuffer>
IndexedBuffer readIndexed(GLenum binding, GLenum start, GLenum size, int unit) {
    return {integerAt(binding, unit), integer64At(start, unit), integer64At(size, unit)};
}

/// Each of kCapabilities switched off, whether it was on kept in `enabled`.
void disableCapabilities(std::array<GLboolean, kCapabilities.size()>& enabled) {
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
        enabled[i] = glIsEnabled(kCapabilities[i]);
        if (enabled[i]) {
            glDisable(kCapabilities[i]);
        }
    }
}

/// The defaults the passes rely on; `samplers` the host's sampler objects by unit, unbound.
template <std::size_t Units>
void setPassDefaults(const std::array<GLint, Units>& samplers) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glBindProgramPipeline(0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    for (std::size_t unit = 0; unit < Units; ++unit) {
        if (samplers[unit] != 0) {
            glBindSampler(GLuint(unit), 0);
        }
    }
}

} // namespace

GlStateScope::GlStateScope() {
    mImageUnits = std::clamp(integer(GL_MAX_IMAGE_UNITS), 0, kUnits);
    mUniformBufferUnits = std::clamp(integer(GL_MAX_UNIFORM_BUFFER_BINDINGS), 0, kUnits);
    mStorageBufferUnits = std::clamp(integer(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS), 0, kUnits);
    mDrawFramebuffer = integer(GL_DRAW_FRAMEBUFFER_BINDING);
    mReadFramebuffer = integer(GL_READ_FRAMEBUFFER_BINDING);
    glGetIntegerv(GL_VIEWPORT, mViewport.data());
    glGetIntegerv(GL_SCISSOR_BOX, mScissorBox.data());
    mProgram = integer(GL_CURRENT_PROGRAM);
    mProgramPipeline = integer(GL_PROGRAM_PIPELINE_BINDING);
    mVertexArray = integer(GL_VERTEX_ARRAY_BINDING);
    mActiveTexture = integer(GL_ACTIVE_TEXTURE);
    for (int unit = 0; unit < kUnits; ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        mTextures[unit] = integer(GL_TEXTURE_BINDING_2D);
        mSamplers[unit] = integer(GL_SAMPLER_BINDING);
        if (unit < mImageUnits) {
            readImageUnit(mImages[unit], unit);
        }
        if (unit < mUniformBufferUnits) {
            mUniformBuffers[unit] = readIndexed<IndexedBuffer>(
                GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE, unit);
        }
        if (unit < mStorageBufferUnits) {
            mStorageBuffers[unit] =
                readIndexed<IndexedBuffer>(GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
                                           GL_SHADER_STORAGE_BUFFER_SIZE, unit);
        }
    }
    glActiveTexture(GL_TEXTURE0);
    mUniformBuffer = integer(GL_UNIFORM_BUFFER_BINDING);
    mStorageBuffer = integer(GL_SHADER_STORAGE_BUFFER_BINDING);
    mArrayBuffer = integer(GL_ARRAY_BUFFER_BINDING);
    mPackBuffer = integer(GL_PIXEL_PACK_BUFFER_BINDING);
    mUnpackBuffer = integer(GL_PIXEL_UNPACK_BUFFER_BINDING);
    mCopyReadBuffer = integer(GL_COPY_READ_BUFFER_BINDING);
    mCopyWriteBuffer = integer(GL_COPY_WRITE_BUFFER_BINDING);
    mDispatchIndirectBuffer = integer(GL_DISPATCH_INDIRECT_BUFFER_BINDING);
    mPackAlignment = integer(GL_PACK_ALIGNMENT);
    mUnpackAlignment = integer(GL_UNPACK_ALIGNMENT);
    mPackRowLength = integer(GL_PACK_ROW_LENGTH);
    mUnpackRowLength = integer(GL_UNPACK_ROW_LENGTH);
    mDrawBuffers = std::clamp(integer(GL_MAX_DRAW_BUFFERS), 1, int(mColorMasks.size()));
    for (int i = 0; i < mDrawBuffers; ++i) {
        glGetBooleani_v(GL_COLOR_WRITEMASK, GLuint(i), mColorMasks[i].data());
    }
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mDepthMask);
    glGetIntegerv(GL_POLYGON_MODE, mPolygonMode.data());
    glGetFloatv(GL_COLOR_CLEAR_VALUE, mClearColor.data());
    disableCapabilities(mCapabilities);
    setPassDefaults(mSamplers);
}

GlStateScope::~GlStateScope() {
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
        if (mCapabilities[i]) {
            glEnable(kCapabilities[i]);
        } else {
            glDisable(kCapabilities[i]);
        }
    }
    glClearColor(mClearColor[0], mClearColor[1], mClearColor[2], mClearColor[3]);
    glPolygonMode(GL_FRONT_AND_BACK, GLenum(mPolygonMode[0]));
    glDepthMask(mDepthMask);
    for (int i = 0; i < mDrawBuffers; ++i) {
        const auto& m = mColorMasks[i];
        glColorMaski(GLuint(i), m[0], m[1], m[2], m[3]);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, mPackAlignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, mUnpackAlignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, mPackRowLength);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, mUnpackRowLength);
    for (int unit = 0; unit < kUnits; ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, aliveTexture(mTextures[unit]));
        glBindSampler(GLuint(unit), alive(mSamplers[unit], [](GLuint n) { return glIsSampler(n); }));
        if (unit < mImageUnits) {
            const ImageUnit& image = mImages[unit];
            if (const GLuint name = aliveTexture(image.name); name != 0) {
                glBindImageTexture(GLuint(unit), name, image.level, GLboolean(image.layered), image.layer,
                                   GLenum(image.access), GLenum(image.format));
            } else {
                glBindImageTexture(GLuint(unit), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
            }
        }
        if (unit < mUniformBufferUnits) {
            restoreIndexed(GL_UNIFORM_BUFFER, unit, mUniformBuffers[unit].name, mUniformBuffers[unit].start,
                           mUniformBuffers[unit].size);
        }
        if (unit < mStorageBufferUnits) {
            restoreIndexed(GL_SHADER_STORAGE_BUFFER, unit, mStorageBuffers[unit].name,
                           mStorageBuffers[unit].start, mStorageBuffers[unit].size);
        }
    }
    glActiveTexture(GLenum(mActiveTexture));
    // Indexed binds also set the generic binding point: the generic ones go back last.
    glBindBuffer(GL_UNIFORM_BUFFER, aliveBuffer(mUniformBuffer));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, aliveBuffer(mStorageBuffer));
    glBindBuffer(GL_ARRAY_BUFFER, aliveBuffer(mArrayBuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, aliveBuffer(mPackBuffer));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, aliveBuffer(mUnpackBuffer));
    glBindBuffer(GL_COPY_READ_BUFFER, aliveBuffer(mCopyReadBuffer));
    glBindBuffer(GL_COPY_WRITE_BUFFER, aliveBuffer(mCopyWriteBuffer));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, aliveBuffer(mDispatchIndirectBuffer));
    glBindVertexArray(alive(mVertexArray, [](GLuint n) { return glIsVertexArray(n); }));
    glUseProgram(alive(mProgram, [](GLuint n) { return glIsProgram(n); }));
    glBindProgramPipeline(alive(mProgramPipeline, [](GLuint n) { return glIsProgramPipeline(n); }));
    const auto isFramebuffer = [](GLuint n) { return glIsFramebuffer(n); };
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, alive(mDrawFramebuffer, isFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, alive(mReadFramebuffer, isFramebuffer));
    glViewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
    glScissor(mScissorBox[0], mScissorBox[1], mScissorBox[2], mScissorBox[3]);
}

} // namespace photopic
