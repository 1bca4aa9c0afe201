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

void restoreIndexed(GLenum target, int index, GLint name, GLint64 start, GLint64 size) {
    if (name != 0 && size > 0) {
        glBindBufferRange(target, GLuint(index), GLuint(name), GLintptr(start), GLsizeiptr(size));
    } else {
        glBindBufferBase(target, GLuint(index), GLuint(name));
    }
}

} // namespace

GlStateScope::GlStateScope() {
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
        ImageUnit& image = mImages[unit];
        image.name = integerAt(GL_IMAGE_BINDING_NAME, unit);
        image.level = integerAt(GL_IMAGE_BINDING_LEVEL, unit);
        image.layered = integerAt(GL_IMAGE_BINDING_LAYERED, unit);
        image.layer = integerAt(GL_IMAGE_BINDING_LAYER, unit);
        image.access = integerAt(GL_IMAGE_BINDING_ACCESS, unit);
        image.format = integerAt(GL_IMAGE_BINDING_FORMAT, unit);
        mUniformBuffers[unit] = {integerAt(GL_UNIFORM_BUFFER_BINDING, unit),
                                 integer64At(GL_UNIFORM_BUFFER_START, unit),
                                 integer64At(GL_UNIFORM_BUFFER_SIZE, unit)};
        mStorageBuffers[unit] = {integerAt(GL_SHADER_STORAGE_BUFFER_BINDING, unit),
                                 integer64At(GL_SHADER_STORAGE_BUFFER_START, unit),
                                 integer64At(GL_SHADER_STORAGE_BUFFER_SIZE, unit)};
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
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
        mCapabilities[i] = glIsEnabled(kCapabilities[i]);
        if (mCapabilities[i]) {
            glDisable(kCapabilities[i]);
        }
    }

    // The defaults the passes rely on.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glBindProgramPipeline(0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    for (int unit = 0; unit < kUnits; ++unit) {
        if (mSamplers[unit] != 0) {
            glBindSampler(GLuint(unit), 0);
        }
    }
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
    // A texture or sampler deleted while the scope was open (a pipeline texture the host had bound, freed
    // by the pipeline) is unbound by GL on deletion: rebinding its name would be an error, 0 is what GL left.
    for (int unit = 0; unit < kUnits; ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        const auto texture = GLuint(mTextures[unit]);
        glBindTexture(GL_TEXTURE_2D, texture != 0 && glIsTexture(texture) ? texture : 0u);
        const auto sampler = GLuint(mSamplers[unit]);
        glBindSampler(GLuint(unit), sampler != 0 && glIsSampler(sampler) ? sampler : 0u);
        const ImageUnit& image = mImages[unit];
        if (image.name != 0 && glIsTexture(GLuint(image.name))) {
            glBindImageTexture(GLuint(unit), GLuint(image.name), image.level, GLboolean(image.layered),
                               image.layer, GLenum(image.access), GLenum(image.format));
        } else {
            glBindImageTexture(GLuint(unit), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
        }
        restoreIndexed(GL_UNIFORM_BUFFER, unit, mUniformBuffers[unit].name, mUniformBuffers[unit].start,
                       mUniformBuffers[unit].size);
        restoreIndexed(GL_SHADER_STORAGE_BUFFER, unit, mStorageBuffers[unit].name,
                       mStorageBuffers[unit].start, mStorageBuffers[unit].size);
    }
    glActiveTexture(GLenum(mActiveTexture));
    // Indexed binds also set the generic binding point: the generic ones go back last.
    glBindBuffer(GL_UNIFORM_BUFFER, GLuint(mUniformBuffer));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(mStorageBuffer));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(mArrayBuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(mPackBuffer));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(mUnpackBuffer));
    glBindBuffer(GL_COPY_READ_BUFFER, GLuint(mCopyReadBuffer));
    glBindBuffer(GL_COPY_WRITE_BUFFER, GLuint(mCopyWriteBuffer));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, GLuint(mDispatchIndirectBuffer));
    glBindVertexArray(GLuint(mVertexArray));
    // A host may delete its current program and then call us: GL keeps it alive only while it is current,
    // so once our passes have used their own programs the name is gone and restoring it is an error.
    glUseProgram(mProgram != 0 && glIsProgram(GLuint(mProgram)) ? GLuint(mProgram) : 0u);
    glBindProgramPipeline(GLuint(mProgramPipeline));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(mDrawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(mReadFramebuffer));
    glViewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
    glScissor(mScissorBox[0], mScissorBox[1], mScissorBox[2], mScissorBox[3]);
}

} // namespace photopic
