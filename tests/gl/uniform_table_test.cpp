// Uniforms as a typed table (gfx/uniform_table.h): every uniform a shader reads has an entry that
// sets it. Before the table, a positional struct left u_captureGuessDepth unlocated, so the
// shaders read 0 for it for as long as it existed; these tests would have named it.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/headless_frames.h"
#include "gfx/scene_renderer.h"
#include "gfx/uniform_table.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr const char* kVertex =
    "uniform mat4 u_m;\nin vec3 a;\nvoid main() { gl_Position = u_m * vec4(a, 1.0); }\n";
constexpr const char* kFragment =
    "uniform float u_a;\nuniform vec3 u_b;\nuniform vec3 u_list[3];\nout vec4 c;\n"
    "void main() { c = vec4(u_b * u_a + u_list[2], 1.0); }\n";

struct Partial : UniformTable {
  Uniform<glm::mat4> m{*this, "u_m"};
  Uniform<float> a{*this, "u_a"};
};

TEST(UniformTable, NamesTheActiveUniformsNoEntrySets) {
  Result<ShaderProgram> program =
      ShaderProgram::buildFromSource("table.vert", kVertex, "table.frag", kFragment);
  ASSERT_TRUE(program) << program.error();
  Partial table;
  table.locate(program.value());
  EXPECT_GE(table.a.location(), 0);
  EXPECT_GE(table.m.location(), 0);
  const std::vector<std::string> unset = table.unlisted(program.value().id());
  EXPECT_EQ(unset, (std::vector<std::string>{"u_b", "u_list"}))
      << "arrays are named without [0], in the driver's order: sort if that ever differs";
}

TEST(UniformTable, AnEntryTheProgramLacksIsMinusOne) {
  Result<ShaderProgram> program =
      ShaderProgram::buildFromSource("table.vert", kVertex, "table.frag", kFragment);
  ASSERT_TRUE(program) << program.error();
  struct Extra : UniformTable {
    Uniform<int> missing{*this, "u_notInTheShader"};
  } table;
  table.locate(program.value());
  EXPECT_EQ(table.missing.location(), -1);
}

// Every variant the shipped scenes build, under the settings that pick different programs.
TEST(UniformTable, EveryVariantOfEveryShippedSceneSetsEachUniformItReads) {
  std::vector<AccuracySettings> settings(5);
  settings[1].search = Search::Hierarchical;
  settings[2].search = Search::Linear;
  settings[3].search = Search::Plain;
  settings[3].captureAtOrigin = true;
  settings[4].search = Search::Exact;
  // Each with its roughness as shipped, and two made rough (every mirror and glass 0.5): the
  // skybox's readers of the static sky and the glass cube leaving by its map, which no shipped
  // scene has rough.
  const std::string glassCube = std::string(TEST_DATA_DIR) + "/glass-cube.json";
  std::vector<std::pair<std::string, bool>> scenes;
  for (const std::string& name : shippedSceneNames()) scenes.emplace_back(name, false);
  scenes.emplace_back(glassCube, false);  // glass leaving by its map
  scenes.emplace_back("skybox", true);
  scenes.emplace_back(glassCube, true);
  for (const auto& [name, roughened] : scenes) {
    Result<Scene> scene = loadNamedScene(name);
    ASSERT_TRUE(scene) << scene.error();
    Scene loaded = scene.take();
    if (roughened) {
      for (SceneObject& o : loaded.objects) o.roughness = 0.5f;
    }
    auto demo = testing::makeDemo(std::move(loaded));
    for (const AccuracySettings& s : settings) {
      ASSERT_EQ(demo->setAccuracySettings(s), "");
      ASSERT_TRUE(renderFrameAt(*demo, 1.0, 48, 48)) << name;
      const std::vector<std::string> unset = demo->renderer()->unsetUniforms();
      EXPECT_TRUE(unset.empty()) << name << " (" << s.describe()
                                 << "): " << ::testing::PrintToString(unset);
      EXPECT_GT(demo->renderer()->programCount(), 0u);
    }
  }
}

}  // namespace
}  // namespace reflect
