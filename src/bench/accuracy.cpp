#include "bench/accuracy.h"

#include <chrono>
#include <cmath>
#include <set>

#include "app/headless_frames.h"
#include "core/probe_layout.h"
#include "gfx/offscreen_target.h"

namespace reflect {

std::vector<uint8_t> silhouetteMask(const std::vector<int>& objectIds, int width, int height) {
  std::vector<uint8_t> mask(objectIds.size(), 0);
  if (width < 1 || height < 1 ||
      objectIds.size() != static_cast<size_t>(width) * static_cast<size_t>(height)) {
    return mask;
  }
  const auto id = [&](int x, int y) {
    return objectIds[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int centre = id(x, y);
      bool edge = false;
      for (int dy = -1; dy <= 1 && !edge; ++dy) {
        for (int dx = -1; dx <= 1 && !edge; ++dx) {
          const int nx = x + dx;
          const int ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          edge = id(nx, ny) != centre;
        }
      }
      mask[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] = edge;
    }
  }
  return mask;
}

Result<AccuracyReport> compareWithReference(const RgbaImage& raster,
                                            const ReferenceFrame& reference) {
  const RgbaImage& exact = reference.image;
  if (raster.width != exact.width || raster.height != exact.height) {
    return Result<AccuracyReport>::failure("raster and reference sizes differ");
  }
  AccuracyReport report;
  report.width = exact.width;
  report.height = exact.height;
  report.referenceMs = reference.renderMs;

  const std::vector<uint8_t> edges = silhouetteMask(reference.objectIds, exact.width, exact.height);
  std::vector<uint8_t> off(reference.reflectorMask.size());
  std::vector<uint8_t> interior(reference.reflectorMask.size());
  for (size_t i = 0; i < off.size(); ++i) {
    off[i] = reference.reflectorMask[i] ? 0 : 1;
    interior[i] = off[i] && !edges[i];
  }
  auto reflector = imageErrorMetrics(raster, exact, reference.reflectorMask);
  if (!reflector) return Result<AccuracyReport>::failure(reflector.error());
  auto offMetrics = imageErrorMetrics(raster, exact, off);
  if (!offMetrics) return Result<AccuracyReport>::failure(offMetrics.error());
  auto interiorMetrics = imageErrorMetrics(raster, exact, interior);
  if (!interiorMetrics) return Result<AccuracyReport>::failure(interiorMetrics.error());
  auto angle = meanAngularErrorDegrees(reference.lookupDirs, reference.trueDirs);
  if (!angle) return Result<AccuracyReport>::failure(angle.error());

  report.reflector = reflector.value();
  report.offReflector = offMetrics.value();
  report.offReflectorInterior = interiorMetrics.value();
  report.meanAngularErrorDeg = angle.value();
  report.reflectorPixels = report.reflector.pixelCount;
  report.offReflectorPixels = report.offReflector.pixelCount;
  std::set<int> reflectors;
  for (size_t i = 0; i < off.size(); ++i) {
    if (reference.reflectorMask[i]) reflectors.insert(reference.objectIds[i]);
  }
  for (int object : reflectors) {
    std::vector<uint8_t> own(off.size());
    for (size_t i = 0; i < own.size(); ++i) {
      own[i] = reference.reflectorMask[i] && reference.objectIds[i] == object;
    }
    auto metrics = imageErrorMetrics(raster, exact, own);
    if (!metrics) return Result<AccuracyReport>::failure(metrics.error());
    report.perReflector.emplace_back(object, metrics.value());
  }
  return report;
}

Result<ImageErrorMetrics> objectInteriorError(const RgbaImage& raster,
                                              const ReferenceFrame& reference, int object) {
  const RgbaImage& exact = reference.image;
  const std::vector<uint8_t> edges = silhouetteMask(reference.objectIds, exact.width, exact.height);
  std::vector<uint8_t> own(reference.objectIds.size());
  for (size_t i = 0; i < own.size(); ++i) own[i] = reference.objectIds[i] == object && !edges[i];
  return imageErrorMetrics(raster, exact, own);
}

Result<ReferenceFrame> referenceFor(const Demo& demo, double t, int width, int height,
                                    const ReferenceOptions& options) {
  const MeshLookup meshes = [&demo](const std::string& name) { return demo.meshLevel(name, 0); };
  // The true directions are measured from where the probe really captured.
  const Scene scene = sceneAsCaptured(demo.scene(), demo.accuracySettings().captureAtOrigin);
  return renderReference(scene, meshes, demo.skyboxFaces(), demo.camera(), t, width, height,
                         options);
}

Result<AccuracyReport> measureAccuracy(Demo& demo, double t, int width, int height,
                                       const ReferenceFrame* cached) {
  const auto start = std::chrono::steady_clock::now();
  Result<RgbaImage> raster = renderFrameAt(demo, t, width, height);
  if (!raster) return Result<AccuracyReport>::failure(raster.error());
  const double rasterMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const Scene& scene = demo.scene();
  Result<ReferenceFrame> reference =
      cached ? Result<ReferenceFrame>(*cached) : referenceFor(demo, t, width, height);
  if (!reference) return Result<AccuracyReport>::failure(reference.error());
  // What the raster really looked up (plain or distance-corrected), per pixel, from the GPU.
  Result<OffscreenTarget> directions = OffscreenTarget::create(width, height, true);
  if (!directions) return Result<AccuracyReport>::failure(directions.error());
  demo.renderLookupDirections(directions.value().framebuffer(), width, height);
  const std::vector<glm::vec3> looked = directions.value().readFloats();
  ReferenceFrame& ref = reference.value();
  size_t k = 0;
  for (size_t p = 0; p < ref.reflectorMask.size(); ++p) {
    if (!ref.reflectorMask[p]) continue;
    const glm::vec3 d = looked[p];
    // Only unit vectors are directions: a pixel the raster's mirror does not cover (silhouette;
    // a colour or the background there) keeps the analytic R. Mirrors write the direction they
    // looked up along, glass the one its refracted ray did (the reference's direction for glass
    // is the refracted one too); a cube-textured object writes its colour.
    const int object = ref.objectIds[p];
    const Material m = scene.objects[static_cast<size_t>(object)].material;
    const bool looks = m == Material::Mirror || m == Material::Glass;
    if (looks && k < ref.lookupDirs.size() && std::abs(glm::length(d) - 1.0f) < 1e-3f) {
      ref.lookupDirs[k] = d;
    }
    ++k;
  }
  Result<AccuracyReport> report = compareWithReference(raster.value(), ref);
  if (!report) return report;
  report.value().timeSeconds = t;
  report.value().referenceImage = std::move(ref.image);
  report.value().rasterMs = rasterMs;
  return report;
}

}  // namespace reflect
