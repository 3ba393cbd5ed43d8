// Scene time in seconds. The course adds 0.45 degrees per displayed frame (27 degrees a second at
// 60 Hz); the port turns on time instead, so any frame rate and any test at time T agree.
#pragma once

#include <cmath>

namespace reflect {

class AnimationClock {
 public:
  static constexpr double kOrbitDegreesPerSecond = 27.0;

  // Times whose angle would overflow (beyond DBL_MAX / 27 seconds) are refused like non-finite
  // ones: fmod(inf, 360) is NaN.
  void advance(double dtSeconds) {
    if (std::isfinite(dtSeconds) && dtSeconds > 0.0) set(seconds_ + dtSeconds);
  }
  void set(double seconds) {
    if (std::isfinite(seconds * kOrbitDegreesPerSecond)) seconds_ = seconds;
  }
  double seconds() const { return seconds_; }
  // Wrapped into [0, 360) in double precision before it becomes a float angle.
  double orbitDegrees() const {
    double a = std::fmod(seconds_ * kOrbitDegreesPerSecond, 360.0);
    return a < 0.0 ? a + 360.0 : a;
  }

 private:
  double seconds_ = 0.0;
};

}  // namespace reflect
