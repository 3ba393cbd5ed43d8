// The GGX lobe written twice on purpose, in GLSL for the GPU (shaders/ggx.glsl: the exact mode's
// lobe rays, the probe's prefilter pass) and in C++ (src/core/ggx.h: the reference, the
// planner), held equal as shading_equivalence_test holds shading.glsl: a tiny program that
// includes ggx.glsl runs each function for sample inputs and writes the results to an RGBA32F
// target; core/ggx's functions get the same inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../gl/gl_fixture.h"
#include "core/ggx.h"
#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gfx/shader_library.h"
#include "gfx/shader_program.h"
#include "gpu_sample_rows.h"

namespace reflect {
namespace {

// Both sides compute in 32-bit floats, but GLSL's sin, cos, sqrt and log2 may round otherwise
// than the C library's (a few ULP). Values are compared relative to their size (at least 1):
// 1e-4 is far past that rounding and far below what a changed term moves (a weight missing its
// v.h, a D with alpha for alpha^2).
constexpr float kTolerance = 1e-4f;

struct Sample {
  uint32_t k, n;  // hammersley(k, n)
  glm::vec2 u;    // a point on the unit square for the half vector
  float alpha;
  glm::vec3 normal;
  float nDotV, nDotL, nDotH, vDotH;
};

enum Column { kHammersley, kHalfVector, kTerms, kFrame, kColumns };
const char* const kColumnNames[] = {"hammersley", "ggxHalfVector",
                                    "ggxDistribution, smithG1, lobeSampleWeight",
                                    "frameAround tangent"};

constexpr const char* kProgram = R"glsl(
uniform uint u_k;
uniform uint u_n;
uniform vec2 u_u;
uniform float u_alpha;
uniform vec3 u_normal;
uniform vec4 u_cosines;  // n.v, n.l, n.h, v.h
out vec4 result;

void main() {
  int column = int(gl_FragCoord.x);
  vec3 c = vec3(hammersley(u_k, u_n), 0.0);
  if (column == 1) c = ggxHalfVector(u_u, u_alpha, u_normal);
  if (column == 2) {
    c = vec3(ggxDistribution(u_cosines.z, u_alpha), smithG1(u_cosines.x, u_alpha),
             lobeSampleWeight(u_cosines.x, u_cosines.y, u_cosines.z, u_cosines.w, u_alpha));
  }
  if (column == 3) c = frameAround(u_normal)[0];
  result = vec4(c, 1.0);
}
)glsl";

std::vector<glm::vec3> referenceColumns(const Sample& s) {
  return {glm::vec3(hammersley(s.k, s.n), 0.0f), ggxHalfVector(s.u, s.alpha, s.normal),
          glm::vec3(ggxDistribution(s.nDotH, s.alpha), smithG1(s.nDotV, s.alpha),
                    lobeSampleWeight(s.nDotV, s.nDotL, s.nDotH, s.vDotH, s.alpha)),
          frameAround(s.normal)[0]};
}

std::vector<Sample> samples() {
  const glm::vec3 normals[] = {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1),
                               glm::normalize(glm::vec3(1, 2, 3)),
                               glm::normalize(glm::vec3(-1, 0.5f, -0.2f))};
  const float alphas[] = {0.0625f, 0.25f, 0.5625f, 1.0f};  // roughness 0.25 to 1
  // Cosines from head-on to grazing, and one below the surface (no weight).
  const glm::vec4 cosines[] = {
      glm::vec4(1.0f, 1.0f, 1.0f, 1.0f), glm::vec4(0.7f, 0.5f, 0.95f, 0.8f),
      glm::vec4(0.1f, 0.3f, 0.6f, 0.4f), glm::vec4(0.5f, -0.2f, 0.7f, 0.6f)};
  std::vector<Sample> out;
  uint32_t k = 0;
  for (const glm::vec3& n : normals) {
    for (float alpha : alphas) {
      for (const glm::vec4& c : cosines) {
        Sample s;
        s.n = 64u << (k % 3);
        s.k = (k * 37u) % s.n;
        s.u = hammersley(s.k, s.n) * 0.999f;
        s.alpha = alpha;
        s.normal = n;
        s.nDotV = c.x;
        s.nDotL = c.y;
        s.nDotH = c.z;
        s.vDotH = c.w;
        out.push_back(s);
        ++k;
      }
    }
  }
  return out;
}

void setUniforms(const ShaderProgram& p, const Sample& s) {
  glUniform1ui(p.uniform("u_k"), s.k);
  glUniform1ui(p.uniform("u_n"), s.n);
  glUniform2f(p.uniform("u_u"), s.u.x, s.u.y);
  glUniform1f(p.uniform("u_alpha"), s.alpha);
  glUniform3f(p.uniform("u_normal"), s.normal.x, s.normal.y, s.normal.z);
  glUniform4f(p.uniform("u_cosines"), s.nDotV, s.nDotL, s.nDotH, s.vDotH);
}

// Every sample's columns from the GPU.
std::vector<glm::vec3> gpuColumns(const std::vector<Sample>& all) {
  return testing::drawSampleRows(
      "ggx.glsl", kProgram, kColumns, static_cast<int>(all.size()),
      [&all](const ShaderProgram& p, int i) { setUniforms(p, all[static_cast<size_t>(i)]); });
}

TEST(GgxEquivalence, TheGpuAndCoreComputeTheSameLobe) {
  const std::vector<Sample> all = samples();
  const std::vector<glm::vec3> gpu = gpuColumns(all);
  ASSERT_EQ(gpu.size(), all.size() * kColumns);
  float worst = 0.0f;
  for (size_t i = 0; i < all.size(); ++i) {
    const std::vector<glm::vec3> expected = referenceColumns(all[i]);
    for (int c = 0; c < kColumns; ++c) {
      const glm::vec3 got = gpu[i * kColumns + static_cast<size_t>(c)];
      const glm::vec3 want = expected[static_cast<size_t>(c)];
      for (int k = 0; k < 3; ++k) {
        const float difference = std::abs(got[k] - want[k]) / std::max(std::abs(want[k]), 1.0f);
        worst = std::max(worst, difference);
        EXPECT_LE(difference, kTolerance) << "sample " << i << ", " << kColumnNames[c] << "[" << k
                                          << "]: GPU " << got[k] << ", core " << want[k];
      }
    }
  }
  std::printf("%zu samples, largest relative difference %g\n", all.size(),
              static_cast<double>(worst));
}

}  // namespace
}  // namespace reflect
