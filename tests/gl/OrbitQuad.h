#pragma once
// A one-quad orbit model and a camera looking at it, for the tests that drive OrbitRenderer directly: the
// quad spans [-1, 1]^2 at z = 0 facing +z (texture coordinates 0..1 across it), the camera sits at z = 2.

#include "core/Camera.h"
#include "scenes/orbit/GltfModel.h"

#include <glm/gtc/matrix_transform.hpp>

namespace photopic::test {

/// One mesh of one two-triangle primitive drawn with material 0 (the caller adds the materials).
inline orbit::MeshInstance orbitQuad() {
    orbit::MeshInstance quad;
    orbit::Primitive p;
    for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        p.vertices.push_back(
            {.position = glm::vec3(c, 0.0f), .normal = {0, 0, 1}, .texCoord = c * 0.5f + 0.5f});
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    quad.primitives.push_back(p);
    return quad;
}

/// A still camera on the quad's axis, 2 units away, filling a square target with it.
inline Camera orbitQuadCamera() {
    Camera camera;
    camera.view = glm::lookAt(glm::vec3(0.0f, 0.0f, 2.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    camera.projection = perspectiveProjection(0.6f, 1.0f, 0.1f, 100.0f);
    camera.prevViewProjection = camera.viewProjection();
    return camera;
}

} // namespace photopic::test
