#include "bench/growth_bench.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/demo.h"
#include "app/headless_frames.h"
#include "app/held_trees.h"
#include "core/traced_rays.h"

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

// One cell of a table: a scene's frames timed, and the rays of its last timed frame counted.
struct Cell {
  double frameMs = 0.0;  // median over the timed frames
  int probes = 0;
  double faces = 0.0;
  int traced = 0;
  double seconds = 0.0;  // the scene time the rays were counted at
  TracedRayCount rays;
  double msPerMray() const {
    return rays.rays > 0 ? frameMs / (static_cast<double>(rays.rays) * 1e-6) : 0.0;
  }
};

// The rays the exact tracer cast for the frame the demo drew last, on the trees its atlas holds
// (Demo::meshBvh: the level-0 trees; null where it holds none, and then the tracer neither draws
// nor meets that mesh), at that frame's scene time and camera.
TracedRayCount lastFrameRays(const Demo& demo, int width, int height) {
  return countTracedRays(demo.scene(), demo.lastStats().timeSeconds, heldTrees(demo), demo.camera(),
                         width, height,
                         [&demo](int object) { return demo.lastPlan().traces(object); });
}

Result<Cell> runCell(const std::string& modelDirectory, const GrowthOptions& o, int reflectors,
                     size_t triangles, bool share) {
  Demo demo(growthScene(reflectors, share));
  std::string error = demo.loadMesh("sphere.obj", modelDirectory + "/sphere.obj");
  if (error.empty()) error = demo.loadMesh("quad.obj", modelDirectory + "/quad.obj");
  if (error.empty()) error = demo.setMeshData("blob.obj", uvSphere(triangles / 4, "blob"));
  if (error.empty()) error = demo.initGraphics();
  if (!error.empty()) return Result<Cell>::failure(error);
  demo.waitForLevels();
  auto r = benchFrames(demo, o.width, o.height, o.warmup, o.frames);
  if (!r) return Result<Cell>::failure(r.error());
  Cell cell;
  cell.frameMs = median(r.value().frameMs);
  cell.probes = demo.lastStats().probes;
  cell.faces = r.value().facesPerFrame;
  cell.traced = demo.lastStats().tracedReflectors;
  // The frames step the clock by 1/60 s from 0, so the last timed one is at
  // (warmup + frames) / 60 s whatever the machine: the same figures' places in every run.
  cell.seconds = demo.lastStats().timeSeconds;
  cell.rays = lastFrameRays(demo, o.width, o.height);
  return cell;
}

// A ray count as "1.23M" or "45.6k".
std::string countText(int64_t n) {
  char text[32];
  const double v = static_cast<double>(n);
  if (v >= 1e6) {
    std::snprintf(text, sizeof text, "%.2fM", v * 1e-6);
  } else {
    std::snprintf(text, sizeof text, "%.1fk", v * 1e-3);
  }
  return text;
}

std::string cellText(const Cell& c) {
  char text[256];
  std::snprintf(text, sizeof text,
                " %.1f ms (%d probes, %.0f faces, %d traced, %s rays, %.1f ms/Mray) |", c.frameMs,
                c.probes, c.faces, c.traced, countText(c.rays.rays).c_str(), c.msPerMray());
  return text;
}

// The time a frame adds per million rays it adds, from row `from` to row `to`: the frame's time
// per ray without its fixed work (the scene's raster), which a ratio of whole frames keeps in.
double addedMsPerMray(const Cell& from, const Cell& to) {
  const double addedRays = static_cast<double>(to.rays.rays - from.rays.rays) * 1e-6;
  return addedRays > 0.0 ? (to.frameMs - from.frameMs) / addedRays : 0.0;
}

// 16 reflectors against 1 at each triangle count: the frame, the rays and the time per ray; and
// the time added per ray added from 1 to 4 and from 4 to 16 reflectors (equal where a ray costs
// the same however many mirrors there are).
std::string ratioLine(const std::string& table, const std::vector<std::vector<Cell>>& rows) {
  std::string line = table + ", 16 vs 1 reflectors:";
  const char* names[] = {"10k", "100k", "1M"};
  for (size_t t = 0; t < rows.front().size(); ++t) {
    const Cell& one = rows[0][t];
    const Cell& four = rows[1][t];
    const Cell& sixteen = rows[2][t];
    char part[256];
    std::snprintf(part, sizeof part,
                  "%s %s frame %.1fx, rays %.1fx, ms/Mray %.2fx (added ms per added Mray: 1->4 "
                  "%.0f, 4->16 %.0f)",
                  t == 0 ? "" : ";", names[t], sixteen.frameMs / one.frameMs,
                  static_cast<double>(sixteen.rays.rays) / static_cast<double>(one.rays.rays),
                  sixteen.msPerMray() / one.msPerMray(), addedMsPerMray(one, four),
                  addedMsPerMray(four, sixteen));
    line += part;
  }
  return line + "\n";
}

std::string raysNote(double seconds, int64_t unmodelled) {
  char text[1024];
  std::snprintf(
      text, sizeof text,
      "rays: what the exact tracer casts a frame, bounces included (at most %d a "
      "mirror pixel: its reflection and kMaxBounces = %d followed), counted on the CPU "
      "for the last timed frame (scene time %.4f s); ms/Mray: the frame's median time "
      "per million of them. Per visible pixel: mirror fragments a nearer one covers later "
      "(no depth pre-pass) are shaded too and not counted. No glass here; pixels not "
      "followed: %lld.\n",
      kMaxTracedRays, kMaxBounces, seconds, static_cast<long long>(unmodelled));
  return text;
}

}  // namespace

Result<std::string> runGrowthBench(const std::string& modelDirectory, const GrowthOptions& o) {
  const int reflectorCounts[] = {1, 4, 16};
  const size_t triangleCounts[] = {10'000, 100'000, 1'000'000};
  std::string out, ratios;
  double seconds = 0.0;
  int64_t unmodelled = 0;
  for (bool share : {false, true}) {
    const std::string table =
        share ? "neighbours share a probe (2x2 groups)" : "a probe per reflector";
    out += "\n" + table + ":\n";
    out += "| reflectors \\ scene triangles | 10k | 100k | 1M |\n|---|---|---|---|\n";
    std::vector<std::vector<Cell>> rows;
    for (int reflectors : reflectorCounts) {
      out += "| " + std::to_string(reflectors) + " |";
      rows.emplace_back();
      for (size_t triangles : triangleCounts) {
        Result<Cell> cell = runCell(modelDirectory, o, reflectors, triangles, share);
        if (!cell) return Result<std::string>::failure(cell.error());
        out += cellText(cell.value());
        seconds = cell.value().seconds;
        unmodelled += cell.value().rays.unmodelled;
        rows.back().push_back(cell.take());
        std::fprintf(stderr, ".");
      }
      out += "\n";
    }
    ratios += ratioLine(table, rows);
  }
  std::fprintf(stderr, "\n");
  return raysNote(seconds, unmodelled) + out + "\n" + ratios;
}

}  // namespace reflect
