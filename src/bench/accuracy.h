// How far the raster frame (cube-map reflection) is from the ray-traced reference: the numbers a
// settings sweep reports per setting.
#pragma once

#include <cstdint>
#include <vector>

#include "app/demo.h"
#include "core/error_metrics.h"
#include "core/image.h"
#include "core/result.h"
#include "reference/reference_renderer.h"

namespace reflect {

struct AccuracyReport {
  double timeSeconds = 0.0;
  int width = 0;
  int height = 0;
  // Over the reference's reflector pixels: raster vs reference.
  ImageErrorMetrics reflector;
  // Mean angle between the raster's lookup direction R and the true direction from the probe
  // centre to what the reflected ray hits, over the reflector pixels (degrees).
  double meanAngularErrorDeg = 0.0;
  // Over every other pixel (where both should agree to rounding).
  ImageErrorMetrics offReflector;
  // The same without silhouette pixels (3x3 neighbourhood spans two objects or an object and
  // the background in the reference's ID buffer): rasterisation and ray casting may resolve
  // a pixel on an edge differently.
  ImageErrorMetrics offReflectorInterior;
  // The reference's reflector pixels (its mask decides which pixels count as reflector), and
  // all the others.
  size_t reflectorPixels = 0;
  size_t offReflectorPixels = 0;
  // Per reflector object (by scene index, ascending): its own pixels of the reflector mask.
  std::vector<std::pair<int, ImageErrorMetrics>> perReflector;
  double rasterMs = 0.0;     // renderFrameAt, including read-back
  double referenceMs = 0.0;  // renderReference
  RgbaImage referenceImage;  // measureAccuracy: the reference frame itself
};

// 1 where the 3x3 neighbourhood of a pixel (clipped at the image border) holds more than one
// object ID (-1, the background, counts as an ID).
std::vector<uint8_t> silhouetteMask(const std::vector<int>& objectIds, int width, int height);

// Compares a raster frame with the reference of the same view (sizes must match).
Result<AccuracyReport> compareWithReference(const RgbaImage& raster,
                                            const ReferenceFrame& reference);

// Over the pixels where the reference's primary ray meets object `object`, less silhouette
// pixels (silhouetteMask): how far the raster is from the reference on that object's own surface
// (a probe-lit figure's diffuse light, docs/rough.md).
Result<ImageErrorMetrics> objectInteriorError(const RgbaImage& raster,
                                              const ReferenceFrame& reference, int object);

// Renders the demo's frame at scene time `t` (renderFrameAt: capture with the demo's current
// planner settings and face size, then the main pass) and the reference of the same moment and
// camera (full-detail meshes), and compares them. Needs a current GL context.
// `cached`: the reference of the same scene, camera, moment, size and capture point, when the
// caller already has it (referenceFor), so several settings compare with one trace.
Result<AccuracyReport> measureAccuracy(Demo& demo, double t, int width, int height,
                                       const ReferenceFrame* cached = nullptr);

// The reference frame measureAccuracy compares `demo` with at scene time `t` (`options`: the
// seed and lobe samples of rough mirrors' Monte Carlo).
Result<ReferenceFrame> referenceFor(const Demo& demo, double t, int width, int height,
                                    const ReferenceOptions& options = {});

}  // namespace reflect
