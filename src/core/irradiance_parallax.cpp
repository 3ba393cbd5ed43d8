#include "core/irradiance_parallax.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/cube_cross.h"
#include "core/cube_sampling.h"

namespace reflect {
namespace {

// The box mip chain, level 0 first, down to 1 x 1 (glGenerateMipmap's 2 x 2 means).
std::vector<CubeFaces> boxChain(const CubeFaces& faces) {
  std::vector<CubeFaces> chain{faces};
  for (int size = faces[0].width / 2, factor = 2; size >= 1; size /= 2, factor *= 2) {
    chain.push_back(shrinkFaces(faces, factor));
  }
  return chain;
}

// textureLod through a LINEAR_MIPMAP_LINEAR sampler: bilinear in the two nearest levels, blended.
glm::vec4 sampleLevel(const std::vector<CubeFaces>& chain, const glm::vec3& d, float level) {
  const float top = static_cast<float>(chain.size() - 1);
  const float l = std::clamp(level, 0.0f, top);
  const int below = static_cast<int>(std::floor(l));
  const int above = std::min(below + 1, static_cast<int>(top));
  const float f = l - static_cast<float>(below);
  const glm::vec4 a = sampleCubeLinear(chain[static_cast<size_t>(below)], d);
  return f > 0.0f ? glm::mix(a, sampleCubeLinear(chain[static_cast<size_t>(above)], d), f) : a;
}

struct Taps {
  const std::vector<CubeFaces>& chain;
  ParallaxLevels levels;
  float near;

  float distance(const glm::vec3& u) const {
    const float a = sampleLevel(chain, u, levels.distance).a;
    if (a >= 0.999f) return 1e6f;
    return near * a / std::max(1.0f - a, 1e-3f);
  }

  glm::vec3 seen(const glm::vec3& o, const glm::vec3& w) const {
    float t = distance(w);
    for (int i = 0; i < kParallaxSteps; ++i) {
      const float d = distance(glm::normalize(o + std::min(t, 1e4f) * w));
      const float ow = glm::dot(o, w);
      t = -ow + std::sqrt(std::max(ow * ow - glm::dot(o, o) + d * d, 0.0f));
    }
    return glm::normalize(o + std::min(t, 1e4f) * w);
  }
};

}  // namespace

ParallaxLevels parallaxLevels(int faceSize) {
  const float top = std::log2(static_cast<float>(std::max(faceSize, 1)));
  return {std::clamp(top - 1.5f, 0.0f, top), std::clamp(top - 4.0f, 0.0f, top)};
}

glm::vec3 irradianceParallax(const CubeFaces& faces, const glm::vec3& point,
                             const glm::vec3& centre, const glm::vec3& n, float near) {
  const std::vector<CubeFaces> chain = boxChain(faces);
  const Taps taps{chain, parallaxLevels(faces[0].width), near};
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 tx = glm::normalize(glm::cross(helper, n));
  const glm::vec3 ty = glm::cross(n, tx);
  const glm::vec3 o = point - centre;
  glm::vec3 shift(0.0f);
  for (int k = 0; k < kParallaxTaps; ++k) {
    const float u1 = (static_cast<float>(k) + 0.5f) / static_cast<float>(kParallaxTaps);
    const float turns = static_cast<float>(k) * 0.618034f;
    const float phi = 6.2831853f * (turns - std::floor(turns));
    const float r = std::sqrt(u1);
    const glm::vec3 w =
        r * std::cos(phi) * tx + r * std::sin(phi) * ty + std::sqrt(std::max(1.0f - u1, 0.0f)) * n;
    shift += glm::vec3(sampleLevel(chain, taps.seen(o, w), taps.levels.colour)) -
             glm::vec3(sampleLevel(chain, w, taps.levels.colour));
  }
  return shift / static_cast<float>(kParallaxTaps);
}

}  // namespace reflect
