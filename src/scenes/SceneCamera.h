#pragma once
// The camera at the head of the built-in 3D scenes' frame uniform blocks (the testbed's TestbedFrame and the
// orbit scene's OrbitFrame begin with these members, in this order).

#include "core/Camera.h"
#include "gl/Objects.h"

#include <glm/glm.hpp>

namespace photopic {

/// std140: six matrices and the viewport, 400 bytes, the first members of each scene's frame block.
struct GpuSceneCamera {
    glm::mat4 view;
    glm::mat4 invView;
    glm::mat4 projection;     ///< jittered
    glm::mat4 viewProjection; ///< jittered
    glm::mat4 currViewProj;   ///< unjittered (motion)
    glm::mat4 prevViewProj;   ///< unjittered, previous frame
    glm::vec4 viewport;       ///< width, height, 1 / width, 1 / height
};
static_assert(sizeof(GpuSceneCamera) == 6 * 64 + 16);

/// The block of `camera` drawn with the sub-pixel `jitter` on a target of extent `e`.
[[nodiscard]] GpuSceneCamera sceneCameraBlock(const Camera& camera, glm::vec2 jitter, Extent e);

} // namespace photopic
