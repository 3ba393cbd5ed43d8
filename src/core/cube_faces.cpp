#include "core/cube_faces.h"

#include <glm/gtc/matrix_transform.hpp>

namespace reflect {

glm::mat4 cubeFaceProjection(float near, float far) {
  return glm::perspective(glm::radians(90.0f), 1.0f, near, far);
}

glm::mat4 cubeFaceView(const glm::vec3& centre, int face) {
  const CubeFace& f = kCubeFaces.at(static_cast<size_t>(face));
  return glm::lookAt(centre, centre + f.direction, f.up);
}

}  // namespace reflect
