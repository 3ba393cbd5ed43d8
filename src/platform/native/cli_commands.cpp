#include "platform/native/cli_commands.h"
#include <functional>

#include "app/demo.h"
#include "platform/native/cli_settings.h"
#include "platform/native/cli_validators.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// A whole-number option that is not a setting (--cube, --frames): checked as one, then `set`.
CLI::Option* addWholeNumber(CLI::App& app, CliWording& wording, const SettingInfo& info,
                            const std::string& help, std::function<void(int)> set) {
  CLI::Option* option = app.add_option_function<double>(
      info.optionName(), [set](const double& value) { set(static_cast<int>(value)); }, help);
  wording.expected[option->get_name()] = info.expected();
  option->type_name("N");
  checkAsSetting(option, info);
  return option;
}

// --lobe-samples: the reference's lobe rays a rough pixel (ReferenceOptions::lobeSamples).
CLI::Option* addLobeSamples(CLI::App& c, CliOptions& o, CliWording& w, const std::string& when) {
  return addWholeNumber(c, w, wholeNumberInfo("lobeSamples", 1, 4096),
                        "lobe rays the reference traces a rough mirror's pixel " + when +
                            " (1..4096; default 512; its noise falls as 1/sqrt(N))",
                        [&o](int n) { o.lobeSamples = n; });
}

void defineView(CLI::App& c, CliOptions& o, CliWording& w) {
  const SettingInfo cube = wholeNumberInfo("cube", 1, Demo::kMaxCubeFaceSize);
  addWholeNumber(c, w, cube,
                 "cube-map face size, 1.." + std::to_string(Demo::kMaxCubeFaceSize) +
                     " (default: the scene's capture.faceSize, else 256; a probe read only by "
                     "rough mirrors' lobe taps takes the smaller size its lobes need)",
                 [&o](int side) { o.cubeSize = side; });
  valueOption(c.add_option("--yaw", o.yawDeg, "camera yaw in degrees (default 0)"), w, "DEG",
              "a number of degrees")
      ->check(decimalNumber("degrees"));
  valueOption(
      c.add_option("--pitch", o.pitchDeg, "camera pitch in degrees, clamped to +/-89 (default 0)"),
      w, "DEG", "a number of degrees")
      ->check(decimalNumber("degrees"));
  auto eye = [&o](const std::string& text) { o.eye = parseThreeNumbers(text); };
  valueOption(c.add_option_function<std::string>(
                  "--eye", eye, "camera position (default: the scene's camera eye)"),
              w, "X,Y,Z", "three numbers X,Y,Z")
      ->check(threeNumbers());
}

// The options render and bench share: the scene, the view, the capture settings.
void defineScene(CLI::App& c, CliOptions& o, CliWording& w) {
  valueOption(c.add_option("--scene", o.scene,
                           "a shipped scene (" + joined(shippedSceneNames()) +
                               ") or a .json file (default " + o.scene + ")"),
              w, "NAME", "a scene name or a .json file")
      ->check(sceneNameOrFile());
  valueOption(c.add_option("--assets", o.assets,
                           "take the models from DIR by the course's file names (mario.obj "
                           "sonic.obj sphere.obj quad.obj); the built-in ones for those it lacks"),
              w, "DIR", "a folder")
      ->check(existingFolder());
  valueOption(c.add_option("--material", o.materials,
                           "change object INDEX's material settings (repeatable; names as in "
                           "scene files: reflection, base, ior, fresnel, roughness, environment, "
                           "type), e.g. --material 3:roughness=0.5"),
              w, "INDEX:NAME=VALUE,...", "INDEX:NAME=VALUE[,NAME=VALUE...]");
  w.valueFirst.insert({"--scene", "--assets"});
  auto size = [&o](const std::string& text) {
    const glm::ivec2 side = *parseFrameSize(text);
    o.width = side.x;
    o.height = side.y;
    o.sizeSet = true;
  };
  valueOption(
      c.add_option_function<std::string>(
          "--size", size,
          "frame size in pixels, each side 1.." + std::to_string(kMaxFrameSide) + " (default " +
              std::to_string(o.width) + "x" + std::to_string(o.height) + ")"),
      w, "WxH", frameSizeExpected())
      ->check(frameSize());
  defineView(c, o, w);
}

// What render, explain and bench share after their own options: the scene and the settings, and
// a callback that records the command, applies a preset and notes an explicit --policy (then
// `more`, the command's own).
void defineFrameCommand(CLI::App& c, CliOptions& o, CliWording& w, const char* name,
                        std::function<void()> more = {}) {
  defineScene(c, o, w);
  addSettingOptions(c, o, w);
  c.callback([&c, &o, name, more] {
    o.command = name;
    applyPreset(c, o);
    o.policySet = c.count("--policy") > 0;
    if (more) more();
  });
}

// A mode of the bench: a flag of the modes group.
void addMode(CLI::App& modes, const std::string& name, const std::string& help, bool& on) {
  modes.add_flag(name, on, "mode: " + help);
}

void defineModes(CLI::App& bench, CliOptions& o, CliWording& w) {
  CLI::App* modes = bench.add_option_group(
      "modes", "none given: the policy comparison, or with --policy, that policy alone");
  addMode(*modes, "--growth",
          "frame ms for 1/4/16 reflectors x 10k/100k/1M triangles, with a probe each and with "
          "neighbours sharing probes",
          o.growth);
  addMode(*modes, "--lod-sweep",
          "each captureLod value against full detail: the reflector against the ray-traced "
          "reference at t = 0..5 s, capture triangles and frame ms (the values interleaved); "
          "prints the coarsest value within 0.1 dB and +1 point of pixels off by >32 levels",
          o.lodSweep);
  addMode(*modes, "--view-lod-sweep",
          "each viewLod value against the full-detail view, the camera aimed at the heaviest "
          "figure from several distances: PSNR and pixels off by >32 levels",
          o.viewLodSweep);
  addMode(*modes, "--costs",
          "what the planner's cost model is fitted to: frames drawn as Phong, traced, captured "
          "and searched, and searched alone, with the planner's counts, as ms a unit",
          o.costs);
  addMode(*modes, "--sweep",
          "every accuracy setting (capture point, distance-corrected lookup, face size, depth "
          "bits, filtering, RGBA16F, precision): frame ms and error against the ray-traced "
          "reference",
          o.sweep);
  // The page's frame budget, here a mode: time each search, measure its error against the exact
  // mode, print the table and what "auto" picks.
  for (const auto& field : viewFields()) {
    if (field.info.name == "budget") {
      addSetting(*modes, w, field, o.view)->check(positiveBudget());
    }
  }
  modes->require_option(0, 1);
}

// "120 a policy, 6 a growth cell": a count's default in each mode.
std::string perMode(int (*byDefault)(BenchMode), bool withSweep) {
  std::string text = std::to_string(byDefault(BenchMode::PolicyComparison)) + " a policy, " +
                     std::to_string(byDefault(BenchMode::Growth)) + " a growth cell";
  if (withSweep) text += ", " + std::to_string(byDefault(BenchMode::Sweep)) + " a sweep setting";
  return text;
}

void defineCounts(CLI::App& c, CliOptions& o, CliWording& w) {
  addWholeNumber(c, w, wholeNumberInfo("frames", 1, 1000000),
                 "frames to time (1..1000000; default " + perMode(benchFramesDefault, true) + ")",
                 [&o](int n) { o.frames = n; });
  addWholeNumber(c, w, wholeNumberInfo("warmup", 0, 1000000),
                 "frames before timing (0..1000000; default " + perMode(benchWarmupDefault, false) +
                     "; the sweep has none)",
                 [&o](int n) { o.warmup = n; });
  addWholeNumber(c, w, wholeNumberInfo("accuracyFrames", 0, 100000),
                 "frames each policy is compared with every-frame (0..100000; default " +
                     std::to_string(o.accuracyFrames) + ")",
                 [&o](int n) { o.accuracyFrames = n; });
}

void defineSweepOptions(CLI::App& c, CliOptions& o, CliWording& w) {
  auto times = [&o](const std::string& text) { o.times = *parseNumberList(text); };
  valueOption(c.add_option_function<std::string>(
                  "--times", times,
                  "the sweeps: the scene times measured, in seconds (default 0,1,2,3,4,5; the "
                  "view sweep 0,3; the accuracy sweep reports these instead of its held-out "
                  "times and skips its tuning times)"),
              w, "T1,T2,...", "numbers of seconds T1,T2,...")
      ->check(numberList());
  auto only = [&o](const std::string& text) { o.only = splitNames(text); };
  valueOption(c.add_option_function<std::string>(
                  "--only", only,
                  "sweep: measure only these of its settings, by the names of its rows (e.g. "
                  "original,default: the course's and the default, interleaved)"),
              w, "NAME,...", "names of sweep settings")
      ->check(nameList());
  CLI::Option* sweep = c.get_option("--sweep");
  valueOption(
      c.add_option("--csv", o.csv,
                   "with --sweep: write the rows as CSV (name, ms, psnr_db, rmse, p95, ...)"),
      w, "FILE", "a file name")
      ->needs(sweep);
  valueOption(
      c.add_option("--svg", o.svg,
                   "with --sweep: write a plot of error against time with the Pareto front"),
      w, "FILE", "a file name")
      ->needs(sweep);
  addLobeSamples(c, o, w, "in the sweep's references")->needs(sweep);
}

}  // namespace

void defineRender(CLI::App& c, CliOptions& o, CliWording& w) {
  valueOption(c.add_option("--time", o.time,
                           "scene time in seconds (default 0); the figures orbit 27 deg/s"),
              w, "SECONDS", "a number of seconds")
      ->check(decimalNumber("seconds"));
  // The files render writes: the frame, and each view asked for beside it.
  const auto pngFile = [&c, &w](const char* name, std::string& file, const std::string& help) {
    valueOption(c.add_option(name, file, help), w, "FILE", "a PNG file name");
  };
  pngFile("--out", o.out, "the PNG to write (default " + o.out + ")");
  pngFile("--reference", o.referenceOut,
          "also write the exact (ray-traced, Embree) frame and print the reflector's error "
          "against it");
  addLobeSamples(c, o, w, "with --reference")->needs(c.get_option("--reference"));
  pngFile("--error-view", o.errorViewOut,
          "also write the error view of the frame (a heat map of each mirror and glass pixel's "
          "difference from the exact mode) and print the reflector PSNR and the pixels off by "
          "more than 32 levels");
  pngFile("--faces", o.facesOut,
          "also write the faces view: the probe's cube map unfolded as a cross, each face with "
          "the course's look and up vectors, captured or stale");
  pngFile("--face-use", o.faceUseOut,
          "also write the face-use view: each mirror and glass pixel in the colour of the cube "
          "face it read, with a legend of the pixels each face serves");
  valueOption(c.add_option("--steps", o.stepsDir,
                           "also step through the frame: write one PNG per draw step into DIR "
                           "(step-01.png ...: each face's capture passes, then the main pass, "
                           "which is the frame) and print each step's label and triangles"),
              w, "DIR", "a writable folder");
  for (const auto& field : viewFields()) {
    if (field.info.name == "facesChannel" || field.info.name == "facesProbe") {
      addSetting(c, w, field, o.view);
    }
  }
  defineFrameCommand(c, o, w, "render");
}

// Everything render takes for the frame (scene, time, camera, size, settings) and the pixel.
void defineExplain(CLI::App& c, CliOptions& o, CliWording& w) {
  auto pixel = [&o](const std::string& text) { o.pixel = *parsePixelPosition(text); };
  valueOption(
      c.add_option_function<std::string>(
          "--pixel", pixel, "the pixel to explain, X,Y from the frame's top-left corner (0,0)"),
      w, "X,Y", "a pixel X,Y")
      ->required()
      ->check(pixelPosition());
  valueOption(c.add_option("--time", o.time, "scene time in seconds (default 0)"), w, "SECONDS",
              "a number of seconds")
      ->check(decimalNumber("seconds"));
  defineFrameCommand(c, o, w, "explain");
}

void defineBench(CLI::App& c, CliOptions& o, CliWording& w) {
  defineModes(c, o, w);
  defineCounts(c, o, w);
  defineSweepOptions(c, o, w);
  defineFrameCommand(c, o, w, "bench",
                     [&c, &o] { o.budgetSet = c.get_option("--budget")->count() > 0; });
}

void defineHelp(CLI::App& c, CliOptions& o) {
  c.add_option("COMMAND", o.helpTopic, "render, explain or bench: that command's options alone")
      ->type_name("")
      ->check(commandName({"render", "explain", "bench"}));
  c.callback([&o] { o.command = "help"; });
}

}  // namespace reflect
