// `reflect`: the native, headless entry point (EGL surfaceless). Same scene, same shaders as the
// page; writes PNGs and prints timings.
#include <cstdio>
#include <string>
#include <vector>

#include "app/cli_options.h"
#include "app/demo.h"
#include "app/headless_frames.h"
#include "core/image.h"
#include "platform/native/egl_context.h"
#include "platform/native/model_paths.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "reflect: %s\n", message.c_str());
  return 1;
}

int runRender(reflect::Demo& demo, const reflect::CliOptions& o) {
  reflect::Result<reflect::RgbaImage> image = reflect::renderFrameAt(demo, o.time, o.width, o.height);
  if (!image) return fail(image.error());
  std::string error = reflect::writePng(image.value(), o.out);
  if (!error.empty()) return fail(error);
  std::printf("wrote %s (%dx%d, t=%.3f s)\n", o.out.c_str(), o.width, o.height, o.time);
  return 0;
}

int runBench(reflect::Demo& demo, const reflect::CliOptions& o) {
  reflect::Result<reflect::BenchResult> r =
      reflect::benchFrames(demo, o.width, o.height, o.warmup, o.frames);
  if (!r) return fail(r.error());
  const reflect::BenchResult& b = r.value();
  std::printf("frames %d at %dx%d, cube %d, %d draw calls and %zu triangles a frame\n", o.frames,
              o.width, o.height, o.cubeSize, b.drawCallsPerFrame, b.trianglesPerFrame);
  std::printf("frame ms   median %.3f  p10 %.3f  p90 %.3f\n", reflect::median(b.frameMs),
              reflect::percentile(b.frameMs, 0.1), reflect::percentile(b.frameMs, 0.9));
  std::printf("capture ms median %.3f  p10 %.3f  p90 %.3f\n", reflect::median(b.captureMs),
              reflect::percentile(b.captureMs, 0.1), reflect::percentile(b.captureMs, 0.9));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  reflect::Result<reflect::CliOptions> parsed =
      reflect::parseCli(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed) return fail(parsed.error());
  const reflect::CliOptions& o = parsed.value();
  if (o.command == "help") {
    std::fputs(reflect::cliHelp(), stdout);
    return 0;
  }

  reflect::Demo demo(reflect::makeDynamicReflectionScene());
  demo.setCubeFaceSize(o.cubeSize);
  demo.camera().setAngles(o.yawDeg, o.pitchDeg);
  std::string error = reflect::loadSceneModels(demo, o.assets);
  if (!error.empty()) return fail(error);

  auto context = reflect::HeadlessGlContext::create();
  if (!context) return fail(context.error());
  error = demo.initGraphics();
  if (!error.empty()) return fail(error);
  if (o.command == "bench") std::printf("GL: %s\n", context.value()->description().c_str());
  return o.command == "render" ? runRender(demo, o) : runBench(demo, o);
}
