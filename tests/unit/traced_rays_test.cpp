// core/traced_rays.h: the rays the exact tracer casts, counted exactly for a corridor of two
// facing mirrors, where every ray's fate is worked out by hand below and no ray passes within
// half a unit of an edge that would decide it.
#include <gtest/gtest.h>

#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "core/traced_rays.h"

namespace reflect {
namespace {

// A 2 x 2 square in the z = 0 plane, facing +z.
std::shared_ptr<const MeshBvh> squareTree() {
  MeshData square;
  square.name = "square";
  for (const glm::vec2& p :
       {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
    square.vertices.push_back({glm::vec3(p, 0.0f), {0, 0, 1}});
  square.indices = {0, 1, 2, 0, 2, 3};
  square.bounds = computeBounds(square.vertices);
  return std::make_shared<const MeshBvh>(buildMeshBvh(std::make_shared<const MeshData>(square)));
}

// Mirrors in the planes x = -1 and x = +1, facing each other, 100 x 100 (z from -50 to 50).
// With `wall`, a matte wall across the corridor at z = -20.
Scene corridor(bool wall) {
  Scene scene;
  for (const float x : {-1.0f, 1.0f}) {
    SceneObject mirror;
    mirror.mesh = "square";
    mirror.material = Material::Mirror;
    mirror.placement = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), {x, 0.0f, 0.0f}),
                                              glm::radians(90.0f), {0, 1, 0}),
                                  {50.0f, 50.0f, 1.0f});
    scene.objects.push_back(mirror);
  }
  if (wall) {
    SceneObject matte;
    matte.mesh = "square";
    matte.placement =
        glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -20.0f}), {5.0f, 50.0f, 1.0f});
    scene.objects.push_back(matte);
  }
  return scene;
}

// 8 x 8 pixels from the origin down -z, 70 degrees: column c's rays go sideways by
// s = |c - 3.5| / 4 * tan(35 deg) a unit of depth: 0.0875, 0.2626, 0.4376 and 0.6127 from the
// middle out, whatever the row. Each meets the mirrors at depths (2k - 1) / s, k = 1, 2, ...
TracedRayCount countIn(const Scene& scene, const TracedObject& traced) {
  const auto tree = squareTree();
  CameraSettings settings;
  settings.eye = {0.0f, 0.0f, 0.0f};
  return countTracedRays(
      scene, 0.0, [&](const std::string&) { return tree; }, LookCamera(settings), 8, 8, traced);
}

bool everyObject(int) {
  return true;
}

TEST(TracedRays, FacingMirrorsAreFollowedUpToTheBounceLimit) {
  const TracedRayCount count = countIn(corridor(false), everyObject);
  // Every pixel sees a mirror. The middle two columns meet the mirrors at depths 11.4 and 34.3
  // (the next, 57.1, is past the mirrors' end at 50): 2 rays. The other six meet them more than
  // five times within 50: the pixel's reflection and kMaxBounces = 4 followed ones, 5 rays.
  EXPECT_EQ(count.mirrorPixels, 64);
  EXPECT_EQ(count.unmodelled, 0);
  EXPECT_EQ(count.pixelsWithRays[2], 16);
  EXPECT_EQ(count.pixelsWithRays[5], 48);
  EXPECT_EQ(count.rays, 16 * 2 + 48 * 5);  // 272
  EXPECT_EQ(kMaxTracedRays, 5);
}

TEST(TracedRays, AMatteSurfaceEndsThePath) {
  const TracedRayCount count = countIn(corridor(true), everyObject);
  // The wall at depth 20 stops each column after the mirrors it meets before it: 1 (11.4), 3
  // (3.8, 11.4, 19.0), 4 (2.3, 6.9, 11.4, 16.0); the outer columns still meet six: 5.
  EXPECT_EQ(count.mirrorPixels, 64);
  EXPECT_EQ(count.unmodelled, 0);
  EXPECT_EQ(count.pixelsWithRays[1], 16);
  EXPECT_EQ(count.pixelsWithRays[2], 0);
  EXPECT_EQ(count.pixelsWithRays[3], 16);
  EXPECT_EQ(count.pixelsWithRays[4], 16);
  EXPECT_EQ(count.pixelsWithRays[5], 16);
  EXPECT_EQ(count.rays, 16 * (1 + 3 + 4 + 5));  // 208
}

TEST(TracedRays, OnlyTracedMirrorsCastRays) {
  // Mirror 0 (x = -1, the left half) traced, mirror 1 looked up in its probe: only the left four
  // columns count, and their rays still bounce off mirror 1 (rays met by a traced ray are traced).
  const TracedRayCount count = countIn(corridor(false), [](int object) { return object == 0; });
  EXPECT_EQ(count.mirrorPixels, 32);
  EXPECT_EQ(count.pixelsWithRays[2], 8);
  EXPECT_EQ(count.pixelsWithRays[5], 24);
  EXPECT_EQ(count.rays, 8 * 2 + 24 * 5);  // 136
}

TEST(TracedRays, GlassIsNotFollowed) {
  Scene scene = corridor(false);
  scene.objects[1].material = Material::Glass;
  const TracedRayCount count = countIn(scene, everyObject);
  // The right half is glass, and every left pixel's reflection meets it: none is counted.
  EXPECT_EQ(count.mirrorPixels, 0);
  EXPECT_EQ(count.unmodelled, 64);
  EXPECT_EQ(count.rays, 0);
}

}  // namespace
}  // namespace reflect
