#include "platform/native/native_commands.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <set>
#include <vector>

#include "app/demo.h"
#include "app/face_use_view.h"
#include "app/faces_view.h"
#include "app/frame_step_files.h"
#include "app/headless_frames.h"
#include "app/pixel_explain.h"
#include "bench/accuracy.h"
#include "bench/bench_commands.h"
#include "bench/budget_bench.h"
#include "bench/cost_calibration.h"
#include "bench/process_memory.h"
#include "core/image.h"
#include "gfx/offscreen_target.h"
#include "platform/native/cli_materials.h"
#include "platform/native/model_paths.h"
#include "reference/reference_noise.h"

namespace reflect {
namespace {

// Prints each warning once, however many demos a bench makes from the same files.
class WarningPrinter {
 public:
  void print(const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) {
      if (printed_.insert(warning).second) {
        std::fprintf(stderr, "reflect: warning: %s\n", warning.c_str());
      }
    }
  }

 private:
  std::set<std::string> printed_;
};

// The demo the command line describes, its GL resources made in the current context; with
// `waitForLevels`, its chunks and levels built too.
Result<std::unique_ptr<Demo>> makeDemo(const CliOptions& o, const DemoVariant& variant,
                                       WarningPrinter& warnings, bool waitForLevels = true) {
  using Out = Result<std::unique_ptr<Demo>>;
  Result<Scene> loaded = loadNamedScene(o.scene);
  if (!loaded) return Out::failure(loaded.error());
  Scene scene = loaded.take();
  const std::string materialError = applyMaterialOptions(o.materials, scene);
  if (!materialError.empty()) return Out::failure(materialError);
  if (variant.reflectorAsPhong) {
    for (SceneObject& object : scene.objects) object.material = Material::Phong;
  }
  auto demo = std::make_unique<Demo>(scene);
  if (o.cubeSize) {
    const std::string notice = demo->setCubeFaceSize(*o.cubeSize);
    if (!notice.empty()) std::fprintf(stderr, "reflect: %s\n", notice.c_str());
  }
  demo->setPlannerSettings(o.planner);
  const std::string accuracyError =
      demo->setAccuracySettings(variant.defaultAccuracy ? AccuracySettings{} : o.accuracy);
  if (!accuracyError.empty()) return Out::failure(accuracyError);
  if (o.eye) demo->camera().setEye(*o.eye);
  demo->camera().setAngles(o.yawDeg, o.pitchDeg);
  std::vector<std::string> loadWarnings;
  std::string error = loadSceneModels(*demo, o.assets, &loadWarnings);
  if (error.empty()) {
    std::string nearNotice = demo->captureNearNotice();
    if (!nearNotice.empty()) loadWarnings.push_back(std::move(nearNotice));
  }
  warnings.print(loadWarnings);
  if (error.empty()) error = demo->initGraphics();
  if (!error.empty()) return Out::failure(error);
  // Renders and benchmarks start with every chunk and level built, so what they print does not
  // depend on when a background build happened to finish.
  if (waitForLevels) demo->waitForLevels();
  return Out(std::move(demo));
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// How soon the scene is on screen: one demo made as the page makes it (first frame first, its
// chunks and levels built in the background after it where it captures; else when asked, after
// it), and this process's memory then.
std::string printLoad(const CliOptions& o, WarningPrinter& warnings) {
  const auto start = std::chrono::steady_clock::now();
  auto demo = makeDemo(o, {}, warnings, false);
  if (!demo) return demo.error();
  const double loaded = millisecondsSince(start);
  Result<OffscreenTarget> target = OffscreenTarget::create(o.width, o.height);
  if (!target) return target.error();
  demo.value()->frame(0.0, target.value().framebuffer(), o.width, o.height, true);
  const double firstFrame = millisecondsSince(start);
  const bool readyAtFirstFrame = demo.value()->lodReady();
  // Only a frame that captures wants them (Demo::noteLevelUse); the rest are asked for here.
  const bool wanted = demo.value()->levelsWanted();
  demo.value()->waitForLevels();
  const double ready = millisecondsSince(start);
  std::printf(
      "load: models parsed and GL resources made in %.0f ms; first frame (%dx%d) drawn %.0f ms "
      "after the start%s; chunks and levels ready %.0f ms after the start (%s)\n",
      loaded, o.width, o.height, firstFrame, readyAtFirstFrame ? " (levels already ready)" : "",
      ready,
      wanted ? "built in the background after the first frame"
             : "the first frame captured nothing, so none were built until asked for, after it");
  std::printf("memory after load: %s; meshes %.1f MB as drawn (GPU), %.1f MB kept on the CPU\n",
              describe(processMemory()).c_str(), demo.value()->meshGpuBytes() / 1048576.0,
              demo.value()->meshCpuBytes() / 1048576.0);
  return {};
}

// Where the scene has a rough mirror, the reference's own noise (reference/reference_noise.h):
// `first` against a second rendering with the next seed.
std::string printReferenceNoise(const Demo& demo, const CliOptions& o,
                                const ReferenceFrame& first) {
  if (!hasRoughMirror(demo.scene())) return {};
  ReferenceOptions other = first.options;
  other.seed = first.options.seed + 1;
  auto second = referenceFor(demo, o.time, o.width, o.height, other);
  if (!second) return second.error();
  auto noise = referenceNoise(first, second.value());
  if (!noise) return noise.error();
  std::printf(
      "reference noise: %.1f dB PSNR over the reflectors (%d lobe samples a pixel; two seeds' "
      "difference %.2f dB + 3.01 dB; each reference %.0f ms)\n",
      noise.value().psnrDb, noise.value().lobeSamples, noise.value().difference.psnrDb,
      second.value().renderMs);
  return {};
}

// The reference of the frame (--reference), and its error.
std::string writeReference(Demo& demo, const CliOptions& o) {
  ReferenceOptions options;
  if (o.lobeSamples) options.lobeSamples = *o.lobeSamples;
  auto reference = referenceFor(demo, o.time, o.width, o.height, options);
  if (!reference) return reference.error();
  auto report = measureAccuracy(demo, o.time, o.width, o.height, &reference.value());
  if (!report) return report.error();
  std::string error = writePng(report.value().referenceImage, o.referenceOut);
  if (!error.empty()) return error;
  std::printf(
      "wrote %s; reflector: PSNR %.2f dB, RMSE %.2f, p95 %d, max %d, pixels off by more than "
      "%d levels %zu, mean angular error %.3f deg\n",
      o.referenceOut.c_str(), report.value().reflector.psnrDb, report.value().reflector.rmse,
      report.value().reflector.p95PixelError, report.value().reflector.maxPixelError,
      kVisibleErrorLevels, report.value().reflector.visibleErrorPixels,
      report.value().meanAngularErrorDeg);
  return printReferenceNoise(demo, o, reference.value());
}

// The faces view of the frame just drawn (--faces): the same image the page shows.
std::string writeFacesView(Demo& demo, const CliOptions& o) {
  demo.ensureGeneralCaptures();  // the course's own file draws into a cube of its own
  Result<RgbaImage> view =
      composeFacesView(*demo.renderer(), demo.scene(), demo.lastPlan(), demo.insideViews().ages(),
                       o.view.facesChannel, 0, 0, o.view.facesProbe);
  if (!view) return "--faces: " + view.error();
  std::string error = writePng(view.value(), o.facesOut);
  if (!error.empty()) return error;
  std::printf("wrote %s (the faces view, channel %s: %dx%d)\n", o.facesOut.c_str(),
              facesChannelName(o.view.facesChannel), view.value().width, view.value().height);
  return {};
}

// The face-use view of the frame just drawn (`frame`, its picture; --face-use): the same image
// the page shows.
std::string writeFaceUseView(Demo& demo, const CliOptions& o, const RgbaImage& frame) {
  const auto lookups = [&demo](unsigned target, int w, int h) {
    demo.renderLookupDirections(target, w, h);
  };
  Result<RgbaImage> view = composeFaceUseView(
      demo.scene(), demo.lastPlan(), demo.insideViews().ages(), lookups, frame, o.view.facesProbe);
  if (!view) return "--face-use: " + view.error();
  std::string error = writePng(view.value(), o.faceUseOut);
  if (!error.empty()) return error;
  std::printf("wrote %s (the face-use view: %dx%d)\n", o.faceUseOut.c_str(), view.value().width,
              view.value().height);
  return {};
}

}  // namespace

std::string runRenderCommand(const CliOptions& o) {
  WarningPrinter warnings;
  auto demo = makeDemo(o, {}, warnings);
  if (!demo) return demo.error();
  std::vector<std::string> stepLines;  // --steps: the frame is drawn step by step
  auto image = o.stepsDir.empty() ? renderFrameAt(*demo.value(), o.time, o.width, o.height)
                                  : renderFrameInSteps(*demo.value(), o.time, o.width, o.height,
                                                       o.stepsDir, stepLines);
  if (!image) return o.stepsDir.empty() ? image.error() : "--steps: " + image.error();
  std::string error = writePng(image.value(), o.out);
  if (!error.empty()) return error;
  std::printf("wrote %s (%dx%d, t=%.3f s)\n", o.out.c_str(), o.width, o.height, o.time);
  for (const std::string& line : stepLines) std::printf("%s\n", line.c_str());
  if (!stepLines.empty()) {
    std::printf("wrote %zu step images into %s\n", stepLines.size(), o.stepsDir.c_str());
  }
  // The views of this frame first: the reference and the error view draw frames of their own.
  if (!o.facesOut.empty()) {
    error = writeFacesView(*demo.value(), o);
    if (!error.empty()) return error;
  }
  if (!o.faceUseOut.empty()) {
    error = writeFaceUseView(*demo.value(), o, image.value());
    if (!error.empty()) return error;
  }
  if (!o.referenceOut.empty()) {
    error = writeReference(*demo.value(), o);
    if (!error.empty()) return error;
  }
  if (o.errorViewOut.empty()) return {};
  error = demo.value()->setShowError(true);
  if (!error.empty()) return error;
  auto heat = renderFrameAt(*demo.value(), o.time, o.width, o.height);
  if (!heat) return heat.error();
  error = writePng(heat.value(), o.errorViewOut);
  if (!error.empty()) return error;
  const FrameStats& s = demo.value()->lastStats();
  char psnr[32] = "inf (identical)";
  if (s.errorRmse > 0) std::snprintf(psnr, sizeof psnr, "%.2f dB", s.errorPsnrDb);
  std::printf(
      "wrote %s (error view against the exact mode): reflector PSNR %s, %zu of %zu reflector "
      "pixels off by more than 32 levels (max %d); the exact pass and the comparison took %.1f "
      "ms, the frame %.1f ms\n",
      o.errorViewOut.c_str(), psnr, s.errorPixelsOver32, s.errorReflectorPixels, s.errorMax,
      s.errorViewMs, s.frameMs);
  return {};
}

std::string runExplainCommand(const CliOptions& o) {
  if (o.pixel.x >= o.width || o.pixel.y >= o.height) {
    return "--pixel: " + std::to_string(o.pixel.x) + "," + std::to_string(o.pixel.y) +
           " is outside the " + std::to_string(o.width) + "x" + std::to_string(o.height) +
           " frame (x 0.." + std::to_string(o.width - 1) + ", y 0.." +
           std::to_string(o.height - 1) + ")";
  }
  WarningPrinter warnings;
  auto demo = makeDemo(o, {}, warnings);
  if (!demo) return demo.error();
  auto image = renderFrameAt(*demo.value(), o.time, o.width, o.height);
  if (!image) return image.error();
  auto explained = explainPixel(*demo.value(), o.pixel.x, o.pixel.y, o.width, o.height);
  if (!explained) return explained.error();
  for (const std::string& line : explanationLines(explained.value())) {
    std::printf("%s\n", line.c_str());
  }
  return {};
}

std::string runBenchCommand(const CliOptions& o) {
  WarningPrinter warnings;
  const BenchDemoFactory factory = [&](const DemoVariant& variant) {
    return makeDemo(o, variant, warnings);
  };
  const BenchCommandOptions options = o.benchOptions();
  if (o.benchMode() != BenchMode::Growth) {
    std::string error = printLoad(o, warnings);
    if (!error.empty()) return error;
  }
  switch (o.benchMode()) {
    case BenchMode::Sweep:
      return runSweepCommand(options, factory);
    case BenchMode::Budget:
      return runBudgetCommand(options, factory);
    case BenchMode::Costs:
      return runCostCalibration(options, factory);
    case BenchMode::LodSweep:
      return runLodSweepCommand(options, factory);
    case BenchMode::ViewLodSweep:
      return runViewLodSweepCommand(options, factory);
    case BenchMode::Growth:
      return runGrowthCommand(options, builtInModelDirectory());
    case BenchMode::SinglePolicy:
      return runSinglePolicy(options, factory);
    case BenchMode::PolicyComparison:
      break;
  }
  return runPolicyComparison(options, factory);
}

}  // namespace reflect
