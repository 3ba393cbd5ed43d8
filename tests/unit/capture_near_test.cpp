// The notice that a scene's capture near plane lies outside a reflector with a probe of its own
// (core/capture_near.h): which objects, and the largest near plane that would keep what passes
// close in the captures.
#include <gtest/gtest.h>

#include "core/capture_near.h"
#include "core/scene_file.h"

namespace reflect {
namespace {

// Every mesh a box of half side 1 about the origin; "missing.obj" not loaded.
const Bounds kUnitBox{glm::vec3(-1.0f), glm::vec3(1.0f)};
const Bounds* unitBoxes(const std::string& name) {
  return name == "missing.obj" ? nullptr : &kUnitBox;
}

Scene sceneOf(const std::string& objects, float near) {
  Result<Scene> scene = parseSceneJson(
      R"({"capture": {"near": )" + std::to_string(near) + R"(}, "objects": [)" + objects + "]}",
      "spheres.json");
  EXPECT_TRUE(scene) << scene.error();
  Scene s = scene ? scene.take() : Scene{};
  s.name = "spheres";
  return s;
}

constexpr const char* kMirror = R"({"mesh": "sphere.obj", "scale": 0.6,
                                    "material": {"type": "mirror"}})";
constexpr const char* kGlass = R"({"mesh": "sphere.obj", "scale": 0.9, "translate": [3, 0, 0],
                                   "material": {"type": "glass"}})";

TEST(CaptureNear, NamesTheReflectorsItLiesOutsideAndTheNearPlaneThatWouldDo) {
  const Scene scene = sceneOf(
      std::string(R"({"mesh": "quad.obj", "scale": 0.1}, )") + kMirror + ", " + kGlass, 1.0f);
  EXPECT_EQ(captureNearNotice(scene, unitBoxes),
            "spheres: capture.near 1 lies outside objects 1 and 2 (sphere.obj), whose boxes reach "
            "as near as 0.6 to their centres: a probe's captures leave out what passes nearer "
            "its centre than the near plane; set capture.near to at most 0.6");
}

TEST(CaptureNear, OneReflectorIsNamedInTheSingular) {
  const Scene scene = sceneOf(std::string(kMirror) + ", " + kGlass, 0.7f);
  EXPECT_EQ(captureNearNotice(scene, unitBoxes),
            "spheres: capture.near 0.7 lies outside object 0 (sphere.obj), whose box reaches as "
            "near as 0.6 to its centre: a probe's captures leave out what passes nearer its "
            "centre than the near plane; set capture.near to at most 0.6");
}

TEST(CaptureNear, AFigureWithAnIrradianceProbeOfItsOwnIsHeldToItToo) {
  const Scene scene = sceneOf(
      R"({"mesh": "mario.obj", "scale": 0.3, "ambient": "own-probe"},
         {"mesh": "sonic.obj", "scale": 0.3, "ambient": "constant"})",
      0.5f);
  EXPECT_EQ(captureNearNotice(scene, unitBoxes),
            "spheres: capture.near 0.5 lies outside object 0 (mario.obj), whose box reaches as "
            "near as 0.3 to its centre: a probe's captures leave out what passes nearer its "
            "centre than the near plane; set capture.near to at most 0.3");
}

TEST(CaptureNear, SaysNothingWhereThePlaneIsInsideOrTheProbeIsNotAtTheCentre) {
  EXPECT_EQ(captureNearNotice(sceneOf(kMirror, 0.6f), unitBoxes), "");
  // Phong objects have no probe; the static sky needs none; a shared probe or one the file places
  // is not at the object's centre; a mesh not loaded has no box yet.
  const std::string others =
      R"({"mesh": "a.obj", "scale": 0.1},
         {"mesh": "b.obj", "scale": 0.1, "material": {"type": "mirror", "environment": "skybox"}},
         {"mesh": "c.obj", "scale": 0.1, "material": {"type": "mirror"}, "probe": "pair"},
         {"mesh": "d.obj", "scale": 0.1, "material": {"type": "mirror"}, "probeCentre": [0, 0, 0]},
         {"mesh": "missing.obj", "scale": 0.1, "material": {"type": "mirror"}})";
  EXPECT_EQ(captureNearNotice(sceneOf(others, 1.0f), unitBoxes), "");
}

}  // namespace
}  // namespace reflect
