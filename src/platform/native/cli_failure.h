// How `reflect` words a command line it cannot take: CLI11's failure-message hook
// (CLI::App::failure_message), so that each mistake reads as it always has, e.g.
// "render: unknown option --bogus", "--time: missing value (expected a number of seconds)".
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <set>
#include <string>

namespace reflect {

// What the messages need to know of the options beyond what CLI11 keeps.
struct CliWording {
  // Each value option's expected value, for "missing value (expected ...)".
  std::map<std::string, std::string> expected;
  // Options whose message names the value first: "--scene nope: no such scene ...".
  std::set<std::string> valueFirst;
};

// The message for `error`, raised while `app` (the top-level app) parsed.
std::string cliFailureMessage(const CliWording& wording, const CLI::App& app,
                              const CLI::Error& error);

}  // namespace reflect
