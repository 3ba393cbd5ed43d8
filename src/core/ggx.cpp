#include "core/ggx.h"

#include <algorithm>
#include <cmath>

namespace reflect {

namespace {
constexpr float kPi = 3.14159265358979f;
}

glm::vec2 hammersley(uint32_t i, uint32_t n) {
  uint32_t bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return {static_cast<float>(i) / static_cast<float>(n),
          static_cast<float>(bits) * 2.3283064365386963e-10f};
}

glm::mat3 frameAround(const glm::vec3& n) {
  const glm::vec3 up = std::abs(n.z) < 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const glm::vec3 tangent = glm::normalize(glm::cross(up, n));
  const glm::vec3 bitangent = glm::cross(n, tangent);
  return glm::mat3(tangent, bitangent, n);
}

glm::vec3 ggxHalfVector(const glm::vec2& u, float alpha, const glm::vec3& n) {
  const float phi = 2.0f * kPi * u.x;
  const float a2 = alpha * alpha;
  const float cosTheta = std::sqrt((1.0f - u.y) / (1.0f + (a2 - 1.0f) * u.y));
  const float sinTheta = std::sqrt(std::max(1.0f - cosTheta * cosTheta, 0.0f));
  const glm::vec3 local(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
  return glm::normalize(frameAround(n) * local);
}

float ggxDistribution(float nDotH, float alpha) {
  const float a2 = alpha * alpha;
  const float d = nDotH * nDotH * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

float smithG1(float cosine, float alpha) {
  const float a2 = alpha * alpha;
  return 2.0f * cosine / (cosine + std::sqrt(a2 + (1.0f - a2) * cosine * cosine));
}

float lobeSampleWeight(float nDotV, float nDotL, float nDotH, float vDotH, float alpha) {
  if (nDotL <= 0.0f || nDotV <= 0.0f || nDotH <= 0.0f) return 0.0f;
  return smithG1(nDotV, alpha) * smithG1(nDotL, alpha) * vDotH / (nDotV * nDotH);
}

float prefilterSourceLod(float nDotH, float alpha, int samples, int faceSize) {
  const float pdf = ggxDistribution(nDotH, alpha) * 0.25f;
  const float sampleAngle = 1.0f / (static_cast<float>(samples) * pdf);
  const float size = static_cast<float>(faceSize);
  const float texelAngle = 4.0f * kPi / (6.0f * size * size);
  return std::max(0.5f * std::log2(sampleAngle / texelAngle) + 1.0f, 0.0f);
}

std::vector<glm::vec4> prefilterLobe(float alpha, int samples, int faceSize) {
  const int n = std::clamp(samples, 1, kMaxFilterSamples);
  const glm::vec3 normal(0.0f, 0.0f, 1.0f);  // the set is turned about z; the lobe is isotropic
  std::vector<glm::vec4> lobe;
  float total = 0.0f;
  for (int k = 0; k < n; ++k) {
    const glm::vec3 h = ggxHalfVector(
        hammersley(static_cast<uint32_t>(k), static_cast<uint32_t>(n)), alpha, normal);
    const glm::vec3 l = 2.0f * h.z * h - normal;
    if (l.z <= 0.0f) continue;
    lobe.emplace_back(l * l.z, prefilterSourceLod(h.z, alpha, n, faceSize));
    total += l.z;
  }
  for (glm::vec4& s : lobe) {
    const glm::vec3 d = glm::vec3(s) / total;
    s = glm::vec4(d, s.w);
  }
  return lobe;
}

RoughLevels roughLevelsFor(float roughness, int levels) {
  if (roughness <= 0.0f || levels <= 0) return {};
  const float at = std::min(roughness, 1.0f) * static_cast<float>(levels);
  const int lower = static_cast<int>(std::floor(at));
  return {lower, std::min(static_cast<int>(std::ceil(at)), levels)};
}

int usableRoughLevels(int roughLevels, int faceSize) {
  int top = 0;
  while ((2 << top) <= faceSize) ++top;  // floor(log2(faceSize))
  return std::max(std::min(roughLevels, top), 1);
}

glm::vec3 specularDominantDirection(const glm::vec3& n, const glm::vec3& r, float alpha) {
  const float s = 1.0f - alpha;
  return glm::normalize(glm::mix(n, r, s * (std::sqrt(s) + alpha)));
}

float roughnessOfLevel(int level, int levels) {
  return levels > 0 ? static_cast<float>(level) / static_cast<float>(levels) : 0.0f;
}

float transmissionRoughness(float roughness, float ior) {
  const float r = glm::clamp(roughness, 0.0f, 1.0f);
  return std::min(r * kTransmissionLobeFit * std::sqrt(std::abs(ior - 1.0f) / 2.0f), 1.0f);
}

}  // namespace reflect
