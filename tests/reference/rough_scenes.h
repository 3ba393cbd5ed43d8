// What the rough-surface tests share (rough_reference_test: mirrors and glass): a shipped scene
// with or without its roughness, a demo in the exact mode, and the reference with a given seed.
#pragma once

#include <memory>
#include <string>

#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect::testing {

// The shipped scene `name`; with roughnessZero, every object's roughness set to 0.
inline Scene shippedScene(const std::string& name, bool roughnessZero = false) {
  Result<Scene> scene = loadNamedScene(name);
  EXPECT_TRUE(scene) << scene.error();
  Scene s = scene ? scene.take() : Scene{};
  if (roughnessZero) {
    for (SceneObject& object : s.objects) object.roughness = 0.0f;
  }
  return s;
}

inline std::unique_ptr<Demo> exactDemo(const Scene& scene) {
  auto demo = makeDemo(scene);
  AccuracySettings exact;
  exact.search = Search::Exact;
  EXPECT_EQ(demo->setAccuracySettings(exact), "");
  return demo;
}

// Where and when a test's reference frames are made.
struct ReferenceShot {
  double time = 2.0;
  int width = 0;
  int height = 0;
};

inline ReferenceFrame referenceWithSeed(const Demo& demo, const ReferenceShot& shot, uint32_t seed,
                                        int lobeSamples = ReferenceOptions{}.lobeSamples) {
  ReferenceOptions options;
  options.seed = seed;
  options.lobeSamples = lobeSamples;
  auto frame = referenceFor(demo, shot.time, shot.width, shot.height, options);
  EXPECT_TRUE(frame) << frame.error();
  return frame ? frame.take() : ReferenceFrame{};
}

}  // namespace reflect::testing
