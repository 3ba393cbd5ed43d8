#include "reference/lobe_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/ggx.h"

namespace reflect {
namespace {

// A 32-bit integer hash with good avalanche (every input bit moves every output bit about half
// the time), so nearby points and consecutive seeds get unrelated shifts.
uint32_t mixBits(uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

uint32_t bitsOf(float f) {
  uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

// The top 24 bits as a float in [0, 1): exactly representable, never 1.
float unitFloat(uint32_t h) {
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

float wrap(float x) {
  return x >= 1.0f ? x - 1.0f : x;
}

}  // namespace

LobeSampler::LobeSampler(uint32_t seed, const glm::vec3& position, const glm::vec3& toViewer) {
  uint32_t h = mixBits(seed ^ 0x9e3779b9u);
  for (float f : {position.x, position.y, position.z, toViewer.x, toViewer.y, toViewer.z}) {
    h = mixBits(h ^ bitsOf(f));
  }
  shift_ = glm::vec2(unitFloat(h), unitFloat(mixBits(h ^ 0x68e31da4u)));
}

glm::vec2 LobeSampler::point(uint32_t k, uint32_t count) const {
  const glm::vec2 u = hammersley(k, count);
  return {wrap(u.x + shift_.x), wrap(u.y + shift_.y)};
}

float lobeAlbedo(float nDotV, float alpha, uint32_t count) {
  // In the normal's own frame: n = z, v in the xz plane.
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const glm::vec3 v(std::sqrt(std::max(1.0f - nDotV * nDotV, 0.0f)), 0.0f, nDotV);
  double sum = 0.0;
  for (uint32_t k = 0; k < count; ++k) {
    const glm::vec3 h = ggxHalfVector(hammersley(k, count), alpha, n);
    const glm::vec3 l = glm::reflect(-v, h);
    sum += lobeSampleWeight(nDotV, l.z, h.z, glm::dot(v, h), alpha);
  }
  return static_cast<float>(sum / count);
}

namespace {
constexpr int kLobeAlbedoRows = 64;
constexpr uint32_t kLobeAlbedoPoints = 4096;
}  // namespace

LobeAlbedoTable::LobeAlbedoTable(float alpha) {
  for (int i = 0; i < kLobeAlbedoRows; ++i) {
    const float nDotV = static_cast<float>(i + 1) / kLobeAlbedoRows;
    rows_.push_back(lobeAlbedo(nDotV, alpha, kLobeAlbedoPoints));
  }
}

float LobeAlbedoTable::at(float nDotV) const {
  if (rows_.empty()) return 1.0f;
  const float at = std::clamp(nDotV * kLobeAlbedoRows - 1.0f, 0.0f, kLobeAlbedoRows - 1.0f);
  const int below = std::min(static_cast<int>(at), kLobeAlbedoRows - 2);
  const float t = at - static_cast<float>(below);
  return (1.0f - t) * rows_[static_cast<size_t>(below)] + t * rows_[static_cast<size_t>(below) + 1];
}

}  // namespace reflect
