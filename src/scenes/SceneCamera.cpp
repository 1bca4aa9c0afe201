#include "scenes/SceneCamera.h"

namespace photopic {

GpuSceneCamera sceneCameraBlock(const Camera& camera, glm::vec2 jitter, Extent e) {
    GpuSceneCamera c{};
    c.view = camera.view;
    c.invView = glm::inverse(camera.view);
    c.projection = jitteredProjection(camera.projection, jitter, e.width, e.height);
    c.viewProjection = c.projection * camera.view;
    c.currViewProj = camera.viewProjection();
    c.prevViewProj = camera.prevViewProjection;
    c.viewport = {float(e.width), float(e.height), 1.0f / float(e.width), 1.0f / float(e.height)};
    return c;
}

} // namespace photopic
