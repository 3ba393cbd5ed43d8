// core/cube_sampling.h against the GL it imitates: texture(samplerCube, d) of the skybox's own
// texture (SkyboxPass: RGBA8, LINEAR, CLAMP_TO_EDGE, no mipmaps) on random 8 x 8 faces, for
// random directions and for directions on the edges, at the corners and on the ties between axes.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/cube_sampling.h"
#include "cube_sampler.h"
#include "gfx/skybox_pass.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

constexpr int kFace = 8;

// A small deterministic generator (the same numbers on every platform).
struct Lcg {
  uint32_t state = 12345u;
  uint32_t next() {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  }
  float uniform() { return static_cast<float>(next() & 0xFFFFu) / 65535.0f; }
};

CubeFaces randomFaces(Lcg& random) {
  CubeFaces faces;
  for (RgbaImage& face : faces) {
    face.width = face.height = kFace;
    face.pixels.resize(kFace * kFace * 4);
    for (uint8_t& byte : face.pixels) byte = static_cast<uint8_t>(random.next() & 0xFFu);
  }
  return faces;
}

std::vector<glm::vec3> testDirections(Lcg& random) {
  std::vector<glm::vec3> d;
  // Random directions.
  for (int k = 0; k < 400; ++k) {
    d.emplace_back(random.uniform() * 2 - 1, random.uniform() * 2 - 1, random.uniform() * 2 - 1);
  }
  // Near the twelve edges (|a| = |b| = 1 - e) and the eight corners, where the filter spans
  // faces.
  for (int k = 0; k < 400; ++k) {
    const float e = random.uniform() * 0.3f;
    const float along = random.uniform() * 2 - 1;
    const float sa = random.next() & 1 ? 1.0f : -1.0f;
    const float sb = random.next() & 1 ? 1.0f : -1.0f;
    const float sc = random.next() & 1 ? 1.0f : -1.0f;
    const float major = 1.0f;
    const float nearEdge = 1.0f - e;
    switch (k % 4) {
      case 0:
        d.emplace_back(sa * major, sb * nearEdge, along);
        break;
      case 1:
        d.emplace_back(along, sa * major, sb * nearEdge);
        break;
      case 2:
        d.emplace_back(sb * nearEdge, along, sa * major);
        break;
      default:
        d.emplace_back(sa * major, sb * (1.0f - e * 0.2f), sc * (1.0f - random.uniform() * 0.06f));
        break;
    }
  }
  // Exact ties between two and three axes.
  for (float x : {-1.0f, 0.0f, 1.0f}) {
    for (float y : {-1.0f, 0.0f, 1.0f}) {
      for (float z : {-1.0f, 0.0f, 1.0f}) {
        if (x != 0.0f || y != 0.0f || z != 0.0f) d.emplace_back(x, y, z);
      }
    }
  }
  return d;
}

struct Agreement {
  size_t exact = 0;
  size_t withinOne = 0;
  int worst = 0;
};

Agreement compare(const CubeFaces& faces, const std::vector<glm::vec3>& directions,
                  const std::vector<glm::u8vec3>& gl, CubeEdges edges) {
  Agreement a;
  for (size_t k = 0; k < directions.size(); ++k) {
    const glm::vec4 cpu = sampleCubeLinear(faces, directions[k], edges);
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const long mine = std::lround(std::clamp(cpu[c], 0.0f, 1.0f) * 255.0f);
      worst = std::max(worst, static_cast<int>(std::labs(mine - gl[k][c])));
    }
    a.exact += worst == 0;
    a.withinOne += worst <= 1;
    a.worst = std::max(a.worst, worst);
  }
  return a;
}

TEST(CubeSampling, TheCpuSamplerIsTheGlSamplerTexelForTexel) {
  Lcg random;
  const CubeFaces faces = randomFaces(random);
  const std::vector<glm::vec3> directions = testDirections(random);
  auto pass = SkyboxPass::create(faces);
  ASSERT_TRUE(pass) << pass.error();
  const std::vector<glm::u8vec3> gl = testing::sampleCube(pass.value().texture(), directions);
  ASSERT_EQ(gl.size(), directions.size());

  const Agreement seamless = compare(faces, directions, gl, CubeEdges::Seamless);
  const Agreement clamped = compare(faces, directions, gl, CubeEdges::ClampToEdge);
  std::printf(
      "%zu directions: seamless %zu exact, %zu within 1 (worst %d); clamp-to-edge %zu exact, %zu "
      "within 1 (worst %d)\n",
      directions.size(), seamless.exact, seamless.withinOne, seamless.worst, clamped.exact,
      clamped.withinOne, clamped.worst);
  // GL ES 3.0 filters cube maps seamlessly: every direction within one level (the GPU's
  // arithmetic rounds differently), and per-face clamping visibly wrong near the edges.
  EXPECT_EQ(seamless.withinOne, directions.size());
  EXPECT_LE(seamless.worst, 1);
  EXPECT_LT(clamped.withinOne, directions.size());
}

}  // namespace
}  // namespace reflect
