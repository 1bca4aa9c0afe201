#include "scenes/SceneExr.h"

#include "gl/TextureIo.h"

namespace photopic {

ExrFrame exrFrameFromInputs(const FrameInputs& inputs) {
    ExrFrame frame;
    frame.color = readTextureF(*inputs.color);
    const int w = frame.color.width;
    const int h = frame.color.height;
    const std::size_t pixels = frame.color.pixelCount();
    const Camera* camera = inputs.camera;
    if (inputs.depth != nullptr && camera != nullptr) {
        if (inputs.depthKind == DepthKind::LinearView) {
            const ImageF linear = readTextureF(*inputs.depth);
            frame.depth.resize(pixels);
            for (std::size_t i = 0; i < pixels; ++i) {
                frame.depth[i] = linear.rgba[4 * i];
            }
        } else {
            frame.depth = readDepthTexture(*inputs.depth);
            for (float& d : frame.depth) {
                d = inputs.depthKind == DepthKind::Reversed
                        ? linearDepthFromReversed(d, camera->nearPlane, camera->farPlane)
                        : linearDepthFromWindow(d, camera->nearPlane, camera->farPlane);
            }
        }
    }
    if (inputs.normals != nullptr && camera != nullptr && inputs.normalEncoding == NormalEncoding::ViewXyz) {
        // View space -> world: the inverse of the view's rotation is its transpose.
        const glm::mat3 toWorld = glm::transpose(glm::mat3(camera->view));
        const ImageF n = readTextureF(*inputs.normals);
        frame.normals.resize(pixels * 3);
        for (std::size_t i = 0; i < pixels; ++i) {
            const glm::vec3 v(n.rgba[4 * i], n.rgba[4 * i + 1], n.rgba[4 * i + 2]);
            const glm::vec3 world = glm::dot(v, v) > 0.0f ? toWorld * v : glm::vec3(0.0f);
            frame.normals[3 * i] = world.x;
            frame.normals[3 * i + 1] = world.y;
            frame.normals[3 * i + 2] = world.z;
        }
    }
    if (inputs.motion != nullptr) {
        const ImageF m = readTextureF(*inputs.motion);
        frame.motion.resize(pixels * 2);
        for (std::size_t i = 0; i < pixels; ++i) {
            frame.motion[2 * i] = m.rgba[4 * i] * float(w);
            frame.motion[2 * i + 1] = -m.rgba[4 * i + 1] * float(h);
        }
    }
    if (camera != nullptr) {
        frame.camera = exrFromCamera(*camera, w, h);
    }
    frame.camera.sunDirection = inputs.sunDirection;
    return frame;
}

} // namespace photopic
