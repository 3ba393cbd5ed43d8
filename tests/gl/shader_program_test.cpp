// Shader programs fail loudly: a compile or link failure names the stage and the file, with the
// driver's log, and a file the build did not embed is named.
#include <gtest/gtest.h>

#include "gfx/shader_program.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

constexpr const char* kVertex = "void main() { gl_Position = vec4(0.0); }\n";
constexpr const char* kFragment = "out vec4 colour;\nvoid main() { colour = vec4(1.0); }\n";

TEST(ShaderProgram, CompileFailureNamesTheStageAndTheFile) {
  Result<ShaderProgram> bad = ShaderProgram::buildFromSource(
      "plain.vert", kVertex, "broken.frag", "out vec4 colour;\nvoid main() { colour = 1; }\n");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("fragment shader broken.frag failed to compile:"), std::string::npos)
      << bad.error();
  Result<ShaderProgram> badVertex = ShaderProgram::buildFromSource(
      "broken.vert", "void main() { gl_Position = 0; }\n", "plain.frag", kFragment);
  ASSERT_FALSE(badVertex);
  EXPECT_NE(badVertex.error().find("vertex shader broken.vert failed to compile:"),
            std::string::npos)
      << badVertex.error();
  Result<ShaderProgram> good =
      ShaderProgram::buildFromSource("plain.vert", kVertex, "plain.frag", kFragment);
  EXPECT_TRUE(good) << good.error();
}

TEST(ShaderProgram, LinkFailureNamesBothFiles) {
  // The fragment shader reads a varying the vertex shader does not write.
  Result<ShaderProgram> bad = ShaderProgram::buildFromSource(
      "plain.vert", kVertex, "reads.frag",
      "in vec3 v_missing;\nout vec4 colour;\nvoid main() { colour = vec4(v_missing, 1.0); }\n");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("program plain.vert + reads.frag failed to link:"), std::string::npos)
      << bad.error();
}

TEST(ShaderProgram, MissingFileIsNamed) {
  Result<ShaderProgram> missing = ShaderProgram::build("fullscreen.vert", "no_such.frag");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), "shader no_such.frag: not embedded in this build");
}

TEST(ShaderProgram, DefinesReachTheFragmentShader) {
  // A define that breaks the fragment shader proves the defines are compiled with it.
  Result<ShaderProgram> broken =
      ShaderProgram::build("fullscreen.vert", "depth_reduce.frag", false, "#error by design\n");
  ASSERT_FALSE(broken);
  EXPECT_NE(broken.error().find("fragment shader depth_reduce.frag failed to compile:"),
            std::string::npos)
      << broken.error();
  EXPECT_TRUE(ShaderProgram::build("fullscreen.vert", "depth_reduce.frag"));
}

}  // namespace
}  // namespace reflect
