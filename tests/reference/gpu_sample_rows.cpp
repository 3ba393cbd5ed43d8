#include "gpu_sample_rows.h"

#include <gtest/gtest.h>

#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gfx/shader_library.h"

namespace reflect::testing {

std::vector<glm::vec3> drawSampleRows(
    const char* library, const char* main, int columns, int rows,
    const std::function<void(const ShaderProgram& program, int row)>& setUniforms) {
  const std::string fragment = std::string(embeddedShader(library)) + main;
  const std::string label = std::string(library) + " + test";
  Result<ShaderProgram> program = ShaderProgram::buildFromSource(
      "fullscreen.vert", embeddedShader("fullscreen.vert"), label, fragment.c_str(), false, "");
  EXPECT_TRUE(program) << program.error();
  Result<OffscreenTarget> target = OffscreenTarget::create(columns, rows, true);
  EXPECT_TRUE(target) << target.error();
  if (!program || !target) return {};
  VertexArrayHandle vao(genVertexArray());
  glBindFramebuffer(GL_FRAMEBUFFER, target.value().framebuffer());
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program.value().id());
  glBindVertexArray(vao.id());
  for (int i = 0; i < rows; ++i) {
    setUniforms(program.value(), i);
    glViewport(0, i, columns, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // readFloats gives the top row first: sample i is row rows - 1 - i.
  const std::vector<glm::vec3> flipped = target.value().readFloats();
  std::vector<glm::vec3> out;
  for (int i = 0; i < rows; ++i) {
    const auto row = flipped.begin() + static_cast<std::ptrdiff_t>((rows - 1 - i) * columns);
    out.insert(out.end(), row, row + columns);
  }
  return out;
}

}  // namespace reflect::testing
