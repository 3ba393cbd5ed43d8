// `reflect bench --lod-sweep` and `--view-lod-sweep`: the measurements behind the default levels of
// detail. Every LOD decision is measured as a difference (the same frame at full detail, under the
// same lookup), which stays valid when the mirror's lookup changes.
//
// Capture LOD: for each captureLod value (triangles per pixel of an object's disc in a cube face;
// 0 = full detail), the reflector's error against the ray-traced reference at several times
// (PSNR, and the share of reflector pixels off by more than 32 levels), and, timed with the
// values interleaved frame by frame on the animated scene, capture triangles and frame time. A
// value passes where, at every time, its PSNR is within 0.1 dB of full detail's and its share of
// pixels off by more than 32 levels at most 1 point above full detail's.
//
// View LOD: for each viewLod value, the main view against the same view at full detail, with the
// camera aimed at the scene's heaviest figure from several distances, at several times: PSNR over
// the whole frame and the pixels off by more than 32 levels. A value passes where every frame is
// at least 45 dB from full detail's with no pixel off by more than 32 levels.
#pragma once

#include <string>
#include <vector>

#include "bench/bench_commands.h"

namespace reflect {

struct LodSweepOptions {
  int width = 800;
  int height = 800;
  std::vector<double> times = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  // 0 (full detail) first: the rows are measured against it.
  std::vector<float> captureLods = {0.0f, 16.0f, 8.0f,  4.0f,   2.0f,
                                    1.0f, 0.5f,  0.25f, 0.125f, 0.0625f};
  int frames = 60;  // timed frames a value, interleaved
  int warmup = 10;
  std::vector<double> viewTimes = {0.0, 3.0};
  std::vector<float> viewDistances = {3.0f, 5.0f, 7.0f, 10.0f, 15.0f, 25.0f};
  std::vector<float> viewLods = {0.0f, 8.0f, 4.0f, 2.0f, 1.0f, 0.5f, 0.25f};
};

// Each prints its table and its choice to stdout; "" or the error.
std::string runCaptureLodSweep(const BenchCommandOptions& options, const BenchDemoFactory& makeDemo,
                               const LodSweepOptions& sweep = {});
std::string runViewLodSweep(const BenchCommandOptions& options, const BenchDemoFactory& makeDemo,
                            const LodSweepOptions& sweep = {});

// The share of `mask`ed pixels whose largest RGB difference between `a` and `b` is over `levels`
// (all pixels when `mask` is empty), and how many there are.
struct PixelsOver {
  size_t count = 0;
  size_t compared = 0;
  double fraction() const { return compared ? static_cast<double>(count) / compared : 0.0; }
};
PixelsOver pixelsOver(const RgbaImage& a, const RgbaImage& b, const std::vector<uint8_t>& mask,
                      int levels);

}  // namespace reflect
