// The six cube-map faces, encoded once: GL face order, look direction and up vector.
// The table is the course's (docs/course.md, step 2); GL's cube-map convention needs these exact up
// vectors for texture(cube, d) to land on the texel that the face camera saw in direction d.
#pragma once

#include <array>
#include <glm/glm.hpp>

namespace reflect {

struct CubeFace {
  const char* name;
  glm::vec3 direction;
  glm::vec3 up;
};

// Index i is GL_TEXTURE_CUBE_MAP_POSITIVE_X + i.
inline constexpr std::array<CubeFace, 6> kCubeFaces{{
    {"+X", {1, 0, 0}, {0, -1, 0}},
    {"-X", {-1, 0, 0}, {0, -1, 0}},
    {"+Y", {0, 1, 0}, {0, 0, 1}},
    {"-Y", {0, -1, 0}, {0, 0, -1}},
    {"+Z", {0, 0, 1}, {0, -1, 0}},
    {"-Z", {0, 0, -1}, {0, -1, 0}},
}};

// 90 degree field of view and aspect 1: each face covers exactly its sixth of the sphere.
glm::mat4 cubeFaceProjection(float near, float far);
glm::mat4 cubeFaceView(const glm::vec3& centre, int face);

}  // namespace reflect
