#include "core/obj_faces.h"

#include <cmath>
#include <cstddef>
#include <limits>

namespace reflect {
namespace {

void emit(const ObjCorner& a, const ObjCorner& b, const ObjCorner& c, ObjVertices& vertices,
          BlockArray<uint32_t>& indices) {
  for (const ObjCorner* corner : {&a, &b, &c}) indices.push_back(vertices.vertexOf(*corner));
}

// pnpoly (W. Randolph Franklin), as tinyobjloader's ear clipping uses it.
bool insideTriangle(const float* x, const float* y, float tx, float ty) {
  bool inside = false;
  for (int i = 0, j = 2; i < 3; j = i++) {
    if (((y[i] > ty) != (y[j] > ty)) && (tx < (x[j] - x[i]) * (ty - y[i]) / (y[j] - y[i]) + x[i])) {
      inside = !inside;
    }
  }
  return inside;
}

// The two axes the ear clipper works in: the plane of the first corner that is not straight.
void planeAxes(const std::vector<ObjCorner>& face, const BlockArray<glm::vec3>& positions,
               size_t axes[2]) {
  const size_t n = face.size();
  axes[0] = 1;
  axes[1] = 2;
  for (size_t k = 0; k < n; ++k) {
    const glm::vec3 v0 = positions[face[k % n].position];
    const glm::vec3 v1 = positions[face[(k + 1) % n].position];
    const glm::vec3 v2 = positions[face[(k + 2) % n].position];
    const float e0x = v1.x - v0.x, e0y = v1.y - v0.y, e0z = v1.z - v0.z;
    const float e1x = v2.x - v1.x, e1y = v2.y - v1.y, e1z = v2.z - v1.z;
    const float cx = std::fabs(e0y * e1z - e0z * e1y);
    const float cy = std::fabs(e0z * e1x - e0x * e1z);
    const float cz = std::fabs(e0x * e1y - e0y * e1x);
    const float epsilon = std::numeric_limits<float>::epsilon();
    if (cx > epsilon || cy > epsilon || cz > epsilon) {
      if (!(cx > cy && cx > cz)) {
        axes[0] = 0;
        if (cz > cx && cz > cy) axes[1] = 1;
      }
      return;
    }
  }
}

// Whether a corner of `remaining` other than the three from `guess` lies inside their triangle
// (vx, vy: the triangle in the plane's axes).
bool overlapsAnother(const std::vector<ObjCorner>& remaining, size_t guess,
                     const BlockArray<glm::vec3>& positions, const size_t axes[2], const float* vx,
                     const float* vy) {
  const size_t count = remaining.size();
  for (size_t other = 3; other < count; ++other) {
    const glm::vec3 p = positions[remaining[(guess + other) % count].position];
    if (insideTriangle(vx, vy, p[static_cast<int>(axes[0])], p[static_cast<int>(axes[1])])) {
      return true;
    }
  }
  return false;
}

}  // namespace

void ObjFaceTriangulator::triangulate(const std::vector<ObjCorner>& face,
                                      const BlockArray<glm::vec3>& positions, ObjVertices& vertices,
                                      BlockArray<uint32_t>& indices) {
  const size_t n = face.size();
  if (n == 3) {
    emit(face[0], face[1], face[2], vertices, indices);
    return;
  }
  if (n == 4) {
    const glm::vec3 v0 = positions[face[0].position], v1 = positions[face[1].position];
    const glm::vec3 v2 = positions[face[2].position], v3 = positions[face[3].position];
    const float e02x = v2.x - v0.x, e02y = v2.y - v0.y, e02z = v2.z - v0.z;
    const float e13x = v3.x - v1.x, e13y = v3.y - v1.y, e13z = v3.z - v1.z;
    const float sqr02 = e02x * e02x + e02y * e02y + e02z * e02z;
    const float sqr13 = e13x * e13x + e13y * e13y + e13z * e13z;
    if (sqr02 < sqr13) {
      emit(face[0], face[1], face[2], vertices, indices);
      emit(face[0], face[2], face[3], vertices, indices);
    } else {
      emit(face[0], face[1], face[3], vertices, indices);
      emit(face[1], face[2], face[3], vertices, indices);
    }
    return;
  }
  clipEars(face, positions, vertices, indices);
}

// tinyobjloader's ear clipper, step for step (its "area" is the one it computes: the first two
// corners' cross product, not the polygon's), so a polygon gives the same triangles here.
void ObjFaceTriangulator::clipEars(const std::vector<ObjCorner>& face,
                                   const BlockArray<glm::vec3>& positions, ObjVertices& vertices,
                                   BlockArray<uint32_t>& indices) {
  const size_t n = face.size();
  size_t axes[2];
  planeAxes(face, positions, axes);
  remaining_ = face;
  size_t guess = 0;
  size_t iterationsLeft = n;
  size_t previousCount = n;
  ObjCorner ind[3];
  float vx[3], vy[3];
  while (remaining_.size() > 3 && iterationsLeft > 0) {
    const size_t count = remaining_.size();
    if (guess >= count) guess -= count;
    if (previousCount != count) {
      previousCount = count;
      iterationsLeft = count;
    } else {
      --iterationsLeft;
    }
    for (size_t k = 0; k < 3; ++k) {
      ind[k] = remaining_[(guess + k) % count];
      const glm::vec3 p = positions[ind[k].position];
      vx[k] = p[static_cast<int>(axes[0])];
      vy[k] = p[static_cast<int>(axes[1])];
    }
    const float e0x = vx[1] - vx[0], e0y = vy[1] - vy[0];
    const float e1x = vx[2] - vx[1], e1y = vy[2] - vy[1];
    const float cross = e0x * e1y - e0y * e1x;
    const float area = (vx[0] * vy[1] - vy[0] * vx[1]) * 0.5f;
    // An inner angle, or another corner inside: not an ear.
    if (cross * area < 0.0f || overlapsAnother(remaining_, guess, positions, axes, vx, vy)) {
      ++guess;
      continue;
    }
    emit(ind[0], ind[1], ind[2], vertices, indices);
    remaining_.erase(remaining_.begin() + static_cast<std::ptrdiff_t>((guess + 1) % count));
  }
  if (remaining_.size() == 3) emit(remaining_[0], remaining_[1], remaining_[2], vertices, indices);
}

}  // namespace reflect
