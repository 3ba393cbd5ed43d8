#include "core/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace reflect {

LookCamera::LookCamera(const CameraSettings& settings) : settings_(settings), eye_(settings.eye) {}

void LookCamera::drag(float dx, float dy, float canvasHeight) {
  if (!(canvasHeight > 0.0f) || !std::isfinite(dx) || !std::isfinite(dy)) return;
  setAngles(yawDeg_ + dx * kDegreesPerCanvasHeight / canvasHeight,
            pitchDeg_ + dy * kDegreesPerCanvasHeight / canvasHeight);
}

void LookCamera::setAngles(float yawDeg, float pitchDeg) {
  if (!std::isfinite(yawDeg) || !std::isfinite(pitchDeg)) return;
  // Keep yaw small so float precision does not erode after long drags.
  yawDeg_ = std::remainder(yawDeg, 360.0f);
  pitchDeg_ = glm::clamp(pitchDeg, -kMaxPitchDeg, kMaxPitchDeg);
}

void LookCamera::setEye(const glm::vec3& eye) {
  if (std::isfinite(eye.x) && std::isfinite(eye.y) && std::isfinite(eye.z)) eye_ = eye;
}

void LookCamera::move(float steps) {
  if (!std::isfinite(steps)) return;
  eye_ += viewDirection() * (steps * kMoveStep);
}

void LookCamera::strafe(float steps) {
  if (!std::isfinite(steps)) return;
  // cross(view, up) normalised: level whatever the pitch, so looking down does not slow it.
  const float yaw = glm::radians(yawDeg_);
  eye_ += glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw)) * (steps * kMoveStep);
}

void LookCamera::rise(float steps) {
  if (!std::isfinite(steps)) return;
  eye_.y += steps * kMoveStep;
}

void LookCamera::reset() {
  eye_ = settings_.eye;
  yawDeg_ = 0.0f;
  pitchDeg_ = 0.0f;
}

glm::vec3 LookCamera::viewDirection() const {
  // The course computes Rx(pitch) * Ry(yaw) * (0,0,-1); at yaw 90 degrees that pitch turns about
  // the view axis and does nothing. Yaw after pitch, Ry(yaw) * Rx(pitch) * (0,0,-1), agrees with it
  // at yaw 0 and keeps pitch meaning "look up" in every direction.
  const float yaw = glm::radians(yawDeg_);
  const float pitch = glm::radians(pitchDeg_);
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::mat4 LookCamera::view() const {
  // Turned at the origin, then moved: lookAt(eye, eye + d) subtracts two nearly equal vectors and
  // loses d's low bits far from the origin (0.13 degrees off at 1e5 units, NaN by 1e8).
  return glm::lookAt(glm::vec3(0.0f), viewDirection(), glm::vec3(0.0f, 1.0f, 0.0f)) *
         glm::translate(glm::mat4(1.0f), -eye_);
}

float LookCamera::fovYDeg(float aspect) const {
  if (!std::isfinite(aspect) || !(aspect > 0.0f)) aspect = 1.0f;
  if (aspect >= 1.0f) return settings_.fovYDeg;
  // The horizontal field is the setting. Below aspect 0.006 (a sliver of a canvas) the vertical
  // one stops at 179 degrees, short of the half turn where tan(fov / 2) would flip sign.
  const float vertical =
      glm::degrees(2.0f * std::atan(std::tan(glm::radians(settings_.fovYDeg) * 0.5f) / aspect));
  return std::min(vertical, std::max(settings_.fovYDeg, 179.0f));
}

glm::mat4 LookCamera::projection(float aspect) const {
  if (!std::isfinite(aspect) || !(aspect > 0.0f)) aspect = 1.0f;
  return glm::perspective(glm::radians(fovYDeg(aspect)), aspect, settings_.near, settings_.far);
}

}  // namespace reflect
