// The cube-face cameras must be exactly the course's table and proper rotations.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/cube_faces.h"

namespace reflect {
namespace {

TEST(CubeFaces, TableIsTheSeedTable) {
  const float dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const float ups[6][3] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(kCubeFaces[f].direction, glm::vec3(dirs[f][0], dirs[f][1], dirs[f][2])) << f;
    EXPECT_EQ(kCubeFaces[f].up, glm::vec3(ups[f][0], ups[f][1], ups[f][2])) << f;
  }
}

TEST(CubeFaces, ViewsLookAlongTheFaceWithTheFaceUpAndAreOrthonormal) {
  const glm::vec3 centre(0.0f, 0.25f, 0.0f);
  for (int f = 0; f < 6; ++f) {
    const glm::mat4 view = cubeFaceView(centre, f);
    // Rows of the rotation part: camera right, up, and -forward in world space.
    const glm::mat3 r(view);
    const glm::vec3 right(r[0][0], r[1][0], r[2][0]);
    const glm::vec3 up(r[0][1], r[1][1], r[2][1]);
    const glm::vec3 back(r[0][2], r[1][2], r[2][2]);
    EXPECT_EQ(-back, kCubeFaces[f].direction) << f;
    EXPECT_EQ(up, kCubeFaces[f].up) << f;
    EXPECT_EQ(glm::cross(right, up), back) << f;  // right-handed
    EXPECT_FLOAT_EQ(glm::dot(right, right), 1.0f);
    EXPECT_FLOAT_EQ(glm::dot(right, up), 0.0f);
    // The centre maps to the camera origin.
    const glm::vec4 origin = view * glm::vec4(centre, 1.0f);
    EXPECT_NEAR(glm::length(glm::vec3(origin)), 0.0f, 1e-6f) << f;
  }
}

TEST(CubeFaces, ProjectionCoversExactlyNinetyDegrees) {
  const glm::mat4 p = cubeFaceProjection(1.0f, 100.0f);
  // A point on the 45-degree edge of the frustum lands on the clip-space edge, x/w = 1.
  const glm::vec4 edge = p * glm::vec4(5.0f, 0.0f, -5.0f, 1.0f);
  EXPECT_NEAR(edge.x / edge.w, 1.0f, 1e-6f);
  const glm::vec4 top = p * glm::vec4(0.0f, 5.0f, -5.0f, 1.0f);
  EXPECT_NEAR(top.y / top.w, 1.0f, 1e-6f);  // aspect 1
}

}  // namespace
}  // namespace reflect
