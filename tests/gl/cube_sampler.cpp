#include "cube_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"

namespace reflect::testing {

namespace {

constexpr int kDirectionsPerDraw = 32;

// Pixel i of a one-pixel-high strip is texture(cube, u_directions[i]).
constexpr const char* kSampleVertex = R"(
void main() {
  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(p, 0.0, 1.0);
})";
constexpr const char* kSampleFragment = R"(
uniform samplerCube u_cube;
uniform vec3 u_directions[32];
out vec4 colour;
void main() { colour = texture(u_cube, u_directions[int(gl_FragCoord.x)]); })";

}  // namespace

std::vector<glm::u8vec3> sampleCube(GLuint cube, const std::vector<glm::vec3>& directions) {
  std::vector<glm::u8vec3> colours;
  auto program =
      ShaderProgram::buildFromSource("sample.vert", kSampleVertex, "sample.frag", kSampleFragment);
  EXPECT_TRUE(program) << program.error();
  if (!program) return colours;
  for (size_t first = 0; first < directions.size(); first += kDirectionsPerDraw) {
    const int n = static_cast<int>(std::min<size_t>(kDirectionsPerDraw, directions.size() - first));
    RenderbufferHandle colour(genRenderbuffer());
    glBindRenderbuffer(GL_RENDERBUFFER, colour.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, n, 1);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    FramebufferHandle framebuffer(genFramebuffer());
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour.id());
    glViewport(0, 0, n, 1);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(program.value().id());
    glUniform3fv(program.value().uniform("u_directions"), n, glm::value_ptr(directions[first]));
    glUniform1i(program.value().uniform("u_cube"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    std::vector<uint8_t> strip(static_cast<size_t>(n) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, strip.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    for (int i = 0; i < n; ++i) {
      colours.emplace_back(strip[static_cast<size_t>(i) * 4], strip[static_cast<size_t>(i) * 4 + 1],
                           strip[static_cast<size_t>(i) * 4 + 2]);
    }
  }
  EXPECT_TRUE(checkGlError("sample cube"));
  return colours;
}

}  // namespace reflect::testing
