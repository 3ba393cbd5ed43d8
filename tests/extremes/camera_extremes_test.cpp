// The camera at its limits: pitch at and past +/-90 degrees (set directly and by dragging), the
// view parallel to up that glm::lookAt cannot handle (and that LookCamera never produces), and
// zero-length inputs. Every result is finite, and the view matrix stays a rigid transform.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "core/camera.h"

namespace reflect {
namespace {

constexpr float kOrthoTolerance = 1e-5f;

bool allFinite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// Largest |(R R^T - I)_ij| of the view's rotation part: 0 for a rigid transform.
float orthonormalityError(const glm::mat4& view) {
  const glm::mat3 r(view);
  const glm::mat3 e = r * glm::transpose(r) - glm::mat3(1.0f);
  float worst = 0.0f;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::fabs(e[c][i]));
  return worst;
}

// The view is rigid, finite, looks along viewDirection(), and keeps at least 1 degree from up.
void expectSaneView(const LookCamera& camera, const std::string& what) {
  const glm::mat4 view = camera.view();
  ASSERT_TRUE(allFinite(view)) << what;
  EXPECT_LT(orthonormalityError(view), kOrthoTolerance) << what;
  const glm::vec3 d = camera.viewDirection();
  EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f) << what;
  // The camera looks down its -Z: the view's third row is -d.
  const glm::vec3 back(view[0][2], view[1][2], view[2][2]);
  EXPECT_LT(glm::length(back + d), 1e-5f) << what;
  EXPECT_LE(std::fabs(glm::dot(d, glm::vec3(0, 1, 0))), std::cos(glm::radians(1.0f)) + 1e-6f)
      << what;
  EXPECT_TRUE(allFinite(camera.projection(16.0f / 9.0f))) << what;
}

TEST(CameraExtremes, PitchAtAndBeyondNinetyDegreesIsClampedTo89) {
  const float pitches[] = {89.0f,
                           90.0f,
                           -90.0f,
                           90.0001f,
                           135.0f,
                           180.0f,
                           -270.0f,
                           1e6f,
                           -1e30f,
                           std::numeric_limits<float>::max(),
                           -std::numeric_limits<float>::max()};
  for (float yaw : {0.0f, 90.0f, -135.0f, 1e7f}) {
    for (float pitch : pitches) {
      LookCamera camera;
      camera.setAngles(yaw, pitch);
      const std::string what = "yaw " + std::to_string(yaw) + " pitch " + std::to_string(pitch);
      EXPECT_EQ(std::fabs(camera.pitchDeg()), LookCamera::kMaxPitchDeg) << what;
      EXPECT_EQ(camera.pitchDeg() > 0.0f, pitch > 0.0f) << what;
      EXPECT_LE(std::fabs(camera.yawDeg()), 180.0f) << what;
      expectSaneView(camera, what);
    }
  }
}

TEST(CameraExtremes, DraggingPastVerticalStopsAt89AndComesBackAtOnce) {
  LookCamera camera;
  // A thousand small drags upward: 1000 x 0.2 canvas heights = 20000 degrees requested.
  for (int i = 0; i < 1000; ++i) camera.drag(3.0f, 160.0f, 800.0f);
  EXPECT_EQ(camera.pitchDeg(), LookCamera::kMaxPitchDeg);
  expectSaneView(camera, "after dragging up");
  // No wind-up: the first drag back moves the view at once, by exactly what it asks.
  camera.drag(0.0f, -80.0f, 800.0f);  // -10 degrees
  EXPECT_NEAR(camera.pitchDeg(), 79.0f, 1e-4f);
  // One enormous drag down, and a drag on a one-pixel canvas.
  camera.drag(0.0f, -1e9f, 1.0f);
  EXPECT_EQ(camera.pitchDeg(), -LookCamera::kMaxPitchDeg);
  expectSaneView(camera, "after a huge drag down");
  camera.drag(0.0f, std::numeric_limits<float>::max(), 1e-30f);  // overflows to +inf: ignored
  EXPECT_EQ(camera.pitchDeg(), -LookCamera::kMaxPitchDeg);
  expectSaneView(camera, "after an overflowing drag");
}

TEST(CameraExtremes, GlmLookAtAlongUpIsNaNAndLookCameraNeverAsksForIt) {
  // glm::lookAt builds the side axis as normalize(cross(forward, up)); with forward parallel to
  // up the cross product is zero and normalize(0) = 0 * inversesqrt(0) = NaN: the whole view
  // matrix is NaN (documented here, not something to fix in glm).
  const glm::vec3 eye(0.0f, 1.0f, 7.0f);
  const glm::mat4 up = glm::lookAt(eye, eye + glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
  const glm::mat4 down = glm::lookAt(eye, eye + glm::vec3(0, -3, 0), glm::vec3(0, 1, 0));
  EXPECT_FALSE(allFinite(up));
  EXPECT_FALSE(allFinite(down));
  EXPECT_TRUE(std::isnan(up[0][0]));

  // LookCamera clamps pitch to 89 degrees, so forward and up are always >= 1 degree apart:
  // sweep pitch past the poles in fine steps at several yaws; every view is rigid and finite.
  float worstError = 0.0f;
  for (float yaw = -180.0f; yaw <= 180.0f; yaw += 22.5f) {
    for (float pitch = -100.0f; pitch <= 100.0f; pitch += 0.25f) {
      LookCamera camera;
      camera.setAngles(yaw, pitch);
      const glm::mat4 view = camera.view();
      ASSERT_TRUE(allFinite(view)) << "yaw " << yaw << " pitch " << pitch;
      worstError = std::max(worstError, orthonormalityError(view));
    }
  }
  EXPECT_LT(worstError, kOrthoTolerance);
  std::printf("LookCamera sweep: worst |R R^T - I| = %.3g\n", static_cast<double>(worstError));
}

TEST(CameraExtremes, ZeroLengthDragAndMoveChangeNothing) {
  LookCamera camera;
  camera.setAngles(33.0f, -12.0f);
  camera.move(5.0f);
  const glm::mat4 before = camera.view();
  const glm::vec3 eye = camera.eye();
  camera.drag(0.0f, 0.0f, 800.0f);
  camera.drag(0.0f, 0.0f, 1e-30f);
  camera.drag(-0.0f, 0.0f, 800.0f);
  camera.drag(5.0f, 5.0f, 0.0f);  // a zero-height canvas: ignored
  camera.move(0.0f);
  camera.move(-0.0f);
  EXPECT_EQ(camera.eye(), eye);
  EXPECT_EQ(camera.view(), before);  // bit for bit
  EXPECT_EQ(camera.yawDeg(), 33.0f);
  EXPECT_EQ(camera.pitchDeg(), -12.0f);
  // A denormal move is below float resolution at this eye: nothing moves either.
  camera.move(std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(camera.eye(), eye);
}

TEST(CameraExtremes, HugeMovesStayFiniteAndNonFiniteOnesAreIgnored) {
  LookCamera camera;
  camera.move(1e30f);  // 1e29 units along -Z
  ASSERT_TRUE(std::isfinite(camera.eye().z));
  EXPECT_FLOAT_EQ(camera.eye().z, 7.0f - 1e29f);
  EXPECT_TRUE(allFinite(camera.view()));
  expectSaneView(camera, "1e29 units from the origin");
  const glm::vec3 eye = camera.eye();
  camera.move(std::numeric_limits<float>::infinity());
  camera.move(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(camera.eye(), eye);
}

// The view's forward axis must be the camera's direction wherever the eye is. Measured: the
// angle between them, for eyes ever further from the origin, at an oblique direction.
TEST(CameraExtremes, ViewDirectionHoldsFarFromTheOrigin) {
  for (float distance : {1e2f, 1e4f, 1e5f, 1e6f, 1e8f}) {
    CameraSettings settings;
    settings.eye = glm::vec3(distance, 0.5f * distance, -0.7f * distance);
    LookCamera camera(settings);
    camera.setAngles(37.3f, -21.7f);
    const glm::mat4 view = camera.view();
    ASSERT_TRUE(allFinite(view)) << "eye at " << distance;
    const glm::vec3 forward = -glm::vec3(view[0][2], view[1][2], view[2][2]);
    const float angle =
        std::acos(std::min(1.0f, glm::dot(glm::normalize(forward), camera.viewDirection())));
    std::printf("eye at %.0e: view axis off the camera direction by %.3g degrees\n",
                static_cast<double>(distance), static_cast<double>(glm::degrees(angle)));
    EXPECT_LT(glm::degrees(angle), 0.01f) << "eye at " << distance;
    // And the eye maps to the view-space origin within float resolution at that distance.
    const glm::vec3 eyeInView(view * glm::vec4(settings.eye, 1.0f));
    EXPECT_LT(glm::length(eyeInView), 1e-6f * distance * 4.0f) << "eye at " << distance;
  }
}

TEST(CameraExtremes, ProjectionStaysFiniteForExtremeNearFar) {
  for (float nearPlane : {1e-3f, 1e-2f, 0.1f, 1.0f, 10.0f}) {
    for (float farPlane : {1e2f, 1e4f, 1e6f}) {
      CameraSettings settings;
      settings.near = nearPlane;
      settings.far = farPlane;
      LookCamera camera(settings);
      const glm::mat4 p = camera.projection(1.0f);
      ASSERT_TRUE(allFinite(p)) << nearPlane << " " << farPlane;
      // A point on the near plane maps to depth -1 and one on the far plane to +1 (NDC).
      const glm::vec4 n = p * glm::vec4(0, 0, -nearPlane, 1);
      const glm::vec4 f = p * glm::vec4(0, 0, -farPlane, 1);
      EXPECT_NEAR(n.z / n.w, -1.0f, 1e-4f);
      EXPECT_NEAR(f.z / f.w, 1.0f, 1e-4f);
    }
  }
}

}  // namespace
}  // namespace reflect
