// The harness of the GPU-against-C++ equivalence tests: a test fragment program (a shader library
// followed by a main that writes one value a column) drawn once per sample, sample i into row i
// of a float target, read back in sample order.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gfx/shader_program.h"

namespace reflect::testing {

// `library` is an embedded shader file; `main` the test's GLSL after it. `setUniforms(program, i)`
// sets sample i's inputs. Returns rows x columns values, sample 0's first (empty, with a test
// failure, when the program or the target cannot be made).
std::vector<glm::vec3> drawSampleRows(
    const char* library, const char* main, int columns, int rows,
    const std::function<void(const ShaderProgram& program, int row)>& setUniforms);

}  // namespace reflect::testing
