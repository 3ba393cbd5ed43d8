#include "gfx/probe_prefilter.h"

#include <algorithm>
#include <string>

#include "core/ggx.h"
#include "gfx/gl.h"

namespace reflect {

bool PrefilteredCube::ensure(int faceSize, bool halfFloat, int top) {
  if (texture_.id() != 0 && faceSize_ == faceSize && halfFloat_ == halfFloat && top_ >= top) {
    return true;
  }
  texture_ = TextureHandle(genTexture());
  faceSize_ = faceSize;
  halfFloat_ = halfFloat;
  top_ = top;
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
  for (int mip = 0; mip < top; ++mip) {
    const int size = std::max(faceSize >> (mip + 1), 1);
    for (GLenum face = 0; face < 6; ++face) {
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, mip, halfFloat ? GL_RGBA16F : GL_RGBA8,
                   size, size, 0, GL_RGBA, halfFloat ? GL_HALF_FLOAT : GL_UNSIGNED_BYTE, nullptr);
    }
  }
  // Trilinear: a reader between two rough levels blends them.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, std::max(top - 1, 0));
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  // Levels no reader needs are never drawn: black, not whatever the driver left (a reader's
  // blend weighs them by 0, and 0 x NaN would not be 0).
  GLuint framebuffer = genFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  for (int mip = 0; mip < top; ++mip) {
    for (GLenum face = 0; face < 6; ++face) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                             GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, texture_.id(), mip);
      glClear(GL_COLOR_BUFFER_BIT);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  return checkGlError("allocate prefiltered cube");
}

Result<ProbePrefilter> ProbePrefilter::create() {
  auto built = TabledProgram<Uniforms>::build(
      "fullscreen.vert", "prefilter.frag", false,
      "#define PREFILTER_MAX_SAMPLES " + std::to_string(kMaxFilterSamples) + "\n");
  if (!built) return Result<ProbePrefilter>::failure(built.error());
  ProbePrefilter p;
  p.program_ = built.take();
  glUseProgram(p.program_.id());
  p.program_.u().source.set(0);
  glUseProgram(0);
  p.framebuffer_ = FramebufferHandle(genFramebuffer());
  return p;
}

Result<double> ProbePrefilter::filter(const PrefilterJob& job, PrefilteredCube& target) {
  if (job.levels.empty() || job.faces == 0) return 0.0;
  if (!target.ensure(job.faceSize, job.halfFloat, job.levels.back())) {
    return Result<double>::failure("GL error while allocating a prefiltered cube");
  }
  // The source's box chain, read with trilinear filtering by this pass alone.
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, job.source);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  GLint ownFilter = GL_LINEAR;
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, &ownFilter);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  double taken = 0.0;
  for (int level : job.levels) {
    const int size = std::max(job.faceSize >> level, 1);
    glViewport(0, 0, size, size);
    const Uniforms& u = program_.u();
    u.targetSize.set(static_cast<float>(size));
    const std::vector<glm::vec4> lobe = prefilterLobe(
        ggxAlpha(roughnessOfLevel(level, job.roughLevels)), job.samples, job.faceSize);
    u.lobe.set(lobe.data(), lobe.size());
    u.samples.set(static_cast<int>(lobe.size()));
    for (int face = 0; face < 6; ++face) {
      if ((job.faces & (1u << face)) == 0) continue;
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                             GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face),
                             target.texture(), level - 1);
      u.face.set(face);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      taken += static_cast<double>(size) * size * static_cast<double>(lobe.size());
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, ownFilter);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glUseProgram(0);
  if (!checkGlError("prefilter probe")) {
    return Result<double>::failure("GL error while prefiltering a probe");
  }
  return taken;
}

}  // namespace reflect
