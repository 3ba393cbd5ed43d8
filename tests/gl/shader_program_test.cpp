// Shader programs fail loudly: a compile or link failure names the stage and the file, with the
// driver's log, and a file the build did not embed is named.
#include <gtest/gtest.h>

#include "core/bvh.h"
#include "core/trace_limits.h"
#include "gfx/program_key.h"
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

TEST(ShaderProgram, DefinesReachBothShaders) {
  // A define that breaks the shaders proves the defines are compiled with them: the vertex shader,
  // compiled first, is the one named.
  Result<ShaderProgram> broken =
      ShaderProgram::build("fullscreen.vert", "depth_reduce.frag", false, "#error by design\n");
  ASSERT_FALSE(broken);
  EXPECT_NE(broken.error().find("vertex shader fullscreen.vert failed to compile:"),
            std::string::npos)
      << broken.error();
  EXPECT_TRUE(ShaderProgram::build("fullscreen.vert", "depth_reduce.frag"));
  // AMBIENT_PROBE adds a uniform block to phong.frag and the parallax attribute to mesh.vert: each
  // exists only if that stage saw the define.
  Result<ShaderProgram> lit = ShaderProgram::build(
      "mesh.vert", "phong.frag", false, "#define CAPTURE_OUTPUT 0\n#define AMBIENT_PROBE 1\n");
  ASSERT_TRUE(lit) << lit.error();
  EXPECT_NE(glGetUniformBlockIndex(lit.value().id(), "ProbeIrradiance"), GL_INVALID_INDEX);
  EXPECT_GE(glGetAttribLocation(lit.value().id(), "a_ambientParallax"), 0);
}

// The renderer builds a variant the first time a draw needs one: every variant it can ask for
// must compile and link, not only those the tests' scenes happen to draw.
TEST(ProgramKeys, EveryVariantBuilds) {
  std::vector<ProgramKey> keys;
  for (bool capture : {false, true}) {
    keys.push_back({Look::Phong, capture});
    keys.push_back({Look::CubeTextured, capture});
    for (Search search : {Search::Plain, Search::Linear, Search::Hierarchical, Search::Exact}) {
      for (bool refracts : {false, true}) {
        for (bool glassExit : {false, true}) {
          if (glassExit && (!refracts || search == Search::Exact)) continue;
          for (bool general : {false, true}) {
            if (search != Search::Exact && general) continue;
            if (search == Search::Exact && refracts && !general) continue;  // glass: general
            keys.push_back({Look::Environment, capture, search, refracts, glassExit, general});
          }
        }
      }
    }
  }
  EXPECT_EQ(keys.size(), 28u);  // two passes x (Phong, cube-textured, 12 environment variants)
  for (const ProgramKey& key : keys) {
    for (bool mediump : {false, true}) {
      const std::string precision = mediump ? "#define REFLECT_MEDIUMP 1\n" : "";
      Result<ShaderProgram> built =
          ShaderProgram::build("mesh.vert", key.fragmentFile(), mediump, precision + key.defines());
      EXPECT_TRUE(built) << key.describe() << (mediump ? ", mediump" : "") << ": "
                         << (built ? "" : built.error());
    }
  }
}

TEST(ProgramKeys, TheTracersConstantsComeFromTheCpp) {
  const std::string defines = ProgramKey{Look::Environment, false, Search::Exact}.defines();
  EXPECT_NE(defines.find("#define SEARCH SEARCH_EXACT\n"), std::string::npos);
  EXPECT_NE(defines.find("#define SEARCH_EXACT " + std::to_string(static_cast<int>(Search::Exact))),
            std::string::npos);
  EXPECT_NE(defines.find("#define EXACT_WIDTH_SHIFT " + std::to_string(kBvhTextureWidthShift)),
            std::string::npos);
  EXPECT_NE(defines.find("#define EXACT_INSTANCE_TEXELS " + std::to_string(kInstanceTexels)),
            std::string::npos);
  EXPECT_NE(defines.find("#define EXACT_MAX_BOUNCES " + std::to_string(kMaxBounces)),
            std::string::npos);
  // The main pass writes the colour alone; a capture its outputs too.
  const ProgramKey mainPass, capture{Look::Phong, true};
  EXPECT_NE(mainPass.defines().find("#define CAPTURE_OUTPUT 0"), std::string::npos);
  EXPECT_NE(capture.defines().find("#define CAPTURE_OUTPUT 1"), std::string::npos);
}

}  // namespace
}  // namespace reflect
