#include <gtest/gtest.h>

#include "core/animation_clock.h"

namespace reflect {
namespace {

TEST(AnimationClock, TurnsTwentySevenDegreesPerSecond) {
  AnimationClock clock;
  clock.advance(1.0);
  EXPECT_DOUBLE_EQ(clock.orbitDegrees(), 27.0);
  clock.set(10.0);
  EXPECT_DOUBLE_EQ(clock.orbitDegrees(), 270.0);
  clock.set(20.0);
  EXPECT_DOUBLE_EQ(clock.orbitDegrees(), 180.0);  // 540 wrapped
}

TEST(AnimationClock, SameTimeSameAngleWhateverTheFrameRate) {
  AnimationClock at60, at144;
  for (int i = 0; i < 60 * 4; ++i) at60.advance(1.0 / 60.0);
  for (int i = 0; i < 144 * 4; ++i) at144.advance(1.0 / 144.0);
  EXPECT_NEAR(at60.orbitDegrees(), 108.0, 1e-9);
  EXPECT_NEAR(at144.orbitDegrees(), 108.0, 1e-9);
}

TEST(AnimationClock, WrapsWithoutDriftAfterAMillionSeconds) {
  AnimationClock clock;
  clock.set(1e6);  // 27e6 degrees = 75000 turns exactly
  EXPECT_DOUBLE_EQ(clock.orbitDegrees(), 0.0);
  clock.set(1e6 + 1.0);
  EXPECT_NEAR(clock.orbitDegrees(), 27.0, 1e-6);
  clock.set(-1.0);
  EXPECT_DOUBLE_EQ(clock.orbitDegrees(), 333.0);
}

TEST(AnimationClock, IgnoresNegativeAndNonFiniteSteps) {
  AnimationClock clock;
  clock.advance(-5.0);
  clock.advance(std::numeric_limits<double>::infinity());
  clock.advance(std::numeric_limits<double>::quiet_NaN());
  clock.set(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(clock.seconds(), 0.0);
}

}  // namespace
}  // namespace reflect
