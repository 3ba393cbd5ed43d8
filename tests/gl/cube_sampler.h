// What texture(cube, d) returns for each direction d: the check behind the cube round-trip and
// seam tests (a strip of pixels, one per direction, drawn with a sampling shader).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gfx/gl.h"

namespace reflect::testing {

std::vector<glm::u8vec3> sampleCube(GLuint cube, const std::vector<glm::vec3>& directions);

}  // namespace reflect::testing
