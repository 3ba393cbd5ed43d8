// The matrix that takes normals to world space. The textbook inverse-transpose divides by the
// determinant, which is 0 for a flattening scale such as S(1, 0, 1) and gives inf/NaN. The
// cofactor matrix is the same up to that factor, needs no division and stays finite; the shaders
// normalise anyway. Its sign is corrected so mirroring transforms keep normals outward.
#pragma once

#include <glm/glm.hpp>

namespace reflect {

inline glm::mat3 normalMatrixOf(const glm::mat3& m) {
  // Columns of the cofactor matrix: cross products of the other two columns.
  const glm::mat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
  return glm::determinant(m) < 0.0f ? -cofactor : cofactor;
}

}  // namespace reflect
