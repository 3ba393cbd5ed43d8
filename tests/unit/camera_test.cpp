#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/camera.h"

namespace reflect {
namespace {

bool allFinite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

TEST(LookCamera, StartsAsTheCourseCamera) {
  LookCamera camera;
  EXPECT_EQ(camera.eye(), glm::vec3(0, 1, 7));
  EXPECT_EQ(camera.viewDirection(), glm::vec3(0, 0, -1));
  const glm::mat4 expected =
      glm::lookAt(glm::vec3(0, 1, 7), glm::vec3(0, 1, 6), glm::vec3(0, 1, 0));
  EXPECT_EQ(camera.view(), expected);
}

TEST(LookCamera, DragTurnsOneHundredDegreesPerCanvasHeight) {
  LookCamera camera;
  camera.drag(400.0f, 0.0f, 800.0f);
  EXPECT_FLOAT_EQ(camera.yawDeg(), 50.0f);
  camera.drag(0.0f, 80.0f, 800.0f);
  EXPECT_FLOAT_EQ(camera.pitchDeg(), 10.0f);
  // Positive yaw turns the view toward -X, as the course's Ry(angle) * (0, 0, -1) does.
  EXPECT_LT(camera.viewDirection().x, 0.0f);
  EXPECT_GT(camera.viewDirection().y, 0.0f);
}

TEST(LookCamera, PitchIsClampedShortOfTheVerticalAndViewStaysFinite) {
  LookCamera camera;
  for (float dy : {1e3f, 1e9f, -1e9f, 3e38f, -3e38f}) {
    camera.drag(0.0f, dy, 800.0f);
    EXPECT_LE(std::abs(camera.pitchDeg()), LookCamera::kMaxPitchDeg);
    EXPECT_TRUE(allFinite(camera.view())) << dy;
    EXPECT_NEAR(glm::length(camera.viewDirection()), 1.0f, 1e-6f);
    // The view direction never becomes parallel to up.
    EXPECT_LT(std::abs(camera.viewDirection().y), std::sin(glm::radians(89.5f)));
  }
}

TEST(LookCamera, IgnoresNonFiniteInputAndZeroHeight) {
  LookCamera camera;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  camera.drag(nan, 1.0f, 800.0f);
  camera.drag(1.0f, inf, 800.0f);
  camera.drag(10.0f, 10.0f, 0.0f);
  camera.move(nan);
  EXPECT_EQ(camera.yawDeg(), 0.0f);
  EXPECT_EQ(camera.pitchDeg(), 0.0f);
  EXPECT_EQ(camera.eye(), glm::vec3(0, 1, 7));
}

TEST(LookCamera, YawWrapsAndStaysSmall) {
  LookCamera camera;
  for (int i = 0; i < 10000; ++i) camera.drag(288.0f, 0.0f, 800.0f);  // 36 degrees, 1000 turns
  EXPECT_LE(std::abs(camera.yawDeg()), 180.0f);
  EXPECT_NEAR(camera.yawDeg(), 0.0f, 1e-3f);
  camera.drag(800.0f, 0.0f, 800.0f);  // +100 more
  EXPECT_NEAR(camera.yawDeg(), 100.0f, 1e-3f);
}

TEST(LookCamera, MoveGoesAlongTheViewDirection) {
  LookCamera camera;
  camera.move(1.0f);
  EXPECT_NEAR(camera.eye().z, 6.9f, 1e-6f);
  camera.move(-2.0f);
  EXPECT_NEAR(camera.eye().z, 7.1f, 1e-6f);
  camera.reset();
  EXPECT_EQ(camera.eye(), glm::vec3(0, 1, 7));
}

TEST(LookCamera, StrafeGoesLevelToTheRightAndRiseStraightUp) {
  LookCamera camera;
  camera.strafe(1.0f);  // looking down -Z, right is +X
  EXPECT_NEAR(camera.eye().x, 0.1f, 1e-6f);
  EXPECT_EQ(camera.eye().y, 1.0f);
  EXPECT_NEAR(camera.eye().z, 7.0f, 1e-6f);
  camera.reset();
  camera.setAngles(90.0f, -60.0f);  // looking down towards -X: right is -Z, still level
  camera.strafe(2.0f);
  EXPECT_NEAR(camera.eye().x, 0.0f, 1e-6f);
  EXPECT_EQ(camera.eye().y, 1.0f);
  EXPECT_NEAR(camera.eye().z, 6.8f, 1e-5f);
  // Right is perpendicular to the view and to up.
  camera.reset();
  camera.setAngles(33.0f, 20.0f);
  const glm::vec3 before = camera.eye();
  camera.strafe(1.0f);
  const glm::vec3 right = (camera.eye() - before) / LookCamera::kMoveStep;
  EXPECT_NEAR(glm::dot(right, camera.viewDirection()), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(right), 1.0f, 1e-5f);
  EXPECT_GT(glm::cross(camera.viewDirection(), glm::vec3(0, 1, 0)).x * right.x +
                glm::cross(camera.viewDirection(), glm::vec3(0, 1, 0)).z * right.z,
            0.0f);
  camera.reset();
  camera.rise(-3.0f);
  EXPECT_NEAR(camera.eye().y, 0.7f, 1e-6f);
  camera.strafe(std::numeric_limits<float>::infinity());
  camera.rise(std::numeric_limits<float>::quiet_NaN());
  EXPECT_NEAR(camera.eye().y, 0.7f, 1e-6f);
  EXPECT_EQ(camera.eye().x, 0.0f);
}

TEST(LookCamera, ProjectionFollowsAspectAndRejectsBadAspect) {
  LookCamera camera;
  const glm::mat4 wide = camera.projection(2.0f);
  const glm::mat4 square = camera.projection(1.0f);
  EXPECT_FLOAT_EQ(wide[0][0] * 2.0f, square[0][0]);
  EXPECT_FLOAT_EQ(wide[1][1], square[1][1]);
  EXPECT_EQ(camera.projection(0.0f), square);
  EXPECT_EQ(camera.projection(std::numeric_limits<float>::quiet_NaN()), square);
}

}  // namespace
}  // namespace reflect

#include "core/normal_matrix.h"

namespace reflect {
namespace {

TEST(NormalMatrix, IsTheInverseTransposeUpToScaleAndStaysFiniteWhenSingular) {
  const glm::mat3 m(
      glm::scale(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(1, 2, 3)), {100, 1, 100}));
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.9f, -0.2f));
  const glm::vec3 expected = glm::normalize(glm::inverseTranspose(m) * n);
  const glm::vec3 got = glm::normalize(normalMatrixOf(m) * n);
  EXPECT_NEAR(glm::distance(expected, got), 0.0f, 1e-5f);
  // A mirror keeps the normal pointing the same way as the inverse-transpose does.
  const glm::mat3 mirror(glm::scale(glm::mat4(1.0f), {-1, 1, 1}));
  EXPECT_NEAR(glm::distance(glm::normalize(normalMatrixOf(mirror) * n),
                            glm::normalize(glm::inverseTranspose(mirror) * n)),
              0.0f, 1e-6f);
  // S(1, 0, 1) flattens a plane in y = 0: its normal must stay +Y, finite.
  const glm::mat3 flat(glm::scale(glm::mat4(1.0f), {1, 0, 1}));
  EXPECT_EQ(glm::normalize(normalMatrixOf(flat) * glm::vec3(0, 1, 0)), glm::vec3(0, 1, 0));
  // All zero: a zero matrix (finite); the object covers no pixel anyway.
  const glm::mat3 zero(0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(normalMatrixOf(zero)[c], glm::vec3(0));
}

}  // namespace
}  // namespace reflect
