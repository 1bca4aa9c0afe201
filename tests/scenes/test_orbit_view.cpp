// OrbitView: the orbit and zoom steps an interactive host applies to a 3D scene's camera.

#include "scenes/InteractiveCamera.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace photopic {
namespace {

OrbitView view() {
    OrbitView v;
    v.eye = {1.0f, 2.0f, 7.0f};
    v.target = {1.0f, 1.0f, 2.0f};
    return v;
}

TEST(OrbitView, OrbitKeepsTheDistanceAndTheTarget) {
    OrbitView v = view();
    const float d = v.distance();
    v.orbit(0.7f, -0.3f);
    EXPECT_NEAR(v.distance(), d, 1e-4f);
    EXPECT_EQ(v.target, view().target);
    EXPECT_GT(glm::length(v.eye - view().eye), 0.5f);
}

TEST(OrbitView, OrbitAndItsInverseReturnTheEye) {
    OrbitView v = view();
    v.orbit(0.4f, 0.25f);
    v.orbit(-0.4f, -0.25f);
    EXPECT_LT(glm::length(v.eye - view().eye), 1e-4f);
}

TEST(OrbitView, PositiveYawMovesTheEyeToTheCamerasRightAndPitchUp) {
    OrbitView v;
    v.eye = {0.0f, 0.0f, 5.0f}; // looking down -z: the camera's right is +x
    v.target = {0.0f, 0.0f, 0.0f};
    v.orbit(0.1f, 0.0f);
    EXPECT_GT(v.eye.x, 0.4f);
    EXPECT_NEAR(v.eye.y, 0.0f, 1e-5f);
    v.orbit(0.0f, 0.1f);
    EXPECT_GT(v.eye.y, 0.4f);
}

TEST(OrbitView, PitchStopsShortOfThePoles) {
    OrbitView v = view();
    v.orbit(0.0f, 10.0f);
    const glm::vec3 dir = glm::normalize(v.eye - v.target);
    EXPECT_LT(dir.y, 1.0f);
    EXPECT_NEAR(std::asin(dir.y), std::numbers::pi_v<float> / 2.0f - OrbitView::kPoleMargin, 1e-3f);
}

TEST(OrbitView, ZoomScalesTheDistanceWithinItsBounds) {
    OrbitView v = view();
    const float d = v.distance();
    v.zoom(0.5f);
    EXPECT_NEAR(v.distance(), d * 0.5f, 1e-4f);
    v.zoom(1e-9f);
    EXPECT_NEAR(v.distance(), v.minDistance, 1e-5f);
    v.zoom(1e12f);
    EXPECT_NEAR(v.distance(), v.maxDistance, 1e-2f);
}

TEST(OrbitView, BadStepsAreIgnored) {
    OrbitView v = view();
    v.zoom(0.0f);
    v.zoom(-2.0f);
    v.zoom(std::nanf(""));
    v.orbit(std::nanf(""), 0.0f);
    v.orbit(0.0f, INFINITY);
    EXPECT_EQ(v.eye, view().eye);
}

} // namespace
} // namespace photopic
