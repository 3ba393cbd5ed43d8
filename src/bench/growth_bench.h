// `reflect bench --growth`: how frame time grows with the number of reflectors (1, 4, 16) and the
// scene's triangles (10k, 100k, 1M), with a probe per reflector or neighbours sharing one.
// The scenes are generated: a ground, four orbiting tessellated blobs, a grid of mirror spheres.
// Beside each time, the rays the exact tracer cast for the last timed frame (core/traced_rays.h)
// and the time per million of them, so that a frame that grows because its rays grow can be told
// from one whose rays each cost more.
#pragma once

#include <string>

#include "core/result.h"

namespace reflect {

struct GrowthOptions {
  int width = 800;
  int height = 800;
  int warmup = 2;
  int frames = 6;
};

// Runs every configuration and returns the printed tables (Markdown).
Result<std::string> runGrowthBench(const std::string& modelDirectory, const GrowthOptions& options);

}  // namespace reflect
