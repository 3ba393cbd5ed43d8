// The accuracy settings' description (the sweep's `setting` column) reads back as the settings.
#include <gtest/gtest.h>

#include "core/accuracy_settings.h"

namespace reflect {
namespace {

TEST(AccuracySettings, EveryDescriptionReadsBackAsItsSettings) {
  int combinations = 0;
  for (bool origin : {false, true}) {
    for (int distance : {0, 1, 2, 16}) {
      for (int depth : {16, 24}) {
        for (bool mipmaps : {false, true}) {
          for (bool halfFloat : {false, true}) {
            for (bool mediump : {false, true}) {
              AccuracySettings a;
              a.captureAtOrigin = origin;
              a.distanceIterations = distance;
              a.depthBits = depth;
              a.mipmaps = mipmaps;
              a.halfFloat = halfFloat;
              a.mediump = mediump;
              AccuracySettings back;
              back.depthBits = 0;  // overwritten
              ASSERT_TRUE(parseAccuracyDescription(a.describe(), &back)) << a.describe();
              EXPECT_TRUE(back == a) << a.describe();
              ++combinations;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(combinations, 2 * 4 * 2 * 2 * 2 * 2);
}

TEST(AccuracySettings, PartsNotGivenKeepTheirDefaults) {
  AccuracySettings a;
  ASSERT_TRUE(parseAccuracyDescription("origin, mipmapped", &a));
  AccuracySettings expected;
  expected.captureAtOrigin = true;
  expected.mipmaps = true;
  EXPECT_TRUE(a == expected);
}

TEST(AccuracySettings, UnknownPartsAreRefusedAndChangeNothing) {
  AccuracySettings a;
  a.depthBits = 16;
  const AccuracySettings before = a;
  for (const char* text : {"", "centre, blurry", "distance x", "distance xy", "depth",
                           "centre,,plain", "depth 99999"}) {
    EXPECT_FALSE(parseAccuracyDescription(text, &a)) << text;
    EXPECT_TRUE(a == before) << text;
  }
}

}  // namespace
}  // namespace reflect
