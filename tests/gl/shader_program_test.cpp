// Shader programs: a failure names the stage and the file, and a program started ahead
// (ShaderProgram::start, which the page calls while models download) is the one build() takes
// over, checked then, with nothing left behind.
#include <gtest/gtest.h>

#include "gfx/gl_handle.h"
#include "gfx/scene_renderer.h"
#include "gfx/shader_program.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

constexpr const char* kVertex = "void main() { gl_Position = vec4(0.0); }\n";
constexpr const char* kFragment = "out vec4 colour;\nvoid main() { colour = vec4(1.0); }\n";

const ProgramSource kReduce{"fullscreen.vert", "depth_reduce.frag", false, ""};

TEST(ShaderProgram, CompileFailureNamesTheStageAndTheFile) {
  Result<ShaderProgram> bad = ShaderProgram::buildFromSource(
      "plain.vert", kVertex, "broken.frag", "out vec4 colour;\nvoid main() { colour = 1; }\n");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("fragment shader broken.frag failed to compile:"), std::string::npos)
      << bad.error();
  Result<ShaderProgram> good =
      ShaderProgram::buildFromSource("plain.vert", kVertex, "plain.frag", kFragment);
  EXPECT_TRUE(good) << good.error();
}

TEST(ShaderProgram, MissingFileIsNamed) {
  Result<ShaderProgram> missing = ShaderProgram::build("fullscreen.vert", "no_such.frag");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), "shader no_such.frag: not embedded in this build");
  ShaderProgram::start({"fullscreen.vert", "no_such.frag", false, ""});
  EXPECT_EQ(ShaderProgram::startedCount(), 0u);  // left for build() to report
}

TEST(ShaderProgram, BuildTakesOverTheStartedProgram) {
  const long before = gLiveGlObjects;
  ShaderProgram::start(kReduce);
  ShaderProgram::start(kReduce);  // the same text twice: started once
  EXPECT_EQ(ShaderProgram::startedCount(), 1u);
  EXPECT_EQ(gLiveGlObjects, before + 3);  // two shaders and the program
  {
    Result<ShaderProgram> built = ShaderProgram::build(kReduce);
    ASSERT_TRUE(built) << built.error();
    EXPECT_EQ(ShaderProgram::startedCount(), 0u);
    EXPECT_EQ(gLiveGlObjects, before + 1);  // the shaders are freed once linked
    EXPECT_GE(built.value().uniform("u_source"), 0);
  }
  EXPECT_EQ(gLiveGlObjects, before);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ShaderProgram, DifferentDefinesAreADifferentProgram) {
  const long before = gLiveGlObjects;
  ShaderProgram::start({"fullscreen.vert", "depth_reduce.frag", false, "#define UNUSED 1\n"});
  Result<ShaderProgram> built = ShaderProgram::build(kReduce);
  ASSERT_TRUE(built) << built.error();
  EXPECT_EQ(ShaderProgram::startedCount(), 1u);  // not taken: other text
  ShaderProgram::dropStarted();
  EXPECT_EQ(ShaderProgram::startedCount(), 0u);
  EXPECT_EQ(gLiveGlObjects, before + 1);  // only the built program
}

TEST(ShaderProgram, StartedProgramThatFailsIsReportedAtBuild) {
  const ProgramSource broken{"fullscreen.vert", "depth_reduce.frag", false,
                             "#error deliberately broken\n"};
  ShaderProgram::start(broken);
  Result<ShaderProgram> built = ShaderProgram::build(broken);
  ASSERT_FALSE(built);
  EXPECT_NE(built.error().find("fragment shader depth_reduce.frag failed to compile:"),
            std::string::npos)
      << built.error();
  EXPECT_EQ(ShaderProgram::startedCount(), 0u);
}

// The renderer's list of programs to start is the list create() builds: every started program is
// taken, for each lookup.
TEST(ShaderProgram, RendererTakesEveryProgramItStarted) {
  for (Search search : {Search::Plain, Search::Linear, Search::Hierarchical, Search::Exact}) {
    AccuracySettings accuracy;
    accuracy.search = search;
    SceneRenderer::startPrograms(accuracy);
    const bool searches = search == Search::Linear || search == Search::Hierarchical;
    EXPECT_EQ(ShaderProgram::startedCount(), searches ? 6u : 5u);
    Result<SceneRenderer> renderer = SceneRenderer::create(accuracy);
    ASSERT_TRUE(renderer) << renderer.error();
    EXPECT_EQ(ShaderProgram::startedCount(), 0u) << static_cast<int>(search);
  }
}

}  // namespace
}  // namespace reflect
