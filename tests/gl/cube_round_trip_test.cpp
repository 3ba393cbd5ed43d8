// Catches flipped or swapped cube faces: a marker drawn in direction d from the probe centre must
// be what texture(cube, d) returns, for face centres, edges and corners. And the reflector must
// never appear in its own cube map.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

#include "app/headless_frames.h"
#include "cube_sampler.h"
#include "gfx/offscreen_target.h"
#include "gfx/shader_program.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

constexpr int kMaxDirections = 16;

// Flat colours: ambient 1 and nothing else, so a marker renders exactly its colour.
Scene markerScene() {
  Scene scene;
  scene.light.ambient = 1.0f;
  scene.light.diffuse = 0.0f;
  scene.light.specular = 0.0f;
  scene.clearColour = glm::vec3(0.0f);
  SceneObject sphere;
  sphere.mesh = "sphere.obj";
  sphere.placement = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  sphere.material = Material::Mirror;
  sphere.colour = glm::vec3(1.0f);
  scene.objects.push_back(sphere);
  return scene;
}

glm::u8vec3 toBytes(const glm::vec3& c) {
  return glm::u8vec3(glm::round(c * 255.0f));
}

void expectNear(const glm::u8vec3& got, const glm::u8vec3& want, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(int(got[c]), int(want[c]), 2)
        << what << ": got (" << int(got.r) << "," << int(got.g) << "," << int(got.b) << ")";
  }
}

TEST(CubeRoundTrip, MarkerInDirectionDIsWhatTheCubeReturnsForD) {
  const std::vector<glm::vec3> directions = {{1, 0, 0},   {-1, 0, 0}, {0, 1, 0},    {0, -1, 0},
                                             {0, 0, 1},   {0, 0, -1}, {1, 1, 0},    {-1, 0, 1},
                                             {0, -1, -1}, {1, 1, 1},  {-1, -1, -1}, {1, -1, 1}};
  const std::vector<glm::vec3> colours = {{1, 0, 0},     {0, 1, 0}, {0, 0, 1},     {1, 1, 0},
                                          {1, 0, 1},     {0, 1, 1}, {1, 0.5, 0},   {0.5, 0, 1},
                                          {0, 0.5, 0.5}, {1, 1, 1}, {0.5, 0.5, 0}, {0.5, 1, 0.5}};
  Scene scene = markerScene();
  const glm::vec3 centre(0.0f, 0.25f, 0.0f);  // sphere.obj's bounds centre (0, 0.5, 0) x 0.5
  for (size_t i = 0; i < directions.size(); ++i) {
    SceneObject marker;
    marker.mesh = "cube.obj";
    marker.placement =
        glm::scale(glm::translate(glm::mat4(1.0f), centre + 4.0f * glm::normalize(directions[i])),
                   glm::vec3(0.4f));
    marker.colour = colours[i];
    scene.objects.push_back(marker);
  }
  auto demo = testing::makeCapturingDemo(scene);
  auto frame = renderFrameAt(*demo, 0.0, 64, 64);  // runs the capture
  ASSERT_TRUE(frame) << frame.error();

  std::vector<glm::vec3> lookups = directions;
  lookups.push_back({0.3f, -1.0f, 0.8f});  // between markers: the clear colour
  const auto sampled = testing::sampleCube(demo->environmentTexture(), lookups);
  for (size_t i = 0; i < directions.size(); ++i) {
    expectNear(sampled[i], toBytes(colours[i]), "direction " + std::to_string(i));
  }
  expectNear(sampled.back(), glm::u8vec3(0), "empty direction");
}

TEST(CubeRoundTrip, TheReflectorNeverAppearsInItsOwnCubeMap) {
  Scene scene = markerScene();  // only the (white) mirror sphere, around the probe centre
  auto demo = testing::makeCapturingDemo(scene);
  ASSERT_TRUE(renderFrameAt(*demo, 0.0, 64, 64));
  std::vector<glm::vec3> lookups;
  for (int i = 0; i < kMaxDirections; ++i) {
    const float a = 0.7f * static_cast<float>(i);
    lookups.push_back({std::cos(a), std::sin(1.3f * a), std::sin(a)});
  }
  for (const glm::u8vec3& c : testing::sampleCube(demo->environmentTexture(), lookups)) {
    expectNear(c, glm::u8vec3(0), "reflector drawn into its own capture");
  }
}

}  // namespace
}  // namespace reflect
