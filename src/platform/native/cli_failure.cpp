#include "platform/native/cli_failure.h"

#include <vector>

namespace reflect {
namespace {

constexpr const char* kTryHelp = " (try: reflect --help)";

// "--time" in "--time: 1 required NUMBER missing" or "--csv requires --sweep": CLI11 names the
// option first.
std::string optionNamed(const CLI::Error& error, char after) {
  const std::string text = error.what();
  return text.substr(0, text.find(after));
}

// A word CLI11 did not take: an unknown command, or a command's unknown option or argument.
std::string leftOver(const CLI::App& app, const CLI::App* command) {
  const std::vector<std::string> extras = app.remaining(true);
  if (command == nullptr) {
    if (extras.empty()) return std::string("no command given") + kTryHelp;
    return "unknown command '" + extras.front() + "'" + kTryHelp;
  }
  const std::string extra = extras.empty() ? std::string() : extras.front();
  if (extra.size() > 1 && extra[0] == '-') {
    return command->get_name() + ": unknown option " + extra.substr(0, extra.find('='));
  }
  return command->get_name() + ": unexpected argument '" + extra + "'";
}

// The bench's modes are an option group that takes at most one of them.
std::string modesMessage(const CLI::App& bench) {
  const CLI::Option* budget = bench.get_option_no_throw("--budget");
  if (budget != nullptr && budget->count() > 0) {
    return "bench: --budget is a mode of its own; give it without --growth, --sweep, --costs, "
           "--lod-sweep or --view-lod-sweep";
  }
  return "bench: --growth, --sweep, --costs, --lod-sweep and --view-lod-sweep are separate modes; "
         "give one of them";
}

// CLI11's "--scene: MESSAGE", where the message names the value first ("--scene nope: no such
// scene ...") or comes from a positional ("help: unknown command ...").
std::string invalidValue(const CliWording& wording, const CLI::App* command,
                         const CLI::Error& error) {
  const std::string text = error.what();
  const size_t colon = text.find(": ");
  if (colon == std::string::npos) return text;
  const std::string name = text.substr(0, colon);
  const std::string problem = text.substr(colon + 2);
  if (command != nullptr && command->get_name() == "help") return "help: " + problem;
  if (wording.valueFirst.count(name) > 0 && problem.rfind("missing value", 0) != 0) {
    return name + " " + problem;
  }
  return text;
}

}  // namespace

std::string cliFailureMessage(const CliWording& wording, const CLI::App& app,
                              const CLI::Error& error) {
  const std::vector<CLI::App*> commands = app.get_subcommands();
  const CLI::App* command = commands.empty() ? nullptr : commands.front();
  const std::string kind = error.get_name();
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr || command == nullptr) {
    return leftOver(app, command);
  }
  if (kind == "ArgumentMismatch") {  // the value of the last option is missing
    const std::string name = optionNamed(error, ':');
    const auto expected = wording.expected.find(name);
    if (expected != wording.expected.end()) {
      return name + ": missing value (expected " + expected->second + ")";
    }
  }
  if (kind == "RequiredError" && command->get_name() == "bench") return modesMessage(*command);
  if (kind == "RequiresError" && optionNamed(error, ' ') == "--lobe-samples") {
    const bool bench = command->get_name() == "bench";
    return command->get_name() + ": --lobe-samples sets the reference's lobe rays; add " +
           (bench ? "--sweep" : "--reference FILE");
  }
  if (kind == "RequiresError") {  // --csv and --svg need --sweep
    return "bench: " + optionNamed(error, ' ') + " is the sweep's output; add --sweep";
  }
  if (kind == "ValidationError") return invalidValue(wording, command, error);
  return command->get_name() + ": " + error.what();
}

}  // namespace reflect
