#include "core/cube_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace reflect {
namespace {

// Face f's texel (i, j) has its centre at direction M + sc S + tc T, where sc and tc run over
// (-1, 1) (the table of the header, solved for the direction).
struct FaceBasis {
  glm::vec3 m;  // the major axis
  glm::vec3 s;  // the direction of increasing s
  glm::vec3 t;  // the direction of increasing t (down the image)
};

constexpr std::array<FaceBasis, 6> kBases{{
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // +X: sc = -rz, tc = -ry
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // -X: sc = +rz, tc = -ry
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},     // +Y: sc = +rx, tc = +rz
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // -Y: sc = +rx, tc = -rz
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // +Z: sc = +rx, tc = -ry
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},  // -Z: sc = -rx, tc = -ry
}};

glm::vec4 texel(const CubeFaces& faces, const CubeTexel& at) {
  const uint8_t* p = faces[static_cast<size_t>(at.face)].at(at.i, at.j);
  return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

}  // namespace

CubeFaceCoord cubeFaceCoord(const glm::vec3& d) {
  const float ax = std::abs(d.x);
  const float ay = std::abs(d.y);
  const float az = std::abs(d.z);
  CubeFaceCoord c;
  float ma = 0.0f;
  float sc = 0.0f;
  float tc = 0.0f;
  if (az >= std::max(ax, ay)) {  // ties go to Z
    ma = d.z;
    const bool negative = std::signbit(ma);
    c.face = negative ? 5 : 4;
    sc = negative ? -d.x : d.x;
    tc = -d.y;
  } else if (ax > ay) {  // then to Y
    ma = d.x;
    const bool negative = std::signbit(ma);
    c.face = negative ? 1 : 0;
    sc = negative ? d.z : -d.z;
    tc = -d.y;
  } else {
    ma = d.y;
    const bool negative = std::signbit(ma);
    c.face = negative ? 3 : 2;
    sc = d.x;
    tc = negative ? -d.z : d.z;
  }
  const float magnitude = std::abs(ma);
  const float halfOverMa = magnitude > 0.0f ? 0.5f / magnitude : 0.0f;
  c.s = sc * halfOverMa + 0.5f;
  c.t = tc * halfOverMa + 0.5f;
  return c;
}

glm::vec3 faceDirection(int face, float s, float t) {
  // The table above read backwards: sc = 2s - 1, tc = 2t - 1 with |ma| = 1.
  const float sc = 2.0f * s - 1.0f;
  const float tc = 2.0f * t - 1.0f;
  switch (face) {
    case 0:
      return {1.0f, -tc, -sc};
    case 1:
      return {-1.0f, -tc, sc};
    case 2:
      return {sc, 1.0f, tc};
    case 3:
      return {sc, -1.0f, -tc};
    case 4:
      return {sc, -tc, 1.0f};
    default:
      return {-sc, -tc, -1.0f};
  }
}

CubeTexel seamlessTexel(int face, int i, int j, int size) {
  const bool offS = i < 0 || i >= size;
  const bool offT = j < 0 || j >= size;
  if (!offS && !offT) return {face, i, j};
  // The centre of the texel past the edge, on the face's plane extended, folded over the edge:
  // the coordinate that ran past +-1 becomes the new major axis, and the old major axis becomes
  // the new face's coordinate at the edge texel's centre, 1 - 1/N. The result is exactly a texel
  // centre of the adjacent face, half a texel from any boundary.
  const FaceBasis& b = kBases[static_cast<size_t>(face)];
  const double n = size;
  const double sc = 2.0 * (i + 0.5) / n - 1.0;
  const double tc = 2.0 * (j + 0.5) / n - 1.0;
  const double inward = 1.0 - 1.0 / n;
  glm::dvec3 p;
  if (offS) {
    p = glm::dvec3(b.s) * (sc < 0.0 ? -1.0 : 1.0) + glm::dvec3(b.m) * inward + glm::dvec3(b.t) * tc;
  } else {
    p = glm::dvec3(b.t) * (tc < 0.0 ? -1.0 : 1.0) + glm::dvec3(b.m) * inward + glm::dvec3(b.s) * sc;
  }
  const CubeFaceCoord c = cubeFaceCoord(glm::vec3(p));
  const int ni = std::clamp(static_cast<int>(std::floor(c.s * size)), 0, size - 1);
  const int nj = std::clamp(static_cast<int>(std::floor(c.t * size)), 0, size - 1);
  return {c.face, ni, nj};
}

glm::vec4 sampleCubeLinear(const CubeFaces& faces, const glm::vec3& direction, CubeEdges edges) {
  const int n = faces[0].width;
  if (n < 1) return glm::vec4(0.0f);
  const CubeFaceCoord c = cubeFaceCoord(direction);
  const float u = std::max(c.s, 0.0f) * static_cast<float>(n) - 0.5f;
  const float v = std::max(c.t, 0.0f) * static_cast<float>(n) - 0.5f;
  const float floorU = std::floor(u);
  const float floorV = std::floor(v);
  const int i0 = static_cast<int>(floorU);
  const int j0 = static_cast<int>(floorV);
  const float a = u - floorU;  // weight of column i0 + 1
  const float b = v - floorV;  // weight of row j0 + 1

  // The 2x2 footprint: [0] (i0, j0), [1] (i0 + 1, j0), [2] (i0, j0 + 1), [3] (i0 + 1, j0 + 1).
  std::array<glm::vec4, 4> values;
  int corner = -1;
  for (int k = 0; k < 4; ++k) {
    const int i = i0 + (k & 1);
    const int j = j0 + (k >> 1);
    if (edges == CubeEdges::ClampToEdge) {
      values[static_cast<size_t>(k)] =
          texel(faces, {c.face, std::clamp(i, 0, n - 1), std::clamp(j, 0, n - 1)});
      continue;
    }
    const bool offS = i < 0 || i >= n;
    const bool offT = j < 0 || j >= n;
    if (offS && offT) {
      corner = k;
      continue;
    }
    values[static_cast<size_t>(k)] = texel(faces, seamlessTexel(c.face, i, j, n));
  }
  if (corner >= 0) {
    glm::vec4 sum(0.0f);
    for (int k = 0; k < 4; ++k) {
      if (k != corner) sum += values[static_cast<size_t>(k)];
    }
    values[static_cast<size_t>(corner)] = sum / 3.0f;
  }
  const glm::vec4 top = values[0] + a * (values[1] - values[0]);
  const glm::vec4 bottom = values[2] + a * (values[3] - values[2]);
  return top + b * (bottom - top);
}

}  // namespace reflect
