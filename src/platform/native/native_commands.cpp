#include "platform/native/native_commands.h"

#include <cstdio>
#include <memory>
#include <set>
#include <vector>

#include "app/demo.h"
#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "bench/bench_commands.h"
#include "core/image.h"
#include "platform/native/model_paths.h"

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

// The demo the command line describes, its GL resources made in the current context.
Result<std::unique_ptr<Demo>> makeDemo(const CliOptions& o, const DemoVariant& variant,
                                       WarningPrinter& warnings) {
  using Out = Result<std::unique_ptr<Demo>>;
  Result<Scene> loaded = loadNamedScene(o.scene);
  if (!loaded) return Out::failure(loaded.error());
  Scene scene = loaded.take();
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
  demo->camera().setAngles(o.yawDeg, o.pitchDeg);
  std::vector<std::string> loadWarnings;
  std::string error = loadSceneModels(*demo, o.assets, &loadWarnings);
  warnings.print(loadWarnings);
  if (error.empty()) error = demo->initGraphics();
  if (!error.empty()) return Out::failure(error);
  // Renders and benchmarks start with every chunk and level built, so what they print does not
  // depend on when a background build happened to finish.
  demo->waitForLevels();
  return Out(std::move(demo));
}

}  // namespace

std::string runRenderCommand(const CliOptions& o) {
  WarningPrinter warnings;
  auto demo = makeDemo(o, {}, warnings);
  if (!demo) return demo.error();
  auto image = renderFrameAt(*demo.value(), o.time, o.width, o.height);
  if (!image) return image.error();
  std::string error = writePng(image.value(), o.out);
  if (!error.empty()) return error;
  std::printf("wrote %s (%dx%d, t=%.3f s)\n", o.out.c_str(), o.width, o.height, o.time);
  if (o.referenceOut.empty()) return {};
  auto report = measureAccuracy(*demo.value(), o.time, o.width, o.height);
  if (!report) return report.error();
  error = writePng(report.value().referenceImage, o.referenceOut);
  if (!error.empty()) return error;
  std::printf(
      "wrote %s; reflector: PSNR %.2f dB, RMSE %.2f, p95 %d, max %d, mean angular error "
      "%.3f deg\n",
      o.referenceOut.c_str(), report.value().reflector.psnrDb, report.value().reflector.rmse,
      report.value().reflector.p95PixelError, report.value().reflector.maxPixelError,
      report.value().meanAngularErrorDeg);
  return {};
}

std::string runBenchCommand(const CliOptions& o) {
  WarningPrinter warnings;
  const BenchDemoFactory factory = [&](const DemoVariant& variant) {
    return makeDemo(o, variant, warnings);
  };
  const BenchCommandOptions options = o.benchOptions();
  switch (o.benchMode()) {
    case BenchMode::Sweep:
      return runSweepCommand(options, factory);
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
