// The command line: every option parsed, every mistake answered with what was expected, and the
// help listing the settings table's options (a setting added there is an option with no CLI code).
#include <gtest/gtest.h>

#include <filesystem>

#include "core/settings_schema.h"
#include "platform/native/cli_options.h"

namespace reflect {
namespace {

CliOptions mustParse(const std::vector<std::string>& args) {
  Result<CliOptions> r = parseCli(args);
  EXPECT_TRUE(r) << r.error();
  return r ? r.take() : CliOptions{};
}

std::string errorOf(const std::vector<std::string>& args) {
  Result<CliOptions> r = parseCli(args);
  EXPECT_FALSE(r) << "should not parse";
  return r ? std::string() : r.error();
}

// The help with its wrapped descriptions joined back into single lines.
std::string unwrapped(const std::string& help) {
  std::string text;
  for (size_t i = 0; i < help.size(); ++i) {
    if (help[i] != '\n') {
      text += help[i];
      continue;
    }
    size_t next = help.find_first_not_of(' ', i + 1);
    if (next != std::string::npos && next - i - 1 >= 20) {  // a description's continuation
      text += ' ';
      i = next - 1;
    } else {
      text += '\n';
    }
  }
  return text;
}

const std::string kFolder = std::filesystem::temp_directory_path().string();

TEST(CliOptions, ParsesRender) {
  const CliOptions o = mustParse(
      {"render",   "--size", "640x480",     "--time",    "2.5",     "--out",  "a.png",
       "--assets", kFolder,  "--reference", "exact.png", "--scene", "skybox", "--cube",
       "128",      "--yaw",  "-30",         "--pitch",   "12.5",    "--eye",  "1.5,-2,3e1"});
  EXPECT_EQ(o.command, "render");
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 480);
  EXPECT_DOUBLE_EQ(o.time, 2.5);
  EXPECT_EQ(o.out, "a.png");
  EXPECT_EQ(o.assets, kFolder);
  EXPECT_EQ(o.referenceOut, "exact.png");
  EXPECT_EQ(o.scene, "skybox");
  EXPECT_EQ(o.cubeSize, 128);
  EXPECT_EQ(o.yawDeg, -30.0f);
  EXPECT_EQ(o.pitchDeg, 12.5f);
  ASSERT_TRUE(o.eye.has_value());
  EXPECT_EQ(*o.eye, glm::vec3(1.5f, -2.0f, 30.0f));
  EXPECT_FALSE(mustParse({"render"}).eye.has_value());  // the scene's own
}

// explain takes render's frame options (scene, time, camera, size, settings) and --pixel X,Y.
TEST(CliOptions, ParsesExplain) {
  const CliOptions o =
      mustParse({"explain", "--pixel", "120,45", "--size", "320x240", "--time", "2", "--scene",
                 "skybox", "--yaw", "10", "--eye", "0,1,6", "--search", "linear"});
  EXPECT_EQ(o.command, "explain");
  EXPECT_EQ(o.pixel, glm::ivec2(120, 45));
  EXPECT_EQ(o.width, 320);
  EXPECT_EQ(o.height, 240);
  EXPECT_DOUBLE_EQ(o.time, 2.0);
  EXPECT_EQ(o.scene, "skybox");
  EXPECT_EQ(o.yawDeg, 10.0f);
  EXPECT_EQ(o.eye, glm::vec3(0.0f, 1.0f, 6.0f));
  EXPECT_EQ(o.accuracy.search, Search::Linear);
  EXPECT_EQ(mustParse({"explain", "--pixel", "0,0"}).pixel, glm::ivec2(0, 0));
  EXPECT_EQ(errorOf({"explain", "--pixel", "3"}),
            "--pixel: 3 is not a pixel X,Y (two whole numbers from 0)");
  EXPECT_EQ(errorOf({"explain", "--pixel", "-1,4"}),
            "--pixel: -1,4 is not a pixel X,Y (two whole numbers from 0)");
  EXPECT_EQ(errorOf({"explain", "--pixel", "1.5,4"}),
            "--pixel: 1.5,4 is not a pixel X,Y (two whole numbers from 0)");
  EXPECT_NE(errorOf({"explain"}).find("--pixel"), std::string::npos) << errorOf({"explain"});
  EXPECT_EQ(mustParse({"help", "explain"}).helpTopic, "explain");
  EXPECT_NE(cliHelp("explain").find("--pixel X,Y"), std::string::npos) << cliHelp("explain");
}

TEST(CliOptions, ParsesTheFacesView) {
  const CliOptions o = mustParse({"render", "--faces", "cross.png", "--faces-channel", "distance"});
  EXPECT_EQ(o.facesOut, "cross.png");
  EXPECT_EQ(o.view.facesChannel, FacesChannel::Distance);
  EXPECT_EQ(mustParse({"render"}).view.facesChannel, FacesChannel::Colour);
  EXPECT_NE(errorOf({"render", "--faces-channel", "depth"})
                .find("\"depth\" is not one of colour, distance, layer2, irradiance"),
            std::string::npos)
      << errorOf({"render", "--faces-channel", "depth"});
}

TEST(CliOptions, ParsesTheSteps) {
  EXPECT_EQ(mustParse({"render", "--steps", "out/steps"}).stepsDir, "out/steps");
  EXPECT_EQ(mustParse({"render"}).stepsDir, "");        // off unless asked for
  EXPECT_FALSE(parseCli({"render", "--steps"}));        // a folder is required
  EXPECT_FALSE(parseCli({"bench", "--steps", "out"}));  // render only
}

TEST(CliOptions, DefaultsAreTheDocumentedOnes) {
  const CliOptions o = mustParse({"render"});
  EXPECT_EQ(o.width, 800);
  EXPECT_EQ(o.height, 800);
  EXPECT_EQ(o.time, 0.0);
  EXPECT_EQ(o.out, "frame.png");
  EXPECT_EQ(o.scene, "ex12-2");
  EXPECT_FALSE(o.cubeSize.has_value());  // the scene's own
  EXPECT_EQ(o.planner.policy, PlannerSettings{}.policy);
  EXPECT_TRUE(o.accuracy == AccuracySettings{});
  EXPECT_FALSE(o.policySet);
}

TEST(CliOptions, ParsesEveryPlannerAndAccuracySetting) {
  const CliOptions o = mustParse({"render",
                                  "--policy",
                                  "time-sliced",
                                  "--faces-per-frame",
                                  "3",
                                  "--every-n",
                                  "7",
                                  "--capture-lod",
                                  "0.5",
                                  "--view-lod=0.25",
                                  "--capture-at-origin",
                                  "--search",
                                  "linear",
                                  "--layers",
                                  "1",
                                  "--glass-surfaces",
                                  "1",
                                  "--depth-bits",
                                  "16",
                                  "--mipmaps",
                                  "--half-float",
                                  "--mediump"});
  EXPECT_EQ(o.planner.policy, UpdatePolicy::TimeSliced);
  EXPECT_TRUE(o.policySet);
  EXPECT_EQ(o.planner.facesPerFrame, 3);
  EXPECT_EQ(o.planner.everyN, 7);
  EXPECT_EQ(o.planner.captureLod, 0.5f);
  EXPECT_EQ(o.planner.viewLod, 0.25f);
  EXPECT_TRUE(o.accuracy.captureAtOrigin);
  EXPECT_EQ(o.accuracy.search, Search::Linear);
  EXPECT_EQ(o.accuracy.layers, 1);
  EXPECT_EQ(o.accuracy.glassSurfaces, 1);
  EXPECT_EQ(o.accuracy.depthBits, 16);
  EXPECT_TRUE(o.accuracy.mipmaps);
  EXPECT_TRUE(o.accuracy.halfFloat);
  EXPECT_TRUE(o.accuracy.mediump);
  // A flag can be given as on or off.
  EXPECT_FALSE(mustParse({"render", "--mipmaps=false"}).accuracy.mipmaps);
}

TEST(CliOptions, ParsesBenchAndItsModes) {
  CliOptions o = mustParse({"bench", "--frames", "5", "--warmup", "0", "--accuracy-frames", "3",
                            "--size", "64x32", "--assets", kFolder, "--search", "plain"});
  EXPECT_EQ(o.command, "bench");
  EXPECT_EQ(o.frames, 5);
  EXPECT_EQ(o.warmup, 0);
  EXPECT_EQ(o.accuracyFrames, 3);
  EXPECT_EQ(o.benchMode(), BenchMode::PolicyComparison);
  const BenchCommandOptions b = o.benchOptions();
  EXPECT_EQ(b.width, 64);
  EXPECT_EQ(b.height, 32);
  EXPECT_EQ(b.frames, 5);
  EXPECT_EQ(b.warmup, 0);
  EXPECT_EQ(b.accuracyFrames, 3);
  EXPECT_EQ(b.assets, kFolder);
  EXPECT_EQ(b.cubeSize, 256);

  EXPECT_EQ(mustParse({"bench", "--policy", "every-frame"}).benchMode(), BenchMode::SinglePolicy);
  EXPECT_EQ(mustParse({"bench", "--growth"}).benchMode(), BenchMode::Growth);
  EXPECT_EQ(mustParse({"bench", "--lod-sweep"}).benchMode(), BenchMode::LodSweep);
  EXPECT_EQ(mustParse({"bench", "--view-lod-sweep"}).benchMode(), BenchMode::ViewLodSweep);
  o = mustParse({"bench", "--sweep", "--csv", "s.csv", "--svg", "s.svg"});
  EXPECT_EQ(o.benchMode(), BenchMode::Sweep);
  EXPECT_EQ(o.csv, "s.csv");
  EXPECT_EQ(o.svg, "s.svg");
  // Unset, the frame counts are each mode's own, which the help states.
  EXPECT_FALSE(o.frames.has_value());
  EXPECT_EQ(benchFramesDefault(BenchMode::PolicyComparison), 120);
  EXPECT_EQ(benchFramesDefault(BenchMode::Sweep), 30);
  EXPECT_EQ(benchFramesDefault(BenchMode::Growth), 6);
}

TEST(CliOptions, TheLastOfARepeatedOptionWins) {
  EXPECT_EQ(mustParse({"render", "--time", "1", "--time", "2"}).time, 2.0);
}

TEST(CliOptions, HelpInAnyPosition) {
  EXPECT_EQ(mustParse({"--help"}).command, "help");
  EXPECT_EQ(mustParse({"-h"}).command, "help");
  EXPECT_EQ(mustParse({"help"}).helpTopic, "");
  EXPECT_EQ(mustParse({"help", "bench"}).helpTopic, "bench");
  const CliOptions o = mustParse({"render", "--size", "8x8", "--help"});
  EXPECT_EQ(o.command, "help");
  EXPECT_EQ(o.helpTopic, "render");
}

TEST(CliOptions, HelpListsEveryCommandAndEverySetting) {
  const std::string help = unwrapped(cliHelp());
  for (const char* text :
       {"render", "bench", "--growth", "--sweep", "--frames", "--size", "--scene", "--assets",
        "--reference", "two-mirrors", "30 a sweep setting"}) {
    EXPECT_NE(help.find(text), std::string::npos) << text;
  }
  for (const std::string& command : {std::string("render"), std::string("bench")}) {
    const std::string one = unwrapped(cliHelp(command));
    for (const auto& field : plannerFields()) {
      EXPECT_NE(one.find(field.info.optionName()), std::string::npos) << field.info.name;
      EXPECT_NE(one.find(field.info.expected()), std::string::npos) << field.info.name;
    }
    for (const auto& field : accuracyFields()) {
      EXPECT_NE(one.find(field.info.optionName()), std::string::npos) << field.info.name;
    }
  }
  EXPECT_EQ(cliHelp("render").find("--frames"), std::string::npos);
  const std::string render = unwrapped(cliHelp("render"));
  EXPECT_NE(render.find("  --faces-per-frame N       time-sliced: faces redrawn per frame (default "
                        "2; a whole number from 1 to 6)\n"),
            std::string::npos)
      << render;
}

TEST(CliOptions, ErrorsSayWhatIsExpected) {
  EXPECT_EQ(errorOf({}), "no command given (try: reflect --help)");
  EXPECT_EQ(errorOf({"draw"}), "unknown command 'draw' (try: reflect --help)");
  EXPECT_EQ(errorOf({"help", "draw"}), "help: unknown command 'draw' (try: reflect --help)");
  EXPECT_EQ(errorOf({"render", "--bogus"}), "render: unknown option --bogus");
  EXPECT_EQ(errorOf({"render", "--bogus=1"}), "render: unknown option --bogus");
  EXPECT_EQ(errorOf({"bench", "--time", "1"}), "bench: unknown option --time");
  EXPECT_EQ(errorOf({"render", "--frames", "3"}), "render: unknown option --frames");
  EXPECT_EQ(errorOf({"render", "x.png"}), "render: unexpected argument 'x.png'");
  // The old option names are gone.
  EXPECT_EQ(errorOf({"render", "--slice", "2"}), "render: unknown option --slice");
  EXPECT_EQ(errorOf({"bench", "--distance", "0"}), "bench: unknown option --distance");

  EXPECT_EQ(errorOf({"render", "--size", "0x0"}),
            "--size: 0x0 is not WIDTHxHEIGHT with each in 1..16384");
  EXPECT_EQ(errorOf({"render", "--size", "800"}),
            "--size: 800 is not WIDTHxHEIGHT with each in 1..16384");
  EXPECT_EQ(errorOf({"render", "--size", "16385x1"}),
            "--size: 16385x1 is not WIDTHxHEIGHT with each in 1..16384");
  EXPECT_EQ(errorOf({"render", "--size", "8x0x10"}),
            "--size: 8x0x10 is not WIDTHxHEIGHT with each in 1..16384");
  EXPECT_EQ(errorOf({"render", "--cube", "100000"}), "--cube: 100000 is not in 1..4096");
  EXPECT_EQ(errorOf({"render", "--cube", "0x10"}),
            "--cube: 0x10 is not a whole number from 1 to 4096");
  EXPECT_EQ(errorOf({"render", "--cube", "0"}), "--cube: 0 is not in 1..4096");
  EXPECT_EQ(errorOf({"render", "--cube", "1.5"}), "--cube: 1.5 is not a whole number");
  EXPECT_EQ(errorOf({"render", "--cube", "big"}),
            "--cube: big is not a whole number from 1 to 4096");
  EXPECT_EQ(errorOf({"render", "--time", "nan"}), "--time: nan is not a number of seconds");
  EXPECT_EQ(errorOf({"render", "--time", "1e999"}), "--time: 1e999 is not a number of seconds");
  EXPECT_EQ(errorOf({"render", "--yaw", "left"}), "--yaw: left is not a number of degrees");
  EXPECT_EQ(errorOf({"bench", "--frames", "1.5"}), "--frames: 1.5 is not a whole number");
  EXPECT_EQ(errorOf({"bench", "--frames", "0"}), "--frames: 0 is not in 1..1000000");
  EXPECT_EQ(errorOf({"bench", "--warmup", "-1"}), "--warmup: -1 is not in 0..1000000");
  EXPECT_EQ(errorOf({"bench", "--accuracy-frames", "x"}),
            "--accuracy-frames: x is not a whole number from 0 to 100000");
  EXPECT_EQ(errorOf({"render", "--scene", "nope"}),
            "--scene nope: no such scene (shipped: ex12-2, ex12-1, ex12-2-fresnel, frosted-glass, "
            "glass-sphere, probe-lit, rough-spheres, "
            "shared-probe, skybox, skybox-grid, two-mirrors) and no such .json file");
  EXPECT_EQ(errorOf({"render", "--assets", "/no/such/folder"}),
            "--assets /no/such/folder: not a folder");
  EXPECT_EQ(errorOf({"bench", "--growth", "--sweep"}),
            "bench: --growth, --sweep, --costs, --lod-sweep and --view-lod-sweep are separate "
            "modes; give one of them");
  EXPECT_EQ(errorOf({"bench", "--lod-sweep", "--view-lod-sweep"}),
            "bench: --growth, --sweep, --costs, --lod-sweep and --view-lod-sweep are separate "
            "modes; give one of them");
  EXPECT_EQ(errorOf({"render", "--eye", "1,2"}), "--eye: 1,2 is not three numbers X,Y,Z");
  EXPECT_EQ(errorOf({"render", "--eye", "1,2,x"}), "--eye: 1,2,x is not three numbers X,Y,Z");
  EXPECT_EQ(errorOf({"render", "--eye", "1,2,3,4"}), "--eye: 1,2,3,4 is not three numbers X,Y,Z");
  EXPECT_EQ(errorOf({"bench", "--csv", "a.csv"}),
            "bench: --csv is the sweep's output; add --sweep");
}

TEST(CliOptions, AMissingValueNamesTheOption) {
  EXPECT_EQ(errorOf({"render", "--time"}), "--time: missing value (expected a number of seconds)");
  EXPECT_EQ(errorOf({"render", "--time", "--out", "a.png"}),
            "--time: missing value (expected a number of seconds)");
  EXPECT_EQ(errorOf({"render", "--out"}), "--out: missing value (expected a PNG file name)");
  EXPECT_EQ(errorOf({"render", "--size="}),
            "--size: missing value (expected WIDTHxHEIGHT with each in 1..16384)");
  EXPECT_EQ(errorOf({"bench", "--faces-per-frame"}),
            "--faces-per-frame: missing value (expected a whole number from 1 to 6)");
  EXPECT_EQ(errorOf({"bench", "--policy"}),
            "--policy: missing value (expected one of every-frame, when-changed, time-sliced, "
            "every-n)");
}

// Each command has CLI11's own --help, and `help COMMAND` prints the same text.
TEST(CliOptions, EachCommandHasItsOwnHelp) {
  EXPECT_EQ(mustParse({"bench", "--help"}).helpTopic, "bench");
  EXPECT_EQ(mustParse({"help", "--help"}).helpTopic, "");
  for (const std::string command : {"render", "bench"}) {
    const std::string help = cliHelp(command);
    EXPECT_NE(help.find("Usage: reflect " + command + " [OPTIONS]"), std::string::npos) << help;
    EXPECT_NE(help.find("  -h,--help                 show this help\n"), std::string::npos);
  }
  EXPECT_NE(cliHelp("bench").find("[At most 1 of the following options are allowed]"),
            std::string::npos);
  EXPECT_EQ(errorOf({"help", "render", "bench"}), "help: unexpected argument 'bench'");
}

// The bench's modes are one option group, which CLI11 lets hold one of them at most.
TEST(CliOptions, TheBenchTakesOneModeAtMost) {
  EXPECT_EQ(mustParse({"bench", "--costs"}).benchMode(), BenchMode::Costs);
  const CliOptions budget = mustParse({"bench", "--budget", "30"});
  EXPECT_EQ(budget.benchMode(), BenchMode::Budget);
  EXPECT_EQ(budget.view.budget, 30.0f);
  for (const char* mode : {"--sweep", "--growth", "--costs", "--lod-sweep", "--view-lod-sweep"}) {
    EXPECT_EQ(errorOf({"bench", "--budget", "30", mode}),
              "bench: --budget is a mode of its own; give it without --growth, --sweep, --costs, "
              "--lod-sweep or --view-lod-sweep")
        << mode;
  }
  EXPECT_EQ(errorOf({"bench", "--costs", "--sweep"}),
            "bench: --growth, --sweep, --costs, --lod-sweep and --view-lod-sweep are separate "
            "modes; give one of them");
  EXPECT_EQ(errorOf({"bench", "--budget", "0"}),
            "--budget: give the frame budget in ms, above 0 (natively there is no display "
            "interval to default to)");
  EXPECT_EQ(errorOf({"bench", "--svg", "a.svg", "--growth"}),
            "bench: --svg is the sweep's output; add --sweep");
}

TEST(CliOptions, ValuesReadAsTheyAlwaysHave) {
  EXPECT_TRUE(mustParse({"render", "--mipmaps=on"}).accuracy.mipmaps);  // CLI11's flag words
  EXPECT_EQ(mustParse({"render", "--cube", "128.0"}).cubeSize, 128);    // a whole number
  EXPECT_EQ(mustParse({"render", "--depth-bits", "16.0"}).accuracy.depthBits, 16);
  EXPECT_EQ(mustParse({"bench", "--times", "0.5,2"}).times, std::vector<double>({0.5, 2.0}));
  EXPECT_EQ(mustParse({"bench", "--only", "original,default"}).only,
            std::vector<std::string>({"original", "default"}));
  EXPECT_EQ(mustParse({"render", "--preset", "course"}).planner.policy, UpdatePolicy::EveryFrame);
  // An option given beside the preset overrides it.
  EXPECT_EQ(mustParse({"render", "--preset", "course", "--policy", "every-n"}).planner.policy,
            UpdatePolicy::EveryNFrames);
  EXPECT_EQ(errorOf({"render", "--preset", "nope"}),
            "--preset: \"nope\" is not one of default, course");
  EXPECT_EQ(errorOf({"render", "--scene", "--out"}),
            "--scene: missing value (expected a scene name or a .json file)");
  EXPECT_EQ(errorOf({"bench", "--times", "1,,2"}),
            "--times: 1,,2 is not numbers of seconds T1,T2,...");
  EXPECT_EQ(errorOf({"bench", "--only", "a,,b"}), "--only: a,,b has an empty name");
  EXPECT_EQ(errorOf({"--bogus"}), "unknown command '--bogus' (try: reflect --help)");
}

// The settings' own checks, the page's messages with the option's name.
TEST(CliOptions, SettingsAreCheckedAsThePageChecksThem) {
  EXPECT_EQ(errorOf({"render", "--faces-per-frame", "7"}), "--faces-per-frame: 7 is not in 1..6");
  EXPECT_EQ(errorOf({"render", "--faces-per-frame", "2.5"}),
            "--faces-per-frame: 2.5 is not a whole number");
  EXPECT_EQ(errorOf({"render", "--every-n", "0"}), "--every-n: 0 is not in 1..1000");
  EXPECT_EQ(
      errorOf({"render", "--policy", "sometimes"}),
      "--policy: \"sometimes\" is not one of every-frame, when-changed, time-sliced, every-n");
  EXPECT_EQ(errorOf({"render", "--capture-lod", "-1"}), "--capture-lod: -1 is not in 0..1000");
  EXPECT_EQ(errorOf({"render", "--view-lod", "much"}),
            "--view-lod: much is not a number from 0 to 1000");
  EXPECT_EQ(errorOf({"render", "--layers", "3"}), "--layers: 3 is not in 1..2");
  EXPECT_EQ(errorOf({"render", "--search", "binary"}),
            "--search: \"binary\" is not one of plain, linear, hierarchical, exact, planned");
  EXPECT_EQ(errorOf({"render", "--depth-bits", "20"}), "--depth-bits: 20 is not one of 16, 24");
  EXPECT_EQ(errorOf({"render", "--mipmaps=maybe"}), "--mipmaps: maybe is not true or false");
  // The page's message for the same value, for comparison.
  PlannerSettings planner;
  EXPECT_EQ(applySettingsJson(nlohmann::json{{"facesPerFrame", 7}}, plannerFields(), planner),
            "facesPerFrame: 7 is not in 1..6");
}

}  // namespace
}  // namespace reflect
