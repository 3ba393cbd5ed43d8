#include "platform/native/cli_options.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <system_error>

#include "app/demo.h"
#include "core/presets.h"
#include "core/settings_schema.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

using nlohmann::json;
using Kind = SettingInfo::Kind;

constexpr int kMaxFrameSide = 16384;  // the largest renderbuffer llvmpipe and most GPUs allow
constexpr size_t kHelpColumn = 28;    // where option descriptions start
constexpr size_t kHelpWidth = 100;
constexpr const char* kOptions = "options";
constexpr const char* kPlanner = "capture planning (the page's panel: the same settings)";
constexpr const char* kAccuracy = "accuracy (README: Accuracy)";

const char* kCommandsHelp =
    "commands:\n"
    "  render   render one frame to a PNG\n"
    "  bench    time the capture update policies and compare their pictures (its modes below)\n"
    "  help     this text (also --help); one command's: reflect help COMMAND, or\n"
    "           reflect COMMAND --help\n";

// `text` broken into lines of at most `width` characters, at spaces.
std::string wrap(const std::string& text, size_t width = kHelpWidth - kHelpColumn) {
  std::string out;
  size_t lineLength = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (lineLength > 0 && lineLength + 1 + word.size() > width) {
      out += '\n';
      lineLength = 0;
    } else if (lineLength > 0) {
      out += ' ';
      ++lineLength;
    }
    out += word;
    lineLength += word.size();
    start = end + 1;
  }
  return out;
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// `text` as a JSON number (an integer when it reads as one), or null when it is not a finite
// decimal number.
json numberJson(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) ||
      text.find_first_of("xX") != std::string::npos) {
    return nullptr;  // strtod's hexadecimal floats and leading blanks are not numbers here
  }
  char* end = nullptr;
  errno = 0;
  const long long whole = std::strtoll(text.c_str(), &end, 10);
  if (*end == '\0' && errno == 0) return whole;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !std::isfinite(value)) return nullptr;
  return value;
}

// `text` checked as the value of the setting `info` (SettingInfo::check, the page's messages, with
// the option's name): "" and the value in `out`, or "--option: VALUE is not ...".
std::string checkSetting(const SettingInfo& info, const std::string& text, json* out) {
  json value = text;
  if (info.kind == Kind::Flag) value = text == "true";
  if (info.kind == Kind::Integer || info.kind == Kind::Number) {
    value = numberJson(text);
    if (value.is_null()) return info.optionName() + ": " + text + " is not " + info.expected();
  }
  const std::string problem = info.check(value);
  if (!problem.empty()) return info.optionName() + problem.substr(info.name.size());
  *out = std::move(value);
  return {};
}

// A whole-number option that is not a setting of the page (--cube, --frames, ...).
SettingInfo wholeNumber(std::string name, int min, int max) {
  SettingInfo info;
  info.name = std::move(name);
  info.kind = Kind::Integer;
  info.min = min;
  info.max = max;
  return info;
}

// One option of a command: what CLI11 reads into, and how it is applied to the options.
struct Binding {
  std::string name;  // "--cube"
  bool isFlag = false;
  std::string expected;  // what a value must be, for "missing value" (value options)
  std::string value;     // read by CLI11 (value options)
  bool flag = false;     // read by CLI11 (flags)
  CLI::Option* option = nullptr;
  // Applies the value ("true"/"false" for a flag) to the options: "" or the message.
  std::function<std::string(const std::string&)> apply;
};

// One command's options, defined once: CLI11 parses them and writes the help from them.
class Command {
 public:
  Command(const std::string& name, const std::string& description)
      : name_(name), app_(wrap(description, kHelpWidth) + "\n", "reflect " + name) {
    app_.get_formatter()->column_width(kHelpColumn);
    app_.set_help_flag("-h,--help", "show this help")->group(kOptions);
    app_.allow_extras();  // reported as "COMMAND: unknown option --x" below
  }

  void value(const std::string& name, const std::string& valueName, const std::string& help,
             const std::string& expected, const std::string& group,
             std::function<std::string(const std::string&)> apply) {
    Binding& b = bindings_.emplace_back();
    b.name = name;
    b.expected = expected;
    b.apply = std::move(apply);
    b.option = app_.add_option(name, b.value, wrap(help))
                   ->type_name(valueName)
                   ->group(group)
                   ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  }

  void flag(const std::string& name, const std::string& help, const std::string& group,
            std::function<std::string(const std::string&)> apply) {
    Binding& b = bindings_.emplace_back();
    b.name = name;
    b.isFlag = true;
    b.apply = std::move(apply);
    b.option = app_.add_flag(name, b.flag, wrap(help))->group(group);
  }

  // A setting of the page's table: its name, help, range and default, checked as the page does.
  template <class S>
  void setting(const SettingField<S>& field, S& settings, const std::string& group) {
    const SettingInfo& info = field.info;
    const json byDefault = field.get(S{});
    std::string shownDefault =
        byDefault.is_string() ? byDefault.get<std::string>() : byDefault.dump();
    if (info.kind == Kind::Flag) shownDefault = byDefault.get<bool>() ? "on" : "off";
    if (byDefault.is_number_float()) shownDefault = formatNumber(byDefault.get<double>());
    auto apply = [&info, &settings, &field](const std::string& text) {
      json value;
      std::string problem = checkSetting(info, text, &value);
      if (problem.empty()) {
        problem = applySettingsJson(json{{info.name, value}}, std::vector<SettingField<S>>{field},
                                    settings);
      }
      return problem;
    };
    if (info.kind == Kind::Flag) {
      flag(info.optionName(), info.help + " (default " + shownDefault + ")", group, apply);
      return;
    }
    std::string valueName = "N";
    if (info.kind == Kind::Number) valueName = "X";
    if (info.kind == Kind::Choice) {
      valueName.clear();
      for (char c : info.name) valueName += static_cast<char>(std::toupper(c));
    }
    value(info.optionName(), valueName,
          info.help + " (default " + shownDefault + "; " + info.expected() + ")", info.expected(),
          group, apply);
  }

  // Parses `args`; "" or the first problem.
  std::string parse(const std::vector<std::string>& args, bool* helpWanted) {
    try {
      app_.parse(std::vector<std::string>(args.rbegin(), args.rend()));
    } catch (const CLI::CallForHelp&) {
      *helpWanted = true;
      return {};
    } catch (const CLI::ArgumentMismatch& e) {
      // An option's value is missing only at the end: CLI11 takes the next word, whatever it
      // is, as a value (a value that looks like an option is caught below).
      const std::string last = args.empty() ? "" : args.back().substr(0, args.back().find('='));
      for (const Binding& b : bindings_) {
        if (b.name == last) return missingValue(b);
      }
      return name_ + ": " + e.what();
    } catch (const CLI::ConversionError& e) {
      for (const std::string& arg : args) {  // a flag given a value it cannot read as on or off
        const size_t equals = arg.find('=');
        for (const Binding& b : bindings_) {
          if (b.isFlag && equals != std::string::npos && arg.substr(0, equals) == b.name) {
            return b.name + ": " + arg.substr(equals + 1) + " is not true or false";
          }
        }
      }
      return name_ + ": " + e.what();
    } catch (const CLI::ParseError& e) {
      return name_ + ": " + e.what();
    }
    // CLI11 takes the word after an option as its value even when it is another option: that
    // option's value is missing (and what followed it is not an extra argument).
    for (const Binding& b : bindings_) {
      if (!b.isFlag && b.option->count() > 0 && b.value.rfind("--", 0) == 0) {
        return missingValue(b);
      }
    }
    const std::vector<std::string> extras = app_.remaining();
    if (!extras.empty()) {
      const std::string& extra = extras.front();
      if (extra.size() > 1 && extra[0] == '-') {
        return name_ + ": unknown option " + extra.substr(0, extra.find('='));
      }
      return name_ + ": unexpected argument '" + extra + "'";
    }
    for (Binding& b : bindings_) {
      if (b.option->count() == 0) continue;
      if (b.isFlag) {
        std::string problem = b.apply(b.flag ? "true" : "false");
        if (!problem.empty()) return problem;
        continue;
      }
      if (b.value.empty()) return missingValue(b);
      std::string problem = b.apply(b.value);
      if (!problem.empty()) return problem;
    }
    return {};
  }

  bool given(const std::string& name) const {
    for (const Binding& b : bindings_) {
      if (b.name == name) return b.option->count() > 0;
    }
    return false;
  }

  // CLI11's help, with one blank line between groups, not two.
  std::string help() const {
    std::string text = app_.help();
    for (size_t at = text.find("\n\n\n"); at != std::string::npos; at = text.find("\n\n\n")) {
      text.erase(at, 1);
    }
    return text;
  }

 private:
  static std::string missingValue(const Binding& b) {
    return b.name + ": missing value (expected " + b.expected + ")";
  }

  std::string name_;
  CLI::App app_;
  std::deque<Binding> bindings_;  // stable addresses: CLI11 writes into them
};

// Setters for options that are not settings of the page. `Int`: int or std::optional<int>.
using Setter = std::function<std::string(const std::string&)>;

template <class Int>
Setter wholeNumberInto(const SettingInfo& info, Int* out) {
  return [info, out](const std::string& text) {
    json value;
    std::string problem = checkSetting(info, text, &value);
    if (problem.empty()) *out = value.get<int>();
    return problem;
  };
}

Setter numberInto(const std::string& name, const std::string& unit, double* out) {
  return [name, unit, out](const std::string& text) {
    const json value = numberJson(text);
    if (value.is_null()) return name + ": " + text + " is not a number of " + unit;
    *out = value.get<double>();
    return std::string();
  };
}

Setter degreesInto(const std::string& name, float* out) {
  return [name, out](const std::string& text) {
    double degrees = 0;
    std::string problem = numberInto(name, "degrees", &degrees)(text);
    if (problem.empty()) *out = static_cast<float>(degrees);
    return problem;
  };
}

Setter textInto(std::string* out) {
  return [out](const std::string& text) {
    *out = text;
    return std::string();
  };
}

std::string sizeExpected() {
  return "WIDTHxHEIGHT with each in 1.." + std::to_string(kMaxFrameSide);
}

// The options render and bench share: the scene, the view, the capture settings.
void defineScene(Command& c, CliOptions& o) {
  c.value("--scene", "NAME",
          "a shipped scene (" + joined(shippedSceneNames()) + ") or a .json file (default " +
              o.scene + ")",
          "a scene name or a .json file", kOptions, [&o](const std::string& text) {
            const std::string problem = checkSceneName(text);
            if (!problem.empty()) return "--scene " + problem;
            o.scene = text;
            return std::string();
          });
  c.value("--assets", "DIR",
          "take the models from DIR by the course's file names (mario.obj sonic.obj sphere.obj "
          "quad.obj); the built-in ones for those it lacks",
          "a folder", kOptions, [&o](const std::string& text) {
            std::error_code error;
            if (!std::filesystem::is_directory(text, error))
              return "--assets " + text + ": not a folder";
            o.assets = text;
            return std::string();
          });
  c.value("--size", "WxH",
          "frame size in pixels, each side 1.." + std::to_string(kMaxFrameSide) + " (default " +
              std::to_string(o.width) + "x" + std::to_string(o.height) + ")",
          sizeExpected(), kOptions, [&o](const std::string& text) {
            const size_t x = text.find('x');
            const SettingInfo side = wholeNumber("side", 1, kMaxFrameSide);
            json w, h;
            if (x == std::string::npos || !checkSetting(side, text.substr(0, x), &w).empty() ||
                !checkSetting(side, text.substr(x + 1), &h).empty()) {
              return "--size: " + text + " is not " + sizeExpected();
            }
            o.width = w.get<int>();
            o.height = h.get<int>();
            o.sizeSet = true;
            return std::string();
          });
  const SettingInfo cube = wholeNumber("cube", 1, Demo::kMaxCubeFaceSize);
  c.value("--cube", "N",
          "cube-map face size, 1.." + std::to_string(Demo::kMaxCubeFaceSize) +
              " (default: the scene's capture.faceSize, 256 in the shipped scenes)",
          cube.expected(), kOptions, wholeNumberInto(cube, &o.cubeSize));
  c.value("--yaw", "DEG", "camera yaw in degrees (default 0)", "a number of degrees", kOptions,
          degreesInto("--yaw", &o.yawDeg));
  c.value("--pitch", "DEG", "camera pitch in degrees, clamped to +/-89 (default 0)",
          "a number of degrees", kOptions, degreesInto("--pitch", &o.pitchDeg));
  c.value("--eye", "X,Y,Z", "camera position (default: the scene's camera eye)",
          "three numbers X,Y,Z", kOptions, [&o](const std::string& text) {
            glm::vec3 eye(0.0f);
            size_t start = 0;
            for (int k = 0; k < 3; ++k) {
              const size_t comma = text.find(',', start);
              if ((k < 2) != (comma != std::string::npos)) {
                return "--eye: " + text + " is not three numbers X,Y,Z";
              }
              const json value =
                  numberJson(text.substr(start, k < 2 ? comma - start : std::string::npos));
              if (value.is_null()) return "--eye: " + text + " is not three numbers X,Y,Z";
              eye[k] = value.get<float>();
              start = comma + 1;
            }
            o.eye = eye;
            return std::string();
          });
}

void defineSettings(Command& c, CliOptions& o) {
  std::string names;
  for (const Preset& p : presets()) names += (names.empty() ? "" : ", ") + p.name;
  std::string help = "start from a named preset (the options given beside it override it):";
  for (const Preset& p : presets()) help += " " + p.name + " (" + p.help + ");";
  help.pop_back();
  c.value("--preset", "NAME", help, "one of " + names, kPlanner,
          [&o, names](const std::string& text) {
            if (!findPreset(text)) return "--preset: \"" + text + "\" is not one of " + names;
            o.preset = text;
            return std::string();
          });
  for (const auto& field : plannerFields()) c.setting(field, o.planner, kPlanner);
  for (const auto& field : accuracyFields()) c.setting(field, o.accuracy, kAccuracy);
}

std::string renderDescription() {
  return "reflect render: render one frame of a scene to a PNG, headless (EGL, GL ES 3)";
}

std::string benchDescription() {
  auto frames = [](BenchMode mode) { return std::to_string(benchFramesDefault(mode)); };
  return "reflect bench: time the capture update policies on the scene, interleaved frame by "
         "frame, and compare their pictures with every-frame's (the default mode: " +
         frames(BenchMode::PolicyComparison) +
         " frames a policy); with --policy, time that policy alone; with --growth, frame time "
         "against reflectors (1, 4, 16) and scene triangles (10k, 100k, 1M); with --sweep, every "
         "accuracy setting against the ray-traced reference (Embree), at 512x512. The "
         "comparison's rows take --faces-per-frame, --every-n, --capture-lod and --view-lod "
         "(0.5 where 0)";
}

void defineRender(Command& c, CliOptions& o) {
  c.value("--time", "SECONDS", "scene time in seconds (default 0); the figures orbit 27 deg/s",
          "a number of seconds", kOptions, numberInto("--time", "seconds", &o.time));
  c.value("--out", "FILE", "the PNG to write (default " + o.out + ")", "a PNG file name", kOptions,
          textInto(&o.out));
  c.value("--reference", "FILE",
          "also write the exact (ray-traced, Embree) frame and print the reflector's error "
          "against it",
          "a PNG file name", kOptions, textInto(&o.referenceOut));
  c.value("--error-view", "FILE",
          "also write the error view of the frame (a heat map of each mirror and glass pixel's "
          "difference from the exact mode) and print the reflector PSNR and the pixels off by "
          "more than 32 levels",
          "a PNG file name", kOptions, textInto(&o.errorViewOut));
  defineScene(c, o);
  defineSettings(c, o);
}

void defineBench(Command& c, CliOptions& o) {
  // "120 a policy": a mode's default count.
  auto perMode = [](BenchMode mode, const std::string& unit, int (*byDefault)(BenchMode)) {
    return std::to_string(byDefault(mode)) + " " + unit;
  };
  c.flag("--growth",
         "mode: frame ms for 1/4/16 reflectors x 10k/100k/1M triangles, with a probe each and "
         "with neighbours sharing probes",
         kOptions, [&o](const std::string& on) {
           o.growth = on == "true";
           return std::string();
         });
  c.flag("--lod-sweep",
         "mode: each captureLod value against full detail: the reflector against the ray-traced "
         "reference at t = 0..5 s, capture triangles and frame ms (the values interleaved); "
         "prints the coarsest value within 0.1 dB and +1 point of pixels off by >32 levels",
         kOptions, [&o](const std::string& on) {
           o.lodSweep = on == "true";
           return std::string();
         });
  c.flag("--view-lod-sweep",
         "mode: each viewLod value against the full-detail view, the camera aimed at the "
         "heaviest figure from several distances: PSNR and pixels off by >32 levels",
         kOptions, [&o](const std::string& on) {
           o.viewLodSweep = on == "true";
           return std::string();
         });
  c.flag("--costs",
         "mode: what the planner's cost model is fitted to: frames drawn as Phong, traced, "
         "captured and searched, and searched alone, with the planner's counts, as ms a unit",
         kOptions, [&o](const std::string& on) {
           o.costs = on == "true";
           return std::string();
         });
  c.flag("--sweep",
         "mode: every accuracy setting (capture point, distance-corrected lookup, face size, "
         "depth bits, filtering, RGBA16F, precision): frame ms and error against the ray-traced "
         "reference",
         kOptions, [&o](const std::string& on) {
           o.sweep = on == "true";
           return std::string();
         });
  const SettingInfo frames = wholeNumber("frames", 1, 1000000);
  c.value("--frames", "N",
          "frames to time (1..1000000; default " +
              perMode(BenchMode::PolicyComparison, "a policy", benchFramesDefault) + ", " +
              perMode(BenchMode::Growth, "a growth cell", benchFramesDefault) + ", " +
              perMode(BenchMode::Sweep, "a sweep setting", benchFramesDefault) + ")",
          frames.expected(), kOptions, wholeNumberInto(frames, &o.frames));
  const SettingInfo warmup = wholeNumber("warmup", 0, 1000000);
  c.value("--warmup", "N",
          "frames before timing (0..1000000; default " +
              perMode(BenchMode::PolicyComparison, "a policy", benchWarmupDefault) + ", " +
              perMode(BenchMode::Growth, "a growth cell", benchWarmupDefault) +
              "; the sweep has none)",
          warmup.expected(), kOptions, wholeNumberInto(warmup, &o.warmup));
  const SettingInfo accuracyFrames = wholeNumber("accuracyFrames", 0, 100000);
  c.value("--accuracy-frames", "N",
          "frames each policy is compared with every-frame (0..100000; default " +
              std::to_string(o.accuracyFrames) + ")",
          accuracyFrames.expected(), kOptions, wholeNumberInto(accuracyFrames, &o.accuracyFrames));
  c.value("--times", "T1,T2,...",
          "the sweeps: the scene times measured, in seconds (default 0,1,2,3,4,5; the view "
          "sweep 0,3; the accuracy sweep reports these instead of its held-out times and skips "
          "its tuning times)",
          "numbers of seconds T1,T2,...", kOptions, [&o](const std::string& text) {
            std::vector<double> times;
            size_t start = 0;
            for (;;) {
              const size_t comma = text.find(',', start);
              const json value = numberJson(text.substr(start, comma - start));
              if (value.is_null())
                return "--times: " + text + " is not numbers of seconds T1,T2,...";
              times.push_back(value.get<double>());
              if (comma == std::string::npos) break;
              start = comma + 1;
            }
            o.times = times;
            return std::string();
          });
  c.value("--only", "NAME,...",
          "sweep: measure only these of its settings, by the names of its rows (e.g. "
          "original,default: the course's and the default, interleaved)",
          "names of sweep settings", kOptions, [&o](const std::string& text) {
            std::vector<std::string> names;
            size_t start = 0;
            for (;;) {
              const size_t comma = text.find(',', start);
              names.push_back(text.substr(start, comma - start));
              if (names.back().empty()) return "--only: " + text + " has an empty name";
              if (comma == std::string::npos) break;
              start = comma + 1;
            }
            o.only = names;
            return std::string();
          });
  c.value("--csv", "FILE", "sweep: write the rows as CSV (name, ms, psnr_db, rmse, p95, ...)",
          "a file name", kOptions, textInto(&o.csv));
  c.value("--svg", "FILE", "sweep: write a plot of error against time with the Pareto front",
          "a file name", kOptions, textInto(&o.svg));
  // The page's frame budget, here a mode: time each search, measure its error against the exact
  // mode, print the table and what "auto" picks.
  for (const auto& field : viewFields()) {
    if (field.info.name == "budget") c.setting(field, o.view, kOptions);
  }
  defineScene(c, o);
  defineSettings(c, o);
}

// The command's definition, bound to `o`.
std::unique_ptr<Command> makeCommand(const std::string& name, CliOptions& o) {
  if (name == "render") {
    auto c = std::make_unique<Command>(name, renderDescription());
    defineRender(*c, o);
    return c;
  }
  auto c = std::make_unique<Command>(name, benchDescription());
  defineBench(*c, o);
  return c;
}

bool isCommand(const std::string& name) {
  return name == "render" || name == "bench";
}

}  // namespace

BenchMode CliOptions::benchMode() const {
  if (budgetSet) return BenchMode::Budget;
  if (sweep) return BenchMode::Sweep;
  if (costs) return BenchMode::Costs;
  if (lodSweep) return BenchMode::LodSweep;
  if (viewLodSweep) return BenchMode::ViewLodSweep;
  if (growth) return BenchMode::Growth;
  return policySet ? BenchMode::SinglePolicy : BenchMode::PolicyComparison;
}

BenchCommandOptions CliOptions::benchOptions() const {
  BenchCommandOptions b;
  b.scene = scene;
  b.assets = assets;
  b.width = width;
  b.height = height;
  b.cubeSize = cubeSize.value_or(b.cubeSize);
  b.frames = frames;
  b.warmup = warmup;
  b.accuracyFrames = accuracyFrames;
  b.planner = planner;
  b.times = times;
  b.only = only;
  if (sizeSet) b.sweepSize = {width, height};
  b.csv = csv;
  b.svg = svg;
  b.budgetMs = view.budget;
  return b;
}

std::string cliHelp(const std::string& command) {
  CliOptions unused;
  if (isCommand(command)) return makeCommand(command, unused)->help();
  return "reflect - dynamic cube-map reflection (the course's Ex12-2), rendered headless\n\n"
         "usage: reflect COMMAND [OPTIONS]\n\n" +
         std::string(kCommandsHelp) + "\n" + makeCommand("render", unused)->help() + "\n" +
         makeCommand("bench", unused)->help();
}

Result<CliOptions> parseCli(const std::vector<std::string>& args) {
  using Out = Result<CliOptions>;
  CliOptions o;
  if (args.empty()) return Out::failure("no command given (try: reflect --help)");
  const std::string& command = args[0];
  if (command == "help" || command == "--help" || command == "-h") {
    o.command = "help";
    if (args.size() > 1) {
      if (!isCommand(args[1])) {
        return Out::failure("help: unknown command '" + args[1] + "' (try: reflect --help)");
      }
      o.helpTopic = args[1];
    }
    if (args.size() > 2) return Out::failure("help: unexpected argument '" + args[2] + "'");
    return o;
  }
  if (!isCommand(command)) {
    return Out::failure("unknown command '" + command + "' (try: reflect --help)");
  }
  o.command = command;
  std::unique_ptr<Command> definition = makeCommand(command, o);
  bool helpWanted = false;
  std::string problem =
      definition->parse(std::vector<std::string>(args.begin() + 1, args.end()), &helpWanted);
  if (!problem.empty()) return Out::failure(problem);
  if (helpWanted) {
    CliOptions help;
    help.command = "help";
    help.helpTopic = command;
    return help;
  }
  // A preset's settings, where no option of the command line gave one.
  if (const Preset* preset = findPreset(o.preset)) {
    for (const auto& field : plannerFields()) {
      if (!definition->given(field.info.optionName())) {
        field.set(o.planner, field.get(preset->planner));
      }
    }
    for (const auto& field : accuracyFields()) {
      if (!definition->given(field.info.optionName())) {
        field.set(o.accuracy, field.get(preset->accuracy));
      }
    }
  }
  o.policySet = definition->given("--policy");
  o.budgetSet = command == "bench" && definition->given("--budget");
  if (o.budgetSet && !(o.view.budget > 0.0f)) {
    return Out::failure(
        "bench: --budget: give the frame budget in ms, above 0 (natively there is "
        "no display interval to default to)");
  }
  if (o.budgetSet && (o.sweep || o.growth)) {
    return Out::failure(
        "bench: --budget is a mode of its own; give it without --sweep or --growth");
  }
  if (command == "bench") {
    if (int(o.growth) + int(o.sweep) + int(o.lodSweep) + int(o.viewLodSweep) + int(o.costs) > 1) {
      return Out::failure(
          "bench: --growth, --sweep, --costs, --lod-sweep and --view-lod-sweep are separate "
          "modes; give one of them");
    }
    for (const char* output : {"--csv", "--svg"}) {
      if (definition->given(output) && !o.sweep) {
        return Out::failure(std::string("bench: ") + output +
                            " is the sweep's output; add --sweep");
      }
    }
  }
  return o;
}

}  // namespace reflect
