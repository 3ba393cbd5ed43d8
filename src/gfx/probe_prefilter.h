// Rough mirrors' prefiltered probes (docs/rough.md): after a capture, the planner's levels
// (ProbePlan::roughLevels) of a probe's colour cube are filtered with the GGX lobe of their
// roughness into a cube of their own, which rough readers look up between two levels
// (environment.frag, ROUGH 1). Made only for probes that have a rough reader; nothing here runs
// for a scene of perfect mirrors.
//
// The filtered cube's mip i holds rough level i + 1 (roughness (i + 1) / roughLevels) at face
// size faceSize >> (i + 1); level 0, roughness 0, is the capture itself. Only the levels up to the
// highest one needed are allocated; those between that no reader needs stay black.
// The pass (fullscreen.vert + prefilter.frag) draws each face of each level with `samples` GGX
// samples a texel, each read from the capture's own box mip chain at the level that covers its
// share of the lobe (filtered importance sampling), so few samples suffice.
#pragma once

#include <map>
#include <vector>

#include "core/result.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"
#include "gfx/uniform_table.h"

namespace reflect {

// What one filter call needs to know of the probe and the settings.
struct PrefilterJob {
  GLuint source = 0;        // the capture's colour cube (level 0 drawn)
  int faceSize = 0;         // its level 0
  bool halfFloat = false;   // its format: RGBA16F, else RGBA8
  std::vector<int> levels;  // rough levels to filter, ascending (ProbePlan::roughLevels)
  int roughLevels = 1;      // accuracy.roughLevels: level m holds roughness m / roughLevels
  int samples = 32;         // accuracy.filterSamples
  unsigned faces = 0x3Fu;   // bit f: filter face f
};

class PrefilteredCube {
 public:
  GLuint texture() const { return texture_.id(); }
  // Allocates (or keeps) mips 0..top - 1 for a source of faceSize in the given format, cleared
  // to black. False on a GL error.
  bool ensure(int faceSize, bool halfFloat, int top);

 private:
  TextureHandle texture_;
  int faceSize_ = 0;
  bool halfFloat_ = false;
  int top_ = 0;  // mips allocated
};

class ProbePrefilter {
 public:
  static Result<ProbePrefilter> create();
  // Filters job.levels of job.faces into `target` (made to fit first). Generates the source's
  // box mip chain first (its own min filter stays LINEAR, so its sharp readers do not change).
  // Leaves framebuffer 0 bound and the viewport at the last level's: callers set their own.
  // Returns the samples taken (texels filtered x samples), the planner's measure of the work.
  Result<double> filter(const PrefilterJob& job, PrefilteredCube& target);

 private:
  struct Uniforms : UniformTable {
    Uniform<int> source{*this, "u_source"};  // unit 0
    Uniform<int> face{*this, "u_face"};
    UniformArray<glm::vec4> lobe{*this, "u_lobe"};
    Uniform<int> samples{*this, "u_samples"};
    Uniform<float> targetSize{*this, "u_targetSize"};
  };
  TabledProgram<Uniforms> program_;
  FramebufferHandle framebuffer_;
};

}  // namespace reflect
