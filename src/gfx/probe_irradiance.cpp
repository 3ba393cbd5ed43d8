#include "gfx/probe_irradiance.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "core/irradiance_parallax.h"
#include "core/normal_matrix.h"
#include "gfx/capture_state.h"
#include "gfx/gl.h"

namespace reflect {
namespace {

constexpr GLsizeiptr kBufferBytes = kIrradianceCoefficients * 4 * sizeof(float);
constexpr GLuint kProbeUnit = 0;

BufferHandle makeBuffer() {
  BufferHandle buffer(generateOne<glGenBuffers>());
  glBindBuffer(GL_UNIFORM_BUFFER, buffer.id());
  const std::array<float, kIrradianceCoefficients * 4> zeros{};
  glBufferData(GL_UNIFORM_BUFFER, kBufferBytes, zeros.data(), GL_DYNAMIC_COPY);
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
  return buffer;
}

}  // namespace

Result<ProbeIrradiance> ProbeIrradiance::create() {
  Result<ShaderProgram> program = ShaderProgram::build(
      "irradiance_project.vert", "no_fragment.frag", false, "", {"v_coefficient"});
  if (!program) return Result<ProbeIrradiance>::failure(program.error());
  ProbeIrradiance p;
  p.program_ = program.take();
  p.probeUnit_ = p.program_.uniform("u_probe");
  p.lod_ = p.program_.uniform("u_lod");
  p.grid_ = p.program_.uniform("u_grid");
  p.sampler_ = filteredSampler(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  Result<ShaderProgram> parallax =
      ShaderProgram::build("parallax_feedback.vert", "no_fragment.frag", false, "", {"v_parallax"});
  if (!parallax) return Result<ProbeIrradiance>::failure(parallax.error());
  p.parallax_ = parallax.take();
  p.parallaxModel_ = p.parallax_.uniform("u_model");
  p.parallaxNormals_ = p.parallax_.uniform("u_normalMatrix");
  p.parallaxCube_ = p.parallax_.uniform("u_parallaxCube");
  p.parallaxProbe_ = p.parallax_.uniform("u_parallaxProbe");
  p.parallaxLevels_ = p.parallax_.uniform("u_parallaxLevels");
  p.parallaxSampler_ = filteredSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  p.feedback_ = TransformFeedbackHandle(generateOne<glGenTransformFeedbacks>());
  p.vertexArray_ = VertexArrayHandle(generateOne<glGenVertexArrays>());
  p.empty_ = makeBuffer();
  if (!checkGlError("create the irradiance projection")) {
    return Result<ProbeIrradiance>::failure("GL error while creating the irradiance projection");
  }
  return p;
}

int ProbeIrradiance::levelFor(int faceSize) {
  int level = 0;
  while ((faceSize >> level) >= 16) ++level;
  return level;
}

void ProbeIrradiance::project(int owner, GLuint cube, int faceSize) {
  auto it = buffers_.find(owner);
  if (it == buffers_.end()) it = buffers_.emplace(owner, makeBuffer()).first;
  const int level = levelFor(faceSize);
  // WebGL refuses transform feedback into a buffer still bound elsewhere: the last probe-lit
  // draw left one at the uniform binding (and the generic one).
  glBindBufferBase(GL_UNIFORM_BUFFER, kIrradianceBinding, 0);
  glUseProgram(program_.id());
  glUniform1i(probeUnit_, static_cast<GLint>(kProbeUnit));
  glUniform1f(lod_, static_cast<float>(level));
  glUniform1i(grid_, std::max(faceSize >> level, 1));
  glActiveTexture(GL_TEXTURE0 + kProbeUnit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glBindSampler(kProbeUnit, sampler_.id());
  glBindVertexArray(vertexArray_.id());
  writePoints(kIrradianceCoefficients, it->second.id());
  glBindSampler(kProbeUnit, 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
}

void ProbeIrradiance::writePoints(GLsizei count, GLuint buffer) const {
  glEnable(GL_RASTERIZER_DISCARD);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback_.id());
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, count);
  glEndTransformFeedback();
  // WebGL refuses a buffer bound for transform feedback and read elsewhere: unbound at once.
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  glDisable(GL_RASTERIZER_DISCARD);
}

GLuint ProbeIrradiance::buffer(int owner) const {
  auto it = buffers_.find(owner);
  return it == buffers_.end() ? 0 : it->second.id();
}

bool ProbeIrradiance::bindFor(const FramePlan& plan, int object) const {
  const ProbePlan* probe = plan.irradianceOf(object);
  const GLuint b = probe ? buffer(probe->reflector) : 0;
  glBindBufferBase(GL_UNIFORM_BUFFER, kIrradianceBinding, b != 0 ? b : empty_.id());
  return b != 0;
}

GLuint ProbeIrradiance::feedParallax(int object, GLuint vertexArray, GLsizei vertexCount,
                                     const glm::mat4& model, GLuint cube, int faceSize,
                                     const glm::vec3& centre, float near) const {
  PerVertex& out = parallaxBuffers_[object];
  if (out.buffer.id() == 0 || out.vertices != vertexCount) {
    out.buffer = BufferHandle(generateOne<glGenBuffers>());
    glBindBuffer(GL_ARRAY_BUFFER, out.buffer.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertexCount) * 3 * sizeof(float), nullptr,
                 GL_DYNAMIC_COPY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    out.vertices = vertexCount;
  }
  GLint previous = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
  glUseProgram(parallax_.id());
  glUniformMatrix4fv(parallaxModel_, 1, GL_FALSE, glm::value_ptr(model));
  const glm::mat3 normals = normalMatrixOf(glm::mat3(model));
  glUniformMatrix3fv(parallaxNormals_, 1, GL_FALSE, glm::value_ptr(normals));
  glUniform1i(parallaxCube_, kParallaxUnit);
  glUniform4f(parallaxProbe_, centre.x, centre.y, centre.z, near);
  const ParallaxLevels levels = parallaxLevels(faceSize);
  glUniform2f(parallaxLevels_, levels.colour, levels.distance);
  glActiveTexture(GL_TEXTURE0 + kParallaxUnit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glBindSampler(kParallaxUnit, parallaxSampler_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(vertexArray);
  writePoints(vertexCount, out.buffer.id());
  glBindSampler(kParallaxUnit, 0);
  glActiveTexture(GL_TEXTURE0 + kParallaxUnit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(static_cast<GLuint>(previous));
  return out.buffer.id();
}

}  // namespace reflect
