// Diffuse light from the live probes (docs/rough.md, "Diffuse light from the probe"): after a
// capture, each probe with probe-lit readers (ProbePlan::diffuseReaders) has its cube projected
// on the order-2 spherical harmonics (shaders/irradiance_project.vert) into a uniform buffer of its
// own, nine vec4s (colour in rgb, w unused), which phong.frag reads as its ProbeIrradiance
// block (AMBIENT_PROBE). The projection runs only when the plan says a face of the probe was
// redrawn (ProbePlan::projectIrradiance), or the probe has no buffer yet; it reads the capture's
// box mip chain (CaptureFormat::boxChain) through a sampler of its own and nothing comes back to
// the CPU. The same chain, read trilinearly, gives the parallax taps (feedParallax,
// irradiance_parallax.glsl).
#pragma once

#include <map>

#include "core/frame_planner.h"
#include "core/irradiance.h"
#include "core/result.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"

namespace reflect {

// The uniform block binding every probe-lit draw reads its probe's irradiance from.
inline constexpr GLuint kIrradianceBinding = 0;

class ProbeIrradiance {
 public:
  static Result<ProbeIrradiance> create();
  // Projects the probes the plan asks for (and any reader's probe without a buffer yet);
  // `cubeOf(owner)` gives a probe's captured cube texture and face size, 0 when it has none.
  // Returns the number of probes projected.
  template <typename CubeOf>
  int update(const FramePlan& plan, const CubeOf& cubeOf) {
    int projected = 0;
    for (const ProbePlan& probe : plan.probes) {
      if (probe.diffuseReaders.empty()) continue;
      if (!probe.projectIrradiance && buffer(probe.reflector) != 0) continue;
      const auto [cube, faceSize] = cubeOf(probe.reflector);
      if (cube == 0) continue;
      project(probe.reflector, cube, faceSize);
      ++projected;
    }
    return projected;
  }
  // The buffer of the probe owned by object `owner` (0 before its first projection).
  GLuint buffer(int owner) const;
  // Binds the buffer of the probe probe-lit `object` reads (plan.irradianceOf) to
  // kIrradianceBinding; false when it has none yet (the draw then lights it with zeros).
  bool bindFor(const FramePlan& plan, int object) const;
  // The parallax taps (irradiance_parallax.glsl) for each vertex of a probe-lit object's mesh
  // (its vertex array and count, placed by `model`), read from `cube` (faceSize texels, its box
  // chain trilinearly) about `centre` with the capture's `near` plane, by transform feedback into
  // a buffer of the object's own, which it returns for mesh.vert's a_ambientParallax. The program
  // in use before is in use after.
  GLuint feedParallax(int object, GLuint vertexArray, GLsizei vertexCount, const glm::mat4& model,
                      GLuint cube, int faceSize, const glm::vec3& centre, float near) const;
  // The mip level the projection reads a cube of faceSize at: the first whose faces are under 16
  // texels square (8 x 8 for 256- and 32-texel faces; the whole face below 16). Order 2 keeps
  // nothing narrower than about a radian; 16 x 16 cost twice as much for the same pixels.
  static int levelFor(int faceSize);
  // Probes with a buffer, for tests.
  size_t buffers() const { return buffers_.size(); }

 private:
  ProbeIrradiance() = default;
  void project(int owner, GLuint cube, int faceSize);
  // Draws `count` points of the program and vertex array in use with the rasteriser off, their
  // outputs written into `buffer` by transform feedback.
  void writePoints(GLsizei count, GLuint buffer) const;

  ShaderProgram program_;
  GLint probeUnit_ = -1, lod_ = -1, grid_ = -1;
  SamplerHandle sampler_;          // reads the box chain's mips whatever the cube's own filter
  SamplerHandle parallaxSampler_;  // ... trilinearly, for the parallax taps
  ShaderProgram parallax_;         // parallax_feedback.vert
  GLint parallaxModel_ = -1, parallaxNormals_ = -1, parallaxCube_ = -1, parallaxProbe_ = -1,
        parallaxLevels_ = -1;
  struct PerVertex {
    BufferHandle buffer;
    GLsizei vertices = 0;
  };
  // By the probe-lit object's index: rewritten every frame the object is drawn, a cache.
  mutable std::map<int, PerVertex> parallaxBuffers_;
  TransformFeedbackHandle feedback_;
  VertexArrayHandle vertexArray_;        // the nine vertices have no attributes
  BufferHandle empty_;                   // bound while a reader's probe has no buffer yet (zeros)
  std::map<int, BufferHandle> buffers_;  // by the probe owner's index
};

}  // namespace reflect
