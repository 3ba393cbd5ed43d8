#include "app/headless_frames.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "gfx/offscreen_target.h"

namespace reflect {

Result<RgbaImage> renderFrameAt(Demo& demo, double seconds, int width, int height) {
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height);
  if (!target) return Result<RgbaImage>::failure(target.error());
  demo.clock().set(seconds);
  demo.frame(0.0, target.value().framebuffer(), width, height, true);
  return target.value().readPixels();
}

double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

Result<BenchResult> benchFrames(Demo& demo, int width, int height, int warmup, int frames) {
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height);
  if (!target) return Result<BenchResult>::failure(target.error());
  BenchResult result;
  for (int i = 0; i < warmup + frames; ++i) {
    const double cpuBefore = processCpuMs();
    const FrameStats& s = demo.frame(1.0 / 60.0, target.value().framebuffer(), width, height, true);
    if (i < warmup) continue;
    result.cpuMs.push_back(processCpuMs() - cpuBefore);
    result.frameMs.push_back(s.frameMs);
    result.captureMs.push_back(s.captureMs);
    result.trianglesPerFrame = s.triangles();
    result.drawCallsPerFrame = s.drawCalls();
    result.facesPerFrame += s.facesCaptured / static_cast<double>(frames);
  }
  return result;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(rank));
  const size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (values[hi] - values[lo]) * (rank - static_cast<double>(lo));
}

std::vector<TimedFrames> timeInBlocks(const std::vector<Demo*>& demos, unsigned framebuffer,
                                      int width, int height, int frames,
                                      const std::function<double(size_t)>& dt, int perBlock) {
  std::vector<TimedFrames> out(demos.size());
  perBlock = std::max(perBlock, 1);
  for (int done = 0; done < frames; done += perBlock) {
    const int block = std::min(perBlock, frames - done);
    for (size_t i = 0; i < demos.size(); ++i) {
      demos[i]->frame(dt(i), framebuffer, width, height, true);  // settles, untimed
      for (int f = 0; f < block; ++f) {
        const double cpuBefore = processCpuMs();
        const FrameStats& s = demos[i]->frame(dt(i), framebuffer, width, height, true);
        out[i].ms.push_back(s.frameMs);
        out[i].cpuMs.push_back(processCpuMs() - cpuBefore);
        out[i].captureMs.push_back(s.captureMs);
        out[i].filterMs.push_back(s.filterMs);
        out[i].irradianceMs.push_back(s.irradianceMs);
      }
    }
  }
  return out;
}

double median(std::vector<double> values) {
  return percentile(std::move(values), 0.5);
}

}  // namespace reflect
