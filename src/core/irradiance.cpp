#include "core/irradiance.h"

#include <algorithm>
#include <cmath>

#include "core/cube_sampling.h"

namespace reflect {

float shBasis(const glm::vec3& n, int i) {
  switch (i) {
    case 0:
      return 0.282095f;
    case 1:
      return 0.488603f * n.y;
    case 2:
      return 0.488603f * n.z;
    case 3:
      return 0.488603f * n.x;
    case 4:
      return 1.092548f * n.x * n.y;
    case 5:
      return 1.092548f * n.y * n.z;
    case 6:
      return 0.315392f * (3.0f * n.z * n.z - 1.0f);
    case 7:
      return 1.092548f * n.x * n.z;
    default:
      return 0.546274f * (n.x * n.x - n.y * n.y);
  }
}

float shBandFactor(int i) {
  if (i == 0) return 1.0f;
  return i < 4 ? 2.0f / 3.0f : 0.25f;
}

glm::vec3 irradianceAt(const IrradianceCoefficients& c, const glm::vec3& n) {
  glm::vec3 e(0.0f);
  for (int i = 0; i < kIrradianceCoefficients; ++i) e += c[static_cast<size_t>(i)] * shBasis(n, i);
  return glm::max(e, glm::vec3(0.0f));
}

glm::vec3 irradianceDirection(const glm::vec3& n, const glm::vec3& point, const glm::vec3& centre,
                              float radius) {
  if (radius <= 0.0f) return n;
  const glm::vec3 o = point - centre;
  const float on = glm::dot(o, n);
  const float t = -on + std::sqrt(std::max(on * on - glm::dot(o, o) + radius * radius, 0.0f));
  const glm::vec3 d = o + std::max(t, 0.0f) * n;
  const float length = glm::length(d);
  return length > 1e-6f ? d / length : n;
}

namespace {

// The cube's colour projected on the harmonics with the cosine lobe's band factors: each texel
// weighed by its solid angle, the weights scaled to 4 pi.
std::array<glm::dvec3, kIrradianceCoefficients> projectTexels(const CubeFaces& faces) {
  std::array<glm::dvec3, kIrradianceCoefficients> sums{};
  double weights = 0.0;
  for (int f = 0; f < 6; ++f) {
    const RgbaImage& face = faces[static_cast<size_t>(f)];
    const int n = face.width;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const float s = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
        const float t = (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
        const glm::vec3 d = faceDirection(f, s, t);
        const double r2 = glm::dot(d, d);
        const double w = 1.0 / (r2 * std::sqrt(r2));
        const uint8_t* texel = face.at(i, j);
        const glm::dvec3 value(texel[0] / 255.0, texel[1] / 255.0, texel[2] / 255.0);
        const glm::vec3 unit = glm::normalize(d);
        for (int k = 0; k < kIrradianceCoefficients; ++k) {
          sums[static_cast<size_t>(k)] += w * static_cast<double>(shBasis(unit, k)) * value;
        }
        weights += w;
      }
    }
  }
  const double scale = weights > 0.0 ? 4.0 * 3.14159265358979 / weights : 0.0;
  for (int k = 0; k < kIrradianceCoefficients; ++k) {
    sums[static_cast<size_t>(k)] *= scale * static_cast<double>(shBandFactor(k));
  }
  return sums;
}

}  // namespace

IrradianceCoefficients projectIrradiance(const CubeFaces& faces) {
  const auto sums = projectTexels(faces);
  IrradianceCoefficients c{};
  for (size_t k = 0; k < c.size(); ++k) c[k] = glm::vec3(sums[k]);
  return c;
}

CubeFaces irradianceCube(const IrradianceCoefficients& c, int size) {
  CubeFaces faces;
  for (int f = 0; f < 6; ++f) {
    RgbaImage& face = faces[static_cast<size_t>(f)];
    face.width = face.height = size;
    face.pixels.assign(static_cast<size_t>(size) * static_cast<size_t>(size) * 4, 255);
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        const float s = (static_cast<float>(i) + 0.5f) / static_cast<float>(size);
        const float t = (static_cast<float>(j) + 0.5f) / static_cast<float>(size);
        const glm::vec3 e =
            glm::min(irradianceAt(c, glm::normalize(faceDirection(f, s, t))), glm::vec3(1.0f));
        const size_t texel = 4 * (static_cast<size_t>(j) * static_cast<size_t>(size) + i);
        for (int k = 0; k < 3; ++k) {
          face.pixels[texel + static_cast<size_t>(k)] =
              static_cast<uint8_t>(std::lround(e[k] * 255.0f));
        }
      }
    }
  }
  return faces;
}

}  // namespace reflect
