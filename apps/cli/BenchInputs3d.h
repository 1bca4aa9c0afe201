#pragma once
// The 3D inputs of the bench's frame (BenchInputs3d), for the passes that need them.

#include "core/Camera.h"
#include "core/Motion.h"
#include "gl/Objects.h"
#include "pipeline/Pipeline.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace photopic::cli {

/// Depth (R32F linear), view-space normals (RGBA16F, facing the camera), motion (RG16F: zero, or a uniform
/// motion to the right), a camera, a
/// sun and a sun shadow map for the benchmark frame: a wall 10 units away. The shadow map (1024 texels,
/// 32-bit float depth) is synthetic: an orthographic sun view 40 units across over the space between the
/// camera and the wall, with square casters of 64 texels in a checkerboard halfway along the light's depth,
/// so volumetric light's shadow-map march (mode auto) reads a map that shadows half its steps.
class BenchInputs3d {
public:
    /// `sunInView`: the sun ahead of the camera, near the image's centre, so volumetric light marches every
    /// sample of every pixel (its worst case); else behind it (contact shadows' worst case, see frame()).
    /// `motionPixels`: every pixel moves this many pixels a frame to the right (0: a still frame).
    /// `floor`: the lower part of the image is a floor kFloorDrop below the camera, its normal up, that meets
    /// the wall: mirror rays from it run up the screen towards the wall (screen-space reflections' long
    /// rays; the wall's rays leave the screen within a few cells).
    BenchInputs3d(int width, int height, bool sunInView, float motionPixels = 0.0f, bool floor = false)
        : mSunDirection(sunInView ? glm::normalize(glm::vec3(0.05f, 0.03f, -1.0f))
                                  : glm::normalize(glm::vec3(0.3f, 0.5f, 0.8f)))
        , mDepth({.extent = {width, height}, .format = GL_R32F, .debugName = "bench depth"})
        , mNormals({.extent = {width, height}, .format = GL_RGBA16F, .debugName = "bench normals"})
        , mMotion({.extent = {width, height}, .format = GL_RG16F, .debugName = "bench motion"})
        , mShadowMap({.extent = {kShadowMapSize, kShadowMapSize},
                      .format = GL_DEPTH_COMPONENT32F,
                      .debugName = "bench sun shadow map"}) {
        const float depth = 10.0f;
        glClearTexImage(mDepth.id(), 0, GL_RED, GL_FLOAT, &depth);
        // uv_prev = uv - motion: a pixel that moved right came from the left.
        const float motion[2] = {motionPixels / float(width), 0.0f};
        glClearTexImage(mMotion.id(), 0, GL_RG, GL_FLOAT, motion);
        const float facing[4] = {0.0f, 0.0f, 1.0f, 0.0f};
        glClearTexImage(mNormals.id(), 0, GL_RGBA, GL_FLOAT, facing);
        mCamera.projection = perspectiveProjection(mCamera.verticalFov, float(width) / float(height),
                                                   mCamera.nearPlane, mCamera.farPlane);
        if (floor) {
            // Row 0 is the image's bottom. A row's view ray (per unit of depth) falls by -ndcY * tan(fov /
            // 2); the floor is where it reaches kFloorDrop before the wall's depth.
            const float tanHalf = std::tan(0.5f * mCamera.verticalFov);
            const float up[4] = {0.0f, 1.0f, 0.0f, 0.0f};
            for (int y = 0; y < height; ++y) {
                const float fall = -((2.0f * float(y) + 1.0f) / float(height) - 1.0f) * tanHalf;
                const float floorDepth = fall > 0.0f ? kFloorDrop / fall : depth;
                if (floorDepth < depth) {
                    glClearTexSubImage(mDepth.id(), 0, 0, y, 0, width, 1, 1, GL_RED, GL_FLOAT, &floorDepth);
                    glClearTexSubImage(mNormals.id(), 0, 0, y, 0, width, 1, 1, GL_RGBA, GL_FLOAT, up);
                }
            }
        }
        mCamera.prevViewProjection = mCamera.viewProjection();
        std::vector<float> casters(std::size_t(kShadowMapSize) * kShadowMapSize);
        for (int y = 0; y < kShadowMapSize; ++y) {
            for (int x = 0; x < kShadowMapSize; ++x) {
                casters[std::size_t(y) * kShadowMapSize + std::size_t(x)] =
                    ((x / 64 + y / 64) % 2) ? 0.5f : 1.0f;
            }
        }
        glTextureSubImage2D(mShadowMap.id(), 0, 0, 0, kShadowMapSize, kShadowMapSize, GL_DEPTH_COMPONENT,
                            GL_FLOAT, casters.data());
        const glm::vec3 centre(0.0f, 0.0f, -5.0f);
        mShadowWorldToClip = glm::ortho(-20.0f, 20.0f, -20.0f, 20.0f, 0.0f, 40.0f) *
                             glm::lookAt(centre + 20.0f * mSunDirection, centre, glm::vec3(0.0f, 1.0f, 0.0f));
    }
    [[nodiscard]] FrameInputs frame(const Texture& color) const {
        return {.color = &color,
                .depth = &mDepth,
                .depthKind = DepthKind::LinearView,
                .normals = &mNormals,
                .motion = &mMotion,
                .camera = &mCamera,
                // Unless the sun is in view: behind the camera, up and to the right; the wall faces it, so
                // contact shadows march every step of every pixel (their worst case).
                .sunDirection = mSunDirection,
                .sunShadow = {.depth = &mShadowMap, .worldToClip = mShadowWorldToClip}};
    }

private:
    static constexpr int kShadowMapSize = 1024;
    static constexpr float kFloorDrop = 1.5f; ///< the floor's distance below the camera, scene units
    glm::vec3 mSunDirection;
    Texture mDepth;
    Texture mNormals;
    Texture mMotion;
    Texture mShadowMap;
    glm::mat4 mShadowWorldToClip{1.0f};
    Camera mCamera;
};

} // namespace photopic::cli
