// Frames rendered off screen and read back: what `reflect render` writes, what the GL tests
// compare with golden PNGs, and what `reflect bench` times.
#pragma once

#include <functional>
#include <vector>

#include "app/demo.h"
#include "core/image.h"
#include "core/result.h"

namespace reflect {

// Renders the frame at scene time `seconds` (capture included) and returns its pixels.
Result<RgbaImage> renderFrameAt(Demo& demo, double seconds, int width, int height);

struct BenchResult {
  std::vector<double> frameMs;
  std::vector<double> captureMs;
  // CPU time of the whole process (llvmpipe's threads included) per frame: what a frame costs,
  // much less inflated than wall time when other work shares the machine.
  std::vector<double> cpuMs;
  size_t trianglesPerFrame = 0;  // of the last frame
  int drawCallsPerFrame = 0;     // of the last frame
  double facesPerFrame = 0;      // mean over the timed frames
};
// Renders warmup + frames frames at 60 Hz scene time steps, waiting for the GPU after each.
Result<BenchResult> benchFrames(Demo& demo, int width, int height, int warmup, int frames);

// Several demos timed in one context, taking turns a block of frames at a time: each block's
// first frame is drawn untimed, then `perBlock` frames are timed, until each demo has `frames`.
// (Frame by frame in turn, a cheap setting drawn between expensive ones measured up to three times
// its own time in llvmpipe: the traced default 17 ms between the course's and the hierarchical
// search's frames against 5.7 ms alone; in blocks, 6.0 ms.) `dt(demo)` is each frame's time step.
// Returns, per demo, the timed frames' wall ms and process CPU ms.
struct TimedFrames {
  std::vector<double> ms, cpuMs;
  std::vector<double> captureMs, filterMs;  // the capture's share of ms, and the filter's of it
  std::vector<double> irradianceMs;         // the irradiance projection's share of captureMs
};
std::vector<TimedFrames> timeInBlocks(const std::vector<Demo*>& demos, unsigned framebuffer,
                                      int width, int height, int frames,
                                      const std::function<double(size_t)>& dt, int perBlock = 5);

double median(std::vector<double> values);
// CPU time this process has used so far, in milliseconds.
double processCpuMs();
double percentile(std::vector<double> values, double p);

}  // namespace reflect
