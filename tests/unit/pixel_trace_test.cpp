// core/pixel_trace.h, pick a pixel's CPU side: the pixel's ray, the angle between directions, and
// the path through a glass mesh (against the project's icosphere; Embree checks the hits in
// tests/reference/pixel_explain_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "core/obj_loader.h"
#include "core/pixel_trace.h"

namespace reflect {
namespace {

TEST(PixelTrace, ThePixelRayGoesThroughThePixelCentreFromTheTopLeft) {
  const LookCamera camera;  // eye (0, 1, 7) looking down -z, 70 degrees vertically
  // On an odd-sized frame the middle pixel looks straight ahead.
  const std::optional<TraceRay> middle = pixelRay(camera, 50, 50, 101, 101);
  ASSERT_TRUE(middle.has_value());
  EXPECT_LT(angleDegrees(middle->direction, {0, 0, -1}), 1e-4);
  EXPECT_NEAR(glm::length(middle->direction), 1.0f, 1e-6f);
  // Row 0 is the top: its ray climbs; column 0 is the left.
  const std::optional<TraceRay> corner = pixelRay(camera, 0, 0, 101, 101);
  ASSERT_TRUE(corner.has_value());
  EXPECT_GT(corner->direction.y, 0.0f);
  EXPECT_LT(corner->direction.x, 0.0f);
  // Row 0's centre is half a pixel below the top edge: ndc y = 1 - 1 / 101.
  const double top = glm::degrees(std::atan(std::tan(glm::radians(35.0)) * 100.0 / 101.0));
  EXPECT_NEAR(angleDegrees(pixelRay(camera, 50, 0, 101, 101)->direction, {0, 0, -1}), top, 1e-4);
  EXPECT_FALSE(pixelRay(camera, 101, 0, 101, 101).has_value());
  EXPECT_FALSE(pixelRay(camera, 0, -1, 101, 101).has_value());
}

TEST(PixelTrace, AnglesAreExactLargeAndSmall) {
  EXPECT_DOUBLE_EQ(angleDegrees({1, 0, 0}, {0, 3, 0}), 90.0);
  EXPECT_DOUBLE_EQ(angleDegrees({1, 0, 0}, {-2, 0, 0}), 180.0);
  EXPECT_EQ(angleDegrees({0, 0, 1}, {0, 0, 1}), 0.0);
  // 1e-5 radians, where acos of a float dot product would read 0.
  EXPECT_NEAR(angleDegrees({0, 0, 1}, {1e-5f, 0, 1}), glm::degrees(1e-5), 1e-9);
}

std::shared_ptr<const MeshBvh> icosphere() {
  Result<LoadedMesh> loaded = loadObjFile(std::string(MODEL_DIR) + "/sphere.obj");
  EXPECT_TRUE(loaded) << loaded.error();
  auto mesh = std::make_shared<const MeshData>(loaded.take().mesh);
  return std::make_shared<const MeshBvh>(buildMeshBvh(mesh));
}

Scene oneSphere() {
  Scene scene;
  SceneObject glass;
  glass.mesh = "sphere.obj";
  glass.material = Material::Glass;
  scene.objects = {glass};
  return scene;
}

TEST(PixelTrace, GlassOfIndexOneLetsTheRayThroughUnbent) {
  const auto tree = icosphere();
  const SceneBvh placed = placeScene(oneSphere(), 0.0, [&](const std::string&) { return tree; });
  const glm::vec3 centre = tree->mesh->bounds.centre();
  const TraceRay ray{centre + glm::vec3(0.3f, 0.2f, 10.0f), {0, 0, -1}};
  const SurfacePoint entry = firstSurface(placed, ray);
  ASSERT_EQ(entry.object, 0);
  EXPECT_GT(glm::dot(entry.normal, ray.direction), -1.0f);  // outward, facing the ray
  EXPECT_LT(glm::dot(entry.normal, ray.direction), 0.0f);
  const GlassRoute route = followGlass(placed, entry, ray.direction, 1.0f, true);
  EXPECT_FALSE(route.totalAtEntry);
  EXPECT_TRUE(route.exited);
  EXPECT_EQ(route.internalReflections, 0);
  EXPECT_LT(angleDegrees(route.inside, ray.direction), 1e-3);
  EXPECT_LT(angleDegrees(route.leaving, ray.direction), 1e-3);
  // It leaves on the far side, on the ray's own line.
  EXPECT_LT(route.exitPoint.z, centre.z);
  EXPECT_NEAR(route.exitPoint.x, ray.origin.x, 1e-4f);
  EXPECT_NEAR(route.exitPoint.y, ray.origin.y, 1e-4f);
  // With one surface the ray stops at the entry.
  const GlassRoute one = followGlass(placed, entry, ray.direction, 1.52f, false);
  EXPECT_FALSE(one.exited);
  EXPECT_EQ(one.exitPoint, entry.position);
}

TEST(PixelTrace, GlassBendsTheRayInAndBackOutParallelForASphere) {
  // Through a sphere a ray leaves at the angle it entered: in and out, it is turned by the same
  // angle twice, towards the axis through the centre. The icosphere is faceted but its
  // interpolated normals follow the sphere: within a degree.
  const auto tree = icosphere();
  const SceneBvh placed = placeScene(oneSphere(), 0.0, [&](const std::string&) { return tree; });
  const glm::vec3 centre = tree->mesh->bounds.centre();
  const TraceRay ray{centre + glm::vec3(0.0f, 0.8f, 10.0f), {0, 0, -1}};
  const SurfacePoint entry = firstSurface(placed, ray);
  ASSERT_EQ(entry.object, 0);
  const GlassRoute route = followGlass(placed, entry, ray.direction, 1.52f, true);
  ASSERT_TRUE(route.exited);
  const double incidence = angleDegrees(-ray.direction, entry.normal);
  const double refracted = glm::degrees(std::asin(std::sin(glm::radians(incidence)) / 1.52));
  EXPECT_NEAR(angleDegrees(route.inside, -entry.normal), refracted, 1e-3);
  EXPECT_LT(route.leaving.y, 0.0f);  // bent down, towards the centre's level
  EXPECT_NEAR(angleDegrees(route.leaving, ray.direction), 2.0 * (incidence - refracted), 1.0);
}

}  // namespace
}  // namespace reflect
