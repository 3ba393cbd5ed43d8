#include "bench/lod_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "core/error_metrics.h"
#include "core/probe_layout.h"
#include "gfx/offscreen_target.h"
#include "reference/reference_renderer.h"

namespace reflect {
namespace {

std::string number(double value, const char* format = "%.2f") {
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string lodLabel(float value) {
  return value == 0.0f ? std::string("0 (full detail)") : number(value, "%g");
}

std::string modelsLabel(const BenchCommandOptions& o) {
  return o.assets.empty() ? std::string("built-in models")
                          : "models from " + o.assets + " (the built-in ones where it has none)";
}

struct CaptureCell {
  double psnrDb = 0.0;
  double over32 = 0.0;  // share of reflector pixels off by more than 32 levels
};

}  // namespace

PixelsOver pixelsOver(const RgbaImage& a, const RgbaImage& b, const std::vector<uint8_t>& mask,
                      int levels) {
  PixelsOver out;
  const size_t pixels = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  if (a.width != b.width || a.height != b.height || a.pixels.size() < pixels * 4 ||
      b.pixels.size() < pixels * 4) {
    return out;
  }
  for (size_t p = 0; p < pixels; ++p) {
    if (!mask.empty() && !mask[p]) continue;
    ++out.compared;
    int largest = 0;
    for (size_t c = 0; c < 3; ++c) {
      largest = std::max(largest, std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c])));
    }
    if (largest > levels) ++out.count;
  }
  return out;
}

std::string runCaptureLodSweep(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo,
                               const LodSweepOptions& sweep) {
  const int width = o.width, height = o.height;
  const int frames = o.frames.value_or(sweep.frames);
  const int warmup = o.warmup.value_or(sweep.warmup);
  const std::vector<float>& values = sweep.captureLods;
  const std::vector<double>& times = sweep.times;
  std::printf(
      "capture LOD sweep: scene %s with %s, %dx%d, cube %d; the reflector against the ray-traced "
      "reference at t =",
      o.scene.c_str(), modelsLabel(o).c_str(), width, height, o.cubeSize);
  for (double t : times) std::printf(" %g", t);
  std::printf(
      " s; timing: policy %s, %d frames after %d warm-up at 60 Hz from t = 0, every value's demo "
      "in turn each frame\n\n",
      policyName(o.planner.policy), frames, warmup);
  std::fflush(stdout);

  // Accuracy: one demo, each value in turn, each time against the same reference.
  auto made = makeDemo({});
  if (!made) return made.error();
  Demo& demo = *made.value();
  const Scene captured = sceneAsCaptured(demo.scene(), demo.accuracySettings().captureAtOrigin);
  const MeshLookup meshes = [&demo](const std::string& name) { return demo.meshLevel(name, 0); };
  std::vector<ReferenceFrame> references;
  for (double t : times) {
    Result<ReferenceFrame> reference =
        renderReference(captured, meshes, demo.skyboxFaces(), demo.camera(), t, width, height);
    if (!reference) return reference.error();
    references.push_back(reference.take());
  }
  std::vector<std::vector<CaptureCell>> cells(values.size());
  for (size_t v = 0; v < values.size(); ++v) {
    PlannerSettings settings = o.planner;
    settings.captureLod = values[v];
    demo.setPlannerSettings(settings);
    demo.waitForLevels();
    for (size_t k = 0; k < times.size(); ++k) {
      Result<RgbaImage> raster = renderFrameAt(demo, times[k], width, height);
      if (!raster) return raster.error();
      Result<AccuracyReport> report = compareWithReference(raster.value(), references[k]);
      if (!report) return report.error();
      const PixelsOver over =
          pixelsOver(raster.value(), references[k].image, references[k].reflectorMask, 32);
      cells[v].push_back(CaptureCell{report.value().reflector.psnrDb, over.fraction()});
    }
    std::fprintf(stderr, ".");
  }
  made.value().reset();  // the timing's demos need the memory more

  // Timing: a demo a value, all advancing together.
  std::vector<std::unique_ptr<Demo>> demos;
  for (float value : values) {
    auto timed = makeDemo({});
    if (!timed) return timed.error();
    PlannerSettings settings = o.planner;
    settings.captureLod = value;
    timed.value()->setPlannerSettings(settings);
    timed.value()->waitForLevels();
    demos.push_back(timed.take());
  }
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height);
  if (!target) return target.error();
  std::vector<std::vector<double>> ms(values.size());
  std::vector<double> captureTriangles(values.size(), 0.0), triangles(values.size(), 0.0);
  for (int frame = 0; frame < warmup + frames; ++frame) {
    for (size_t v = 0; v < values.size(); ++v) {
      const FrameStats& s = demos[v]->frame(frame == 0 ? 0.0 : 1.0 / 60.0,
                                            target.value().framebuffer(), width, height, true);
      if (frame < warmup) continue;
      ms[v].push_back(s.frameMs);
      captureTriangles[v] += static_cast<double>(s.captureTriangles) / frames;
      triangles[v] += static_cast<double>(s.triangles()) / frames;
    }
  }
  demos.clear();
  std::fprintf(stderr, "\n");

  // The table: each value against full detail (values[0]) at the same time.
  std::printf(
      "| captureLod | reflector PSNR dB (mean) | worst dPSNR vs full detail (dB) | reflector "
      "pixels >32 levels (mean) | worst d(>32) vs full detail (points) | capture tris/frame | all "
      "tris/frame | frame ms median (p10-p90) | within 0.1 dB and +1 point at every time |\n"
      "|---|---|---|---|---|---|---|---|---|\n");
  std::vector<bool> passes(values.size(), true);
  for (size_t v = 0; v < values.size(); ++v) {
    double psnr = 0.0, over = 0.0, worstDb = 1e9, worstOver = -1e9;
    for (size_t k = 0; k < times.size(); ++k) {
      psnr += cells[v][k].psnrDb / static_cast<double>(times.size());
      over += cells[v][k].over32 / static_cast<double>(times.size());
      worstDb = std::min(worstDb, cells[v][k].psnrDb - cells[0][k].psnrDb);
      worstOver = std::max(worstOver, cells[v][k].over32 - cells[0][k].over32);
    }
    passes[v] = worstDb >= -0.1 && worstOver <= 0.01;
    std::printf("| %s | %.2f | %+.3f | %.3f%% | %+.3f | %.0f | %.0f | %.2f (%.2f-%.2f) | %s |\n",
                lodLabel(values[v]).c_str(), psnr, worstDb, 100.0 * over, 100.0 * worstOver,
                captureTriangles[v], triangles[v], median(ms[v]), percentile(ms[v], 0.1),
                percentile(ms[v], 0.9), v == 0 ? "(the yardstick)" : (passes[v] ? "yes" : "no"));
  }
  std::printf("\nper time (reflector PSNR dB; pixels >32 levels):\n| captureLod |");
  for (double t : times) std::printf(" t = %g s |", t);
  std::printf("\n|---|");
  for (size_t k = 0; k < times.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (size_t v = 0; v < values.size(); ++v) {
    std::printf("| %s |", lodLabel(values[v]).c_str());
    for (const CaptureCell& c : cells[v]) std::printf(" %.2f; %.3f%% |", c.psnrDb, 100 * c.over32);
    std::printf("\n");
  }
  // The coarsest value that passes with every finer value passing too.
  std::vector<size_t> order;
  for (size_t v = 1; v < values.size(); ++v) order.push_back(v);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] > values[b]; });
  float chosen = 0.0f;
  for (size_t v : order) {
    if (!passes[v]) break;
    chosen = values[v];
  }
  if (chosen > 0.0f) {
    std::printf(
        "\ncoarsest captureLod within 0.1 dB and +1 point of full detail at every time (and every "
        "finer value too): %g\n",
        chosen);
  } else {
    std::printf(
        "\nno captureLod value is within 0.1 dB and +1 point of full detail at every time\n");
  }
  return {};
}

std::string runViewLodSweep(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo,
                            const LodSweepOptions& sweep) {
  const int width = o.width, height = o.height;
  auto made = makeDemo({});
  if (!made) return made.error();
  Demo& demo = *made.value();
  // The heaviest figure: the object whose mesh has the most triangles.
  int figure = -1;
  size_t most = 0;
  for (size_t i = 0; i < demo.scene().objects.size(); ++i) {
    const std::vector<size_t> levels = demo.levelTriangles(demo.scene().objects[i].mesh);
    if (!levels.empty() && levels[0] > most) {
      most = levels[0];
      figure = static_cast<int>(i);
    }
  }
  if (figure < 0) return "view LOD sweep: the scene has no mesh";
  const SceneObject& object = demo.scene().objects[static_cast<size_t>(figure)];
  const MeshData* mesh = demo.meshLevel(object.mesh, 0);
  const glm::vec3 home = demo.camera().eye();
  std::printf(
      "view LOD sweep: scene %s with %s, %dx%d, cube %d; the camera aimed at %s (%zu triangles) "
      "from each distance (its bounds' centre, along the line to the scene's eye), at t =",
      o.scene.c_str(), modelsLabel(o).c_str(), width, height, o.cubeSize, object.mesh.c_str(),
      most);
  for (double t : sweep.viewTimes) std::printf(" %g", t);
  std::printf(
      " s; each frame against the same frame with viewLod 0 (capture settings as given): PSNR "
      "over the whole frame; pixels off by more than 32 levels; main-pass triangles\n\n");
  std::fflush(stdout);

  struct Cell {
    double psnrDb = 0.0;
    size_t over32 = 0;
    size_t mainTriangles = 0;
  };
  const std::vector<float>& values = sweep.viewLods;
  const size_t views = sweep.viewTimes.size() * sweep.viewDistances.size();
  std::vector<std::vector<Cell>> cells(values.size(), std::vector<Cell>(views));
  const std::vector<uint8_t> everyPixel(static_cast<size_t>(width) * static_cast<size_t>(height),
                                        1);
  size_t view = 0;
  for (double t : sweep.viewTimes) {
    const glm::vec3 centre(demo.scene().modelMatrix(object, t) *
                           glm::vec4(mesh->bounds.centre(), 1.0f));
    for (float distance : sweep.viewDistances) {
      const glm::vec3 away = glm::normalize(home - centre);
      const glm::vec3 eye = centre + away * distance;
      const glm::vec3 look = -away;
      demo.camera().setEye(eye);
      demo.camera().setAngles(glm::degrees(std::atan2(-look.x, -look.z)),
                              glm::degrees(std::asin(std::clamp(look.y, -1.0f, 1.0f))));
      RgbaImage full;
      for (size_t v = 0; v < values.size(); ++v) {
        PlannerSettings settings = o.planner;
        settings.viewLod = values[v];
        demo.setPlannerSettings(settings);
        demo.waitForLevels();
        Result<RgbaImage> image = renderFrameAt(demo, t, width, height);
        if (!image) return image.error();
        Cell& cell = cells[v][view];
        cell.mainTriangles = demo.lastStats().mainTriangles;
        if (v == 0) {
          full = image.take();
          cell.psnrDb = kPsnrCapDb;
          continue;
        }
        Result<ImageErrorMetrics> metrics = imageErrorMetrics(full, image.value(), everyPixel);
        if (!metrics) return metrics.error();
        cell.psnrDb = metrics.value().psnrDb;
        cell.over32 = pixelsOver(full, image.value(), {}, 32).count;
      }
      ++view;
      std::fprintf(stderr, ".");
    }
  }
  std::fprintf(stderr, "\n");

  std::printf("| viewLod |");
  for (double t : sweep.viewTimes) {
    for (float d : sweep.viewDistances) std::printf(" t %g s, %g away |", t, d);
  }
  std::printf(" >= 45 dB and no pixel >32 everywhere |\n|---|");
  for (size_t k = 0; k < views; ++k) std::printf("---|");
  std::printf("---|\n");
  for (size_t v = 0; v < values.size(); ++v) {
    std::printf("| %s |", lodLabel(values[v]).c_str());
    bool pass = true;
    bool coarser = false;
    for (size_t k = 0; k < views; ++k) {
      const Cell& c = cells[v][k];
      pass = pass && c.psnrDb >= 45.0 && c.over32 == 0;
      coarser = coarser || c.mainTriangles != cells[0][k].mainTriangles;
      if (v == 0) {
        std::printf(" %zu tris |", c.mainTriangles);
      } else {
        std::printf(" %.1f dB, %zu px, %zu tris |", c.psnrDb, c.over32, c.mainTriangles);
      }
    }
    if (v == 0) {
      std::printf(" (the yardstick) |\n");
    } else {
      std::printf(" %s |\n",
                  pass ? (coarser ? "yes" : "yes (never coarser than full detail)") : "no");
    }
  }
  return {};
}

}  // namespace reflect
