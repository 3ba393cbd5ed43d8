#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/camera.h"
#include "core/frustum.h"
#include "core/obj_loader.h"
#include "core/scene_file.h"

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

// The course's framing: 70 degrees vertically on a square or wider target, the matrix exactly as
// before the field of view followed the aspect (goldens at aspect 1 depend on it).
TEST(LookCamera, SquareAndWiderTargetsKeepTheVerticalFieldOfView) {
  LookCamera camera;
  for (float aspect : {1.0f, 4.0f / 3.0f, 16.0f / 9.0f, 2.0f, 1e4f}) {
    EXPECT_EQ(camera.fovYDeg(aspect), 70.0f) << aspect;
    EXPECT_EQ(camera.projection(aspect),
              glm::perspective(glm::radians(70.0f), aspect, 1.0f, 100.0f))
        << aspect;
  }
  CameraSettings narrow;
  narrow.fovYDeg = 40.0f;
  EXPECT_EQ(LookCamera(narrow).fovYDeg(1.5f), 40.0f);
}

// On a portrait target the horizontal field of view is the setting, so a phone sees as wide as a
// square window; the vertical field is 2 atan(tan(35 degrees) / aspect).
TEST(LookCamera, PortraitTargetsKeepTheHorizontalFieldOfView) {
  LookCamera camera;
  const double tanHalf = std::tan(35.0 * 3.14159265358979323846 / 180.0);
  for (float aspect : {0.999f, 0.9f, 390.0f / 844.0f, 0.25f}) {
    const double expectedDeg = 2.0 * std::atan(tanHalf / aspect) * 180.0 / 3.14159265358979323846;
    EXPECT_NEAR(camera.fovYDeg(aspect), expectedDeg, 1e-4) << aspect;
    EXPECT_GT(camera.fovYDeg(aspect), 70.0f) << aspect;
    const glm::mat4 p = camera.projection(aspect);
    // x_ndc = x_view * p[0][0] / -z: the half-width of the view at distance 1 is 1 / p[0][0].
    EXPECT_NEAR(1.0 / p[0][0], tanHalf, 1e-5) << aspect;
    EXPECT_NEAR(1.0 / p[1][1], tanHalf / aspect, 1e-5) << aspect;
    EXPECT_TRUE(allFinite(p)) << aspect;
  }
  // Continuous through aspect 1: nothing jumps as a window is narrowed past square.
  EXPECT_NEAR(camera.fovYDeg(0.99999f), 70.0f, 1e-3f);
  // A 390x844 phone: 113 degrees vertically for 70 across.
  EXPECT_NEAR(camera.fovYDeg(390.0f / 844.0f), 113.16f, 0.01f);
}

// Where the boxes of the course's scene land at t = 0: on a 390x844 phone every figure is in the
// frame (with the fixed 70-degree vertical field mario was cut off at the right edge), and a
// square window frames them as the course does.
TEST(ScreenBox, TheCoursesFiguresAreInTheFrameOnAPhone) {
  Result<Scene> scene = loadSceneFile(std::string(SCENE_DIR) + "/ex12-2.json");
  ASSERT_TRUE(scene) << scene.error();
  LookCamera camera(scene.value().camera);
  const auto boxesAt = [&](const glm::mat4& projection) {
    std::map<std::string, ScreenBox> boxes;
    for (const SceneObject& object : scene.value().objects) {
      if (object.mesh == "quad.obj") continue;  // the ground runs past every edge
      Result<LoadedMesh> mesh = loadObjFile(std::string(MODEL_DIR) + "/" + object.mesh);
      EXPECT_TRUE(mesh) << mesh.error();
      if (!mesh) continue;
      boxes[object.mesh] =
          screenBox(mesh.value().mesh.bounds, scene.value().modelMatrix(object, 0.0),
                    projection * camera.view());
    }
    return boxes;
  };
  const float phone = 390.0f / 844.0f;
  const auto boxes = boxesAt(camera.projection(phone));
  ASSERT_EQ(boxes.size(), 3u);
  for (const auto& [mesh, box] : boxes) {
    EXPECT_TRUE(box.inFront) << mesh;
    EXPECT_GE(box.x0, 0.0f) << mesh;
    EXPECT_LE(box.x1, 1.0f) << mesh;
    EXPECT_GE(box.y0, 0.0f) << mesh;
    EXPECT_LE(box.y1, 1.0f) << mesh;
    EXPECT_LT(box.x0, box.x1) << mesh;
    EXPECT_LT(box.y0, box.y1) << mesh;
  }
  // The sphere sits in the middle, mario right of it, sonic left.
  EXPECT_NEAR((boxes.at("sphere.obj").x0 + boxes.at("sphere.obj").x1) / 2, 0.5f, 1e-4f);
  EXPECT_GT(boxes.at("mario.obj").x0, boxes.at("sphere.obj").x1);
  EXPECT_LT(boxes.at("sonic.obj").x1, boxes.at("sphere.obj").x0);
  // The old rule, 70 degrees vertically whatever the aspect, put mario past the right edge.
  const auto fixed = boxesAt(glm::perspective(glm::radians(70.0f), phone, 1.0f, 100.0f));
  EXPECT_GT(fixed.at("mario.obj").x1, 1.0f);
  // A square view and a phone see the same horizontal extent: the same x fractions.
  const auto square = boxesAt(camera.projection(1.0f));
  for (const auto& [mesh, box] : boxes) {
    EXPECT_NEAR(square.at(mesh).x0, box.x0, 1e-5f) << mesh;
    EXPECT_NEAR(square.at(mesh).x1, box.x1, 1e-5f) << mesh;
  }
}

TEST(ScreenBox, CornersBehindTheEyeAreReported) {
  LookCamera camera;  // at (0, 1, 7) looking down -z
  const glm::mat4 viewProjection = camera.projection(1.0f) * camera.view();
  const Bounds unit{glm::vec3(-0.5f), glm::vec3(0.5f)};
  const ScreenBox ahead =
      screenBox(unit, glm::translate(glm::mat4(1.0f), {0, 1, 0}), viewProjection);
  EXPECT_TRUE(ahead.inFront);
  EXPECT_NEAR((ahead.x0 + ahead.x1) / 2, 0.5f, 1e-5f);
  EXPECT_NEAR((ahead.y0 + ahead.y1) / 2, 0.5f, 1e-5f);
  // Half the box behind the eye: not in front, the rectangle from the corners that are.
  const ScreenBox straddling =
      screenBox(unit, glm::translate(glm::mat4(1.0f), {0, 1, 7}), viewProjection);
  EXPECT_FALSE(straddling.inFront);
  const ScreenBox behind =
      screenBox(unit, glm::translate(glm::mat4(1.0f), {0, 1, 9}), viewProjection);
  EXPECT_FALSE(behind.inFront);
  EXPECT_EQ(behind.x0, 0.0f);
  EXPECT_EQ(behind.x1, 0.0f);
}

TEST(LookCamera, SliverTargetsStopShortOfAHalfTurn) {
  LookCamera camera;
  for (float aspect : {1e-3f, 1e-6f, 1e-30f}) {
    EXPECT_LE(camera.fovYDeg(aspect), 179.0f) << aspect;
    EXPECT_GT(camera.fovYDeg(aspect), 170.0f) << aspect;
    const glm::mat4 p = camera.projection(aspect);
    EXPECT_TRUE(allFinite(p)) << aspect;
    EXPECT_GT(p[1][1], 0.0f) << aspect;  // not flipped
  }
  for (float bad : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                    std::numeric_limits<float>::infinity()}) {
    EXPECT_EQ(camera.fovYDeg(bad), 70.0f) << bad;
  }
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

namespace reflect {
namespace {

TEST(NearPlaneReach, IsTheDistanceToTheNearPlanesCorners) {
  // A cube face: 90 degrees, square, near 1: the corners at (+-1, +-1, -1).
  EXPECT_NEAR(nearPlaneReach(glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 100.0f)),
              std::sqrt(3.0f), 1e-5f);
  // The default camera, 70 degrees tall on a 2:1 target, near 0.5.
  const float tanY = std::tan(glm::radians(35.0f)), tanX = 2.0f * tanY;
  EXPECT_NEAR(nearPlaneReach(glm::perspective(glm::radians(70.0f), 2.0f, 0.5f, 100.0f)),
              0.5f * std::sqrt(1.0f + tanX * tanX + tanY * tanY), 1e-5f);
  // Not a symmetric perspective: nothing is taken to be outside.
  EXPECT_EQ(nearPlaneReach(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 10.0f)), 0.0f);
  EXPECT_EQ(nearPlaneReach(glm::frustum(-1.0f, 2.0f, -1.0f, 1.0f, 1.0f, 10.0f)), 0.0f);
  EXPECT_EQ(nearPlaneReach(glm::mat4(1.0f)), 0.0f);
}

TEST(NearPlaneReach, DistanceToABoxIsZeroInsideIt) {
  const Bounds box{glm::vec3(-1.0f), glm::vec3(1.0f)};
  EXPECT_EQ(distanceToBox(glm::vec3(0.5f, 0.0f, -0.5f), box), 0.0f);
  EXPECT_FLOAT_EQ(distanceToBox(glm::vec3(4.0f, 0.0f, 0.0f), box), 3.0f);
  EXPECT_FLOAT_EQ(distanceToBox(glm::vec3(4.0f, 5.0f, 1.0f), box), 5.0f);  // (3, 4, 0) away
}

}  // namespace
}  // namespace reflect
