#include "scenes/SceneTargets.h"

#include <string>

namespace photopic {

void SceneTargets::resize(Extent extent, std::string_view name) {
    if (mColor.valid() && mColor.extent() == extent) {
        return;
    }
    const std::string prefix(name);
    const auto target = [&](GLenum format, const char* what) {
        return Texture({.extent = extent,
                        .format = format,
                        .minFilter = GL_NEAREST,
                        .magFilter = GL_NEAREST,
                        .debugName = prefix + " " + what});
    };
    mColor = Texture({.extent = extent, .format = GL_RGBA16F, .debugName = prefix + " colour"});
    mDepth = target(GL_DEPTH_COMPONENT32F, "depth");
    mNormals = target(GL_RGBA16F, "normals");
    mMotion = target(GL_RG16F, "motion");
    mObjectId = target(GL_R32UI, "object ids");
    mMaterial = target(GL_RGBA16F, "material");
    mFramebuffer = Framebuffer({.color = {&mColor, &mNormals, &mMotion, &mObjectId, &mMaterial},
                                .depth = &mDepth,
                                .debugName = prefix + " targets"});
}

void SceneTargets::bindAndClear() const {
    mFramebuffer.bind();
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (const int i : {0, 1, 2, 4}) {
        glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, i, zero);
    }
    const GLuint noObject[4] = {0, 0, 0, 0};
    glClearNamedFramebufferuiv(mFramebuffer.id(), GL_COLOR, 3, noObject);
    const float far = 1.0f;
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &far);
}

} // namespace photopic
