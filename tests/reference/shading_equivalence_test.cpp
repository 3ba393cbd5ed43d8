// The shading written twice on purpose, once in GLSL for the GPU (shaders/shading.glsl) and once
// in C++ for the reference (src/core/reference_shading.h), held equal: a tiny program that
// includes shading.glsl runs each of its functions on the GPU for a set of sample inputs (normals,
// view directions from head-on to grazing and from behind, colours, what the rays see, indices
// of refraction from below 1 to diamond's, Fresnel on and off, glass past its critical angle)
// and writes the results to an RGBA32F target; the reference's functions get the same inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../gl/gl_fixture.h"
#include "core/reference_shading.h"
#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gfx/shader_library.h"
#include "gfx/shader_program.h"
#include "gpu_sample_rows.h"

namespace reflect {
namespace {

// Both sides compute in 32-bit floats (the program is highp), but not with the same operations:
// GLSL ES 3.00 lets pow() be exp2(y log2(x)), exp2 within 3 + 2|x| ULP and log2 within 3 ULP, and
// normalize() an inverse square root; with a shininess of 10 that is up to some 1e-5 of a value
// that lies in [0, 2]. 1e-4 is past that, and 100 times below what a weight moved by 0.01 (the
// course's 0.78 as 0.77) changes in a reflection of 0.1 or more.
constexpr float kTolerance = 1e-4f;

// One sample: the inputs every function of shading.glsl takes. The normal and the direction to
// the viewer are unit vectors, made on the CPU, so both sides start from the same bits.
struct Sample {
  glm::vec3 normal;
  glm::vec3 toViewer;
  glm::vec3 colour;
  glm::vec3 reflected;  // what the reflected ray sees
  glm::vec3 refracted;  // what the refracted ray sees
  float ior;
  bool fresnel;
  float reflectionWeight;
  float baseWeight;
  glm::vec3 point;  // Phong: the surface point, the light and the eye
  glm::vec3 light;
  glm::vec3 eye;
  glm::vec4 phongTerms;  // ambient, diffuse, specular, shininess
};

// What the test program writes, one texel each, in this order.
enum Column { kPhong, kScalars, kMirror, kGlass, kMirrorAdd, kGlassAdd, kWeights, kColumns };

constexpr const char* kProgram = R"glsl(
uniform vec3 u_normal;
uniform vec3 u_toViewer;
uniform vec3 u_colour;
uniform vec3 u_reflected;
uniform vec3 u_refracted;
uniform float u_ior;
uniform int u_fresnel;
uniform float u_reflectionWeight;
uniform float u_baseWeight;
uniform vec3 u_point;
uniform vec3 u_light;
uniform vec3 u_eye;
uniform vec4 u_phongTerms;
out vec4 result;

void main() {
  int column = int(gl_FragCoord.x);
  float f0 = fresnelF0(u_ior);
  float schlick = schlickWeight(f0, u_toViewer, u_normal);
  bool fresnel = u_fresnel == 1;
  vec3 T = refract(-u_toViewer, u_normal, 1.0 / max(u_ior, 1e-3));
  bool total = dot(T, T) == 0.0;
  Blend mirror = mirrorBlend(u_colour, u_reflectionWeight, u_baseWeight, fresnel, schlick);
  Blend glass = glassBlend(u_colour, u_reflected, total, u_reflectionWeight, u_baseWeight,
                           fresnel, schlick);
  vec3 c = phongShade(u_colour, u_point, u_normal, u_light, u_eye, u_phongTerms);
  if (column == 1) c = vec3(f0, schlick, total ? 1.0 : 0.0);
  if (column == 2) c = blended(mirror, u_reflected);
  if (column == 3) c = blended(glass, total ? u_reflected : u_refracted);
  if (column == 4) c = mirror.add;
  if (column == 5) c = glass.add;
  if (column == 6) c = vec3(mirror.weight, glass.weight, 0.0);
  result = vec4(c, 1.0);
}
)glsl";

// The same columns from the reference's functions.
std::vector<glm::vec3> referenceColumns(const Sample& s) {
  const float f0 = fresnelF0(s.ior);
  const float schlick = schlickWeight(f0, s.toViewer, s.normal);
  const glm::vec3 t = glm::refract(-s.toViewer, s.normal, 1.0f / clampedIor(s.ior));
  const bool total = glm::dot(t, t) == 0.0f;
  const Blend mirror = mirrorBlend(s.colour, s.reflectionWeight, s.baseWeight, s.fresnel, schlick);
  const Blend glass = glassBlend(s.colour, s.reflected, total, s.reflectionWeight, s.baseWeight,
                                 s.fresnel, schlick);
  return {phongShade(s.colour, s.point, s.normal, s.light, s.eye, s.phongTerms),
          glm::vec3(f0, schlick, total ? 1.0f : 0.0f),
          blended(mirror, s.reflected),
          blended(glass, total ? s.reflected : s.refracted),
          mirror.add,
          glass.add,
          glm::vec3(mirror.weight, glass.weight, 0.0f)};
}

// A unit vector at `degrees` from unit `n`, turned about an axis across it.
glm::vec3 atAngle(const glm::vec3& n, float degrees) {
  const glm::vec3 across =
      glm::normalize(glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const float a = glm::radians(degrees);
  return glm::normalize(std::cos(a) * n + std::sin(a) * across);
}

std::vector<Sample> samples() {
  const glm::vec3 normals[] = {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, 2, 3)),
                               glm::normalize(glm::vec3(-1, 0.5f, -0.2f))};
  // Head-on to grazing, and from behind the surface (the clamp in Schlick's term). The critical
  // angle for 0.66 (glass seen from inside) is 41.3 degrees: 60 and beyond are total.
  const float angles[] = {0.0f, 30.0f, 60.0f, 85.0f, 89.5f, 100.0f};
  const float iors[] = {1.0f, 1.33f, 1.52f, 2.42f, 0.66f, 0.0f};  // 0: held at 1e-3
  const glm::vec3 colours[] = {glm::vec3(1.0f, 0.84f, 0.0f), glm::vec3(0.2f, 0.4f, 0.9f)};
  const glm::vec3 seen[] = {glm::vec3(0.9f, 0.8f, 0.7f), glm::vec3(1.0f),
                            glm::vec3(0.1f, 0.5f, 0.3f)};
  std::vector<Sample> out;
  int k = 0;
  for (const glm::vec3& n : normals) {
    for (float angle : angles) {
      for (float ior : iors) {
        for (bool fresnel : {false, true}) {
          Sample s;
          s.normal = n;
          s.toViewer = atAngle(n, angle);
          s.colour = colours[k % 2];
          s.reflected = seen[k % 3];
          s.refracted = seen[(k + 1) % 3];
          s.ior = ior;
          s.fresnel = fresnel;
          s.reflectionWeight = k % 2 ? 0.78f : 0.5f;
          s.baseWeight = k % 2 ? 0.3f : 0.6f;
          s.point = glm::vec3(0.1f * static_cast<float>(k % 7), 0.0f, -0.2f);
          // The light in front, beside and behind the surface (no specular there).
          s.light = s.point + 4.0f * atAngle(n, static_cast<float>(k % 4) * 40.0f);
          s.eye = s.point + 3.0f * s.toViewer;
          s.phongTerms = glm::vec4(0.2f, 0.7f, 1.0f, k % 2 ? 10.0f : 64.0f);
          out.push_back(s);
          ++k;
        }
      }
    }
  }
  return out;
}

void setUniforms(const ShaderProgram& p, const Sample& s) {
  const auto vec3 = [&](const char* name, const glm::vec3& v) {
    glUniform3f(p.uniform(name), v.x, v.y, v.z);
  };
  vec3("u_normal", s.normal);
  vec3("u_toViewer", s.toViewer);
  vec3("u_colour", s.colour);
  vec3("u_reflected", s.reflected);
  vec3("u_refracted", s.refracted);
  glUniform1f(p.uniform("u_ior"), s.ior);
  glUniform1i(p.uniform("u_fresnel"), s.fresnel ? 1 : 0);
  glUniform1f(p.uniform("u_reflectionWeight"), s.reflectionWeight);
  glUniform1f(p.uniform("u_baseWeight"), s.baseWeight);
  vec3("u_point", s.point);
  vec3("u_light", s.light);
  vec3("u_eye", s.eye);
  glUniform4f(p.uniform("u_phongTerms"), s.phongTerms.x, s.phongTerms.y, s.phongTerms.z,
              s.phongTerms.w);
}

// Every sample's columns from the GPU.
std::vector<glm::vec3> gpuColumns(const std::vector<Sample>& all) {
  return testing::drawSampleRows(
      "shading.glsl", kProgram, kColumns, static_cast<int>(all.size()),
      [&all](const ShaderProgram& p, int i) { setUniforms(p, all[static_cast<size_t>(i)]); });
}

const char* const kColumnNames[] = {"phongShade",          "fresnelF0, schlickWeight, total",
                                    "mirror blended",      "glass blended",
                                    "mirrorBlend add",     "glassBlend add",
                                    "mirror, glass weight"};

TEST(ShadingEquivalence, TheGpuAndTheReferenceShadeAlike) {
  const std::vector<Sample> all = samples();
  const std::vector<glm::vec3> gpu = gpuColumns(all);
  ASSERT_EQ(gpu.size(), all.size() * kColumns);
  float worst = 0.0f;
  int totals = 0;
  for (size_t i = 0; i < all.size(); ++i) {
    const std::vector<glm::vec3> expected = referenceColumns(all[i]);
    totals += expected[kScalars].z > 0.5f ? 1 : 0;
    for (int c = 0; c < kColumns; ++c) {
      const glm::vec3 got = gpu[i * kColumns + static_cast<size_t>(c)];
      const glm::vec3 want = expected[static_cast<size_t>(c)];
      for (int k = 0; k < 3; ++k) {
        const float difference = std::abs(got[k] - want[k]);
        worst = std::max(worst, difference);
        EXPECT_LE(difference, kTolerance)
            << "sample " << i << ", " << kColumnNames[c] << "[" << k << "]: GPU " << got[k]
            << ", reference " << want[k] << " (ior " << all[i].ior << ", fresnel " << all[i].fresnel
            << ")";
      }
    }
  }
  // The samples reach total internal reflection, and not everywhere.
  EXPECT_GT(totals, 0);
  EXPECT_LT(totals, static_cast<int>(all.size()));
  std::printf("%zu samples, largest difference %g\n", all.size(), static_cast<double>(worst));
}

}  // namespace
}  // namespace reflect
