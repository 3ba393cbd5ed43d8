// libFuzzer target: parseSceneJson (nlohmann::json, then the scene's own checks) on arbitrary
// bytes. An accepted scene must hold only finite numbers where the renderer multiplies them; a
// rejection's message must name the input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/scene_file.h"

namespace {

constexpr const char* kName = "fuzz.json";

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_scene: invariant broken: %s\n", what);
  std::abort();
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    if (!std::isfinite(m[c].x) || !std::isfinite(m[c].y) || !std::isfinite(m[c].z) ||
        !std::isfinite(m[c].w))
      return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  reflect::Result<reflect::Scene> scene = reflect::parseSceneJson(text, kName);
  if (!scene) {
    if (scene.error().find(kName) == std::string::npos)
      fail("error message does not name the input");
    return 0;
  }
  const reflect::Scene& s = scene.value();
  if (!finite(s.camera.eye) || !finite(s.light.position) || !finite(s.clearColour)) {
    fail("non-finite camera, light or clear colour");
  }
  for (const reflect::SceneObject& o : s.objects) {
    if (!finite(o.placement) || !finite(o.colour) || !finite(o.axis) ||
        !std::isfinite(o.degreesPerSecond)) {
      fail("non-finite object field");
    }
    // The model matrix at a few times must stay finite too.
    for (double t : {0.0, 1.0, 1e6}) {
      if (!finite(s.modelMatrix(o, t))) fail("non-finite model matrix");
    }
  }
  return 0;
}
