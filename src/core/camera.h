// The main camera: an eye that looks around by yaw and pitch, as the course's mouse drag does.
#pragma once

#include <glm/glm.hpp>

namespace reflect {

struct CameraSettings {
  glm::vec3 eye{0.0f, 1.0f, 7.0f};
  // The field of view along the narrower side of the target: vertical on a landscape or square
  // target (the course's 70 degrees), horizontal on a portrait one (see LookCamera::fovYDeg).
  float fovYDeg = 70.0f;
  float near = 1.0f;
  float far = 100.0f;
};

class LookCamera {
 public:
  // Pitch stops this far short of straight up/down, so the view never becomes parallel to up.
  static constexpr float kMaxPitchDeg = 89.0f;
  // The original turns 100 degrees per canvas height of drag.
  static constexpr float kDegreesPerCanvasHeight = 100.0f;
  // W/S move the eye this far along the view direction per key press.
  static constexpr float kMoveStep = 0.1f;

  explicit LookCamera(const CameraSettings& settings = {});

  // Pointer drag in the same units as canvasHeight (CSS pixels on the page).
  void drag(float dx, float dy, float canvasHeight);
  // Moves along the view direction by steps * kMoveStep (negative steps move back).
  void move(float steps);
  // Moves sideways, level with the ground, by steps * kMoveStep (positive: to the right of the
  // view; A/D on the page).
  void strafe(float steps);
  // Moves straight up by steps * kMoveStep (negative: down; Q/E on the page).
  void rise(float steps);
  void reset();

  glm::vec3 eye() const { return eye_; }
  float yawDeg() const { return yawDeg_; }
  float pitchDeg() const { return pitchDeg_; }
  void setAngles(float yawDeg, float pitchDeg);
  // Ignored when not finite (a shared link with garbage in it keeps the current eye).
  void setEye(const glm::vec3& eye);
  glm::vec3 viewDirection() const;
  glm::mat4 view() const;
  // aspect = width / height of the target; a non-finite or non-positive aspect falls back to 1.
  // A perspective of fovYDeg(aspect) vertically.
  glm::mat4 projection(float aspect) const;
  // The vertical field of view on a target of this aspect (width / height), in degrees. The
  // camera keeps its field of view along the narrower side: at aspect >= 1 the vertical field is
  // the setting (the course's framing); on a portrait target the horizontal field is, so the
  // vertical one is 2 atan(tan(setting / 2) / aspect) and a phone sees as wide as a square
  // window (up to 179 degrees). Everything that sizes things by the field of view (view LOD)
  // asks here. A bad aspect reads as 1.
  float fovYDeg(float aspect) const;

 private:
  CameraSettings settings_;
  glm::vec3 eye_;
  float yawDeg_ = 0.0f;
  float pitchDeg_ = 0.0f;
};

}  // namespace reflect
