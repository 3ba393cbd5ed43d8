#include "bench/growth_bench.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/demo.h"
#include "app/headless_frames.h"

namespace reflect {
namespace {

// A UV sphere of about `triangles` triangles, radius 1.
MeshData uvSphere(size_t triangles, const std::string& name) {
  const int rings = std::max(3, static_cast<int>(std::sqrt(static_cast<double>(triangles) / 4.0)));
  const int segments = std::max(3, static_cast<int>(triangles / (2 * static_cast<size_t>(rings))));
  MeshData mesh;
  mesh.name = name;
  for (int r = 0; r <= rings; ++r) {
    const float theta =
        static_cast<float>(M_PI) * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi =
          2.0f * static_cast<float>(M_PI) * static_cast<float>(s) / static_cast<float>(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      mesh.vertices.push_back({n, n});
    }
  }
  const uint32_t row = static_cast<uint32_t>(segments + 1);
  for (uint32_t r = 0; r < static_cast<uint32_t>(rings); ++r) {
    for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
      const uint32_t a = r * row + s, b = a + row;
      if (r != 0) mesh.indices.insert(mesh.indices.end(), {a, a + 1, b});
      if (r + 1 != static_cast<uint32_t>(rings))
        mesh.indices.insert(mesh.indices.end(), {a + 1, b + 1, b});
    }
  }
  mesh.bounds = computeBounds(mesh.vertices);
  return mesh;
}

Scene growthScene(int reflectors, bool share) {
  Scene scene = makeDynamicReflectionScene();
  scene.objects.erase(scene.objects.begin() + 1, scene.objects.end());  // keep the ground
  for (int i = 0; i < 4; ++i) {
    SceneObject blob;
    blob.mesh = "blob.obj";
    const float angle = 90.0f * static_cast<float>(i);
    blob.placement =
        glm::scale(glm::translate(glm::rotate(glm::mat4(1.0f), glm::radians(angle), {0, 1, 0}),
                                  {0, -0.8f, 6.0f}),
                   glm::vec3(0.7f));
    blob.motion = Motion::Orbit;
    blob.colour = i % 2 ? glm::vec3(1.0f, 0.4f, 0.4f) : glm::vec3(0.4f, 1.0f, 0.4f);
    scene.objects.push_back(blob);
  }
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(reflectors))));
  for (int i = 0; i < reflectors; ++i) {
    SceneObject mirror;
    mirror.mesh = "sphere.obj";
    const float x = (static_cast<float>(i % side) - 0.5f * static_cast<float>(side - 1)) * 1.6f;
    const float z = (static_cast<float>(i / side) - 0.5f * static_cast<float>(side - 1)) * 1.6f;
    mirror.placement = glm::scale(glm::translate(glm::mat4(1.0f), {x, 0.0f, z}), glm::vec3(0.25f));
    mirror.colour = {0.95f, 0.85f, 0.4f};
    mirror.material = Material::Mirror;
    if (share) mirror.probeGroup = (i % side) / 2 + 100 * ((i / side) / 2);  // 2x2 neighbours
    scene.objects.push_back(mirror);
  }
  return scene;
}

}  // namespace

Result<std::string> runGrowthBench(const std::string& modelDirectory, const GrowthOptions& o) {
  const int reflectorCounts[] = {1, 4, 16};
  const size_t triangleCounts[] = {10'000, 100'000, 1'000'000};
  std::string out;
  char line[256];
  for (bool share : {false, true}) {
    out += share ? "\nneighbours share a probe (2x2 groups):\n" : "\na probe per reflector:\n";
    out += "| reflectors \\ scene triangles | 10k | 100k | 1M |\n|---|---|---|---|\n";
    for (int reflectors : reflectorCounts) {
      std::snprintf(line, sizeof line, "| %d |", reflectors);
      out += line;
      for (size_t triangles : triangleCounts) {
        Demo demo(growthScene(reflectors, share));
        std::string error = demo.loadMesh("sphere.obj", modelDirectory + "/sphere.obj");
        if (error.empty()) error = demo.loadMesh("quad.obj", modelDirectory + "/quad.obj");
        if (error.empty()) error = demo.setMeshData("blob.obj", uvSphere(triangles / 4, "blob"));
        if (error.empty()) error = demo.initGraphics();
        if (!error.empty()) return Result<std::string>::failure(error);
        demo.waitForLevels();
        auto r = benchFrames(demo, o.width, o.height, o.warmup, o.frames);
        if (!r) return Result<std::string>::failure(r.error());
        std::snprintf(line, sizeof line, " %.1f ms (%d probes, %.0f faces, %d traced) |",
                      median(r.value().frameMs), demo.lastStats().probes, r.value().facesPerFrame,
                      demo.lastStats().tracedReflectors);
        out += line;
        std::fprintf(stderr, ".");
      }
      out += "\n";
    }
  }
  std::fprintf(stderr, "\n");
  return out;
}

}  // namespace reflect
