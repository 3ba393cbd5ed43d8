#include "platform/native/cli_options.h"

#include <CLI/CLI.hpp>
#include <memory>
#include <sstream>

#include "platform/native/cli_commands.h"
#include "platform/native/cli_failure.h"
#include "platform/native/cli_help.h"
#include "platform/native/cli_settings.h"

namespace reflect {
namespace {

// A subcommand of `app`, its --help listed first among its options.
CLI::App& addCommand(CLI::App& app, const std::string& name, const std::string& description) {
  CLI::App* command = app.add_subcommand(name, description);
  command->set_help_flag("-h,--help", "show this help")->group(kOptionsGroup);
  return *command;
}

// The whole command line, bound to `options`: the subcommands render, bench and help, each with
// its own --help, and the failure messages worded by `wording`.
std::unique_ptr<CLI::App> makeCli(CliOptions& options, CliWording& wording) {
  auto app = std::make_unique<CLI::App>(
      "reflect - dynamic cube-map reflection (the course's Ex12-2), rendered headless", "reflect");
  app->formatter(cliHelpFormatter());
  app->set_help_flag("-h,--help", "show this help (reflect COMMAND --help: one command's)");
  // Options and subcommands made from here on take these.
  app->option_defaults()
      ->group(kOptionsGroup)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app->require_subcommand(1);
  app->failure_message([&wording](const CLI::App* top, const CLI::Error& error) {
    return cliFailureMessage(wording, *top, error);
  });
  defineRender(addCommand(*app, "render",
                          "render one frame of a scene to a PNG, headless "
                          "(EGL, GL ES 3)"),
               options, wording);
  defineExplain(addCommand(*app, "explain",
                           "render one frame as render does, then explain one mirror or glass "
                           "pixel of it: the view ray, the reflected or refracted ray, the probe "
                           "centre, the course's lookup, where the search lands and the exact "
                           "hit, each lookup's angular error and colour against the exact"),
                options, wording);
  defineBench(
      addCommand(*app, "bench",
                 "time the capture update policies on the scene, interleaved frame by frame, and "
                 "compare their pictures with every-frame's (the default mode: " +
                     std::to_string(benchFramesDefault(BenchMode::PolicyComparison)) +
                     " frames a policy); or one of the modes below. The comparison's rows take "
                     "--faces-per-frame, --every-n, --capture-lod and --view-lod (0.5 where 0)"),
      options, wording);
  defineHelp(addCommand(*app, "help",
                        "this text; one command's options: reflect help "
                        "COMMAND, or reflect COMMAND --help"),
             options);
  return app;
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
  b.lobeSamples = lobeSamples;
  return b;
}

std::string cliHelp(const std::string& command) {
  CliOptions unused;
  CliWording wording;
  const std::unique_ptr<CLI::App> app = makeCli(unused, wording);
  if (command.empty()) return app->help("", CLI::AppFormatMode::All);
  return app->get_subcommand(command)->help("reflect");
}

Result<CliOptions> parseCli(const std::vector<std::string>& args) {
  CliOptions options;
  CliWording wording;
  const std::unique_ptr<CLI::App> app = makeCli(options, wording);
  try {
    app->parse(std::vector<std::string>(args.rbegin(), args.rend()));  // CLI11 pops from the back
  } catch (const CLI::CallForHelp&) {
    CliOptions help;
    help.command = "help";
    for (const CLI::App* command : app->get_subcommands()) {
      if (command->get_name() != "help") help.helpTopic = command->get_name();
    }
    return help;
  } catch (const CLI::ParseError& error) {
    std::ostringstream out, message;
    app->exit(error, out, message);  // CLI11's way to a failure's message: failure_message's
    return Result<CliOptions>::failure(message.str());
  }
  return options;
}

}  // namespace reflect
