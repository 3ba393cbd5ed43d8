// Scene files: the shipped ones parse (and Ex12-2's equals the built-in scene), and every kind of
// mistake is reported with the file name and the key path.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/json_reader.h"
#include "core/scene_file.h"

namespace reflect {
namespace {

const std::string kScenes = std::string(SCENE_DIR) + "/";

std::string errorOf(const std::string& json) {
  Result<Scene> r = parseSceneJson(json, "x.json");
  EXPECT_FALSE(r) << json;
  return r ? std::string() : r.error();
}

constexpr const char* kQuad = R"({"mesh": "quad.obj"})";

std::string withObject(const std::string& object) {
  return std::string(R"({"objects": [)") + object + "]}";
}

TEST(SceneFile, Ex12_2FileIsTheBuiltInScene) {
  Result<Scene> file = loadSceneFile(kScenes + "ex12-2.json");
  ASSERT_TRUE(file) << file.error();
  const Scene built = makeDynamicReflectionScene();
  const Scene& s = file.value();
  EXPECT_EQ(s.name, "ex12-2");
  ASSERT_EQ(s.objects.size(), built.objects.size());
  for (size_t i = 0; i < s.objects.size(); ++i) {
    EXPECT_EQ(s.objects[i].mesh, built.objects[i].mesh);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        EXPECT_FLOAT_EQ(s.objects[i].placement[c][r], built.objects[i].placement[c][r]) << i;
      }
    }
    EXPECT_EQ(s.objects[i].colour, built.objects[i].colour);
    EXPECT_EQ(s.objects[i].material, built.objects[i].material);
    EXPECT_EQ(s.objects[i].motion, built.objects[i].motion);
    EXPECT_EQ(s.modelMatrix(s.objects[i], 3.7), built.modelMatrix(built.objects[i], 3.7)) << i;
  }
  EXPECT_EQ(s.clearColour, built.clearColour);
  EXPECT_EQ(s.light.position, built.light.position);
  EXPECT_EQ(s.camera.eye, built.camera.eye);
  EXPECT_EQ(s.capture.faceSize, 256);
}

TEST(SceneFile, EveryShippedSceneParses) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    Result<Scene> r = loadSceneFile(entry.path().string());
    EXPECT_TRUE(r) << r.error();
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(SceneFile, MaterialsAnimationsProbesAndSkyboxes) {
  Result<Scene> r = parseSceneJson(R"({
    "skybox": "sky/day.png",
    "objects": [
      {"mesh": "a.obj", "material": {"type": "glass", "ior": 1.33, "fresnel": true}, "probe": "p"},
      {"mesh": "b.obj", "material": {"type": "mirror", "environment": "skybox"}, "probe": "p"},
      {"mesh": "c.obj", "material": {"type": "cube-textured"}, "probeCentre": [0, 0, 0],
       "animation": {"type": "spin", "degreesPerSecond": 90, "axis": [1, 1, 1]}}
    ]})",
                                   "x.json");
  ASSERT_TRUE(r) << r.error();
  const Scene& s = r.value();
  EXPECT_EQ(s.skybox.faces[0], "sky/day_px.png");
  EXPECT_EQ(s.skybox.faces[5], "sky/day_nz.png");
  EXPECT_EQ(s.objects[0].material, Material::Glass);
  EXPECT_FLOAT_EQ(s.objects[0].ior, 1.33f);
  EXPECT_TRUE(s.objects[0].fresnel);
  EXPECT_EQ(s.objects[0].probeGroup, s.objects[1].probeGroup);
  EXPECT_EQ(s.objects[1].environment, Environment::Skybox);
  EXPECT_FALSE(s.objects[1].needsLiveProbe());
  EXPECT_EQ(s.objects[2].motion, Motion::Spin);
  EXPECT_EQ(*s.objects[2].probeCentre, glm::vec3(0));
  EXPECT_EQ(s.reflectorIndex(), 0);
  Result<Scene> cross = parseSceneJson(
      R"({"skybox": {"cross": "sky.png"}, "objects": [{"mesh": "a.obj"}]})", "y.json");
  ASSERT_TRUE(cross) << cross.error();
  EXPECT_EQ(cross.value().skybox.cross, "sky.png");
}

TEST(SceneFile, ErrorsNameTheFileAndTheKeyPath) {
  EXPECT_EQ(errorOf("{\"objects\": [\n  {\"mesh\": }\n]}")
                .rfind("x.json: not valid JSON: line 2, column 12", 0),
            0u);
  EXPECT_EQ(errorOf("[]"), "x.json: top level: expected an object");
  // Nesting is bounded (the web build's stack is small); the limit itself is still read.
  const auto nested = [](int depth) {
    return R"({"objects": [{"mesh": "a.obj"}], "title": )" + std::string(depth - 1, '[') +
           std::string(depth - 1, ']') + "}";
  };
  EXPECT_EQ(errorOf(nested(kMaxJsonDepth)), "x.json: title: expected a string");
  EXPECT_EQ(errorOf(nested(kMaxJsonDepth + 1)),
            "x.json: not valid JSON: arrays and objects nested deeper than 64 levels");
  EXPECT_EQ(errorOf(nested(100000)),
            "x.json: not valid JSON: arrays and objects nested deeper than 64 levels");
  EXPECT_EQ(errorOf("{}"), "x.json: objects: missing (expected an array)");
  EXPECT_EQ(errorOf(R"({"objects": []})"), "x.json: objects: a scene needs at least one object");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": "a.obj"}], "colour": 1})"),
            "x.json: colour: unknown key");
  EXPECT_EQ(
      errorOf(withObject(
          std::string(kQuad) +
          R"(, {"mesh": "b.obj"}, {"mesh": "c.obj", "material": {"type": "glass", "ior": "high"}})")),
      "x.json: objects[2].material.ior: expected a number");
  EXPECT_EQ(errorOf(withObject(R"({"mesh": "c.obj", "material": {"type": "glass", "ior": 0.5}})")),
            "x.json: objects[0].material.ior: expected a number from 1 to 4");
  EXPECT_EQ(errorOf(withObject(R"({"mesh": "c.obj", "material": {"type": "chrome"}})")),
            "x.json: objects[0].material.type: expected one of phong, mirror, glass, "
            "cube-textured");
  EXPECT_EQ(errorOf(withObject(R"({"mesh": "../../etc/passwd"})")),
            "x.json: objects[0].mesh: expected a relative file path (letters, digits, _ - . /)");
  EXPECT_EQ(errorOf(withObject(R"({"colour": [1, 1, 1]})")),
            "x.json: objects[0].mesh: missing (expected an .obj file name)");
  EXPECT_EQ(errorOf(withObject(R"({"mesh": "a.obj", "translate": [1, 2]})")),
            "x.json: objects[0].translate: expected an array of 3 numbers");
  EXPECT_EQ(errorOf(withObject(
                R"({"mesh": "a.obj", "animation": {"type": "orbit", "axis": [0, 0, 0]}})")),
            "x.json: objects[0].animation.axis: must not be zero");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": "a.obj"}], "capture": {"faceSize": 100000}})"),
            "x.json: capture.faceSize: expected a number from 1 to 4096");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": "a.obj"}], "skybox": {"faces": ["a.png"]}})"),
            "x.json: skybox.faces: expected 6 paths in the order +X -X +Y -Y +Z -Z");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": "a.obj"}], "camera": {"near": 10, "far": 5}})"),
            "x.json: camera.far: must be greater than near");
  EXPECT_EQ(loadSceneFile("/no/such/scene.json").error(), "/no/such/scene.json: cannot open file");
  EXPECT_NE(errorOf(std::string(2u << 20, ' ')).find("over the limit"), std::string::npos);
}

}  // namespace
}  // namespace reflect
