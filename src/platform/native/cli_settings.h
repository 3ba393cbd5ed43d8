// The options the settings table defines (core/settings_schema.h): a setting added there is an
// option of `render` and `bench` here, named in kebab case (facesPerFrame -> --faces-per-frame),
// with its help, default and checks taken from the table. Also --preset, which fills in the
// settings not given, and the helper that every value option goes through.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/settings_schema.h"
#include "platform/native/cli_failure.h"
#include "platform/native/cli_options.h"

namespace reflect {

// Help groups: where an option is listed in its command's help.
constexpr const char* kOptionsGroup = "options";
constexpr const char* kPlannerGroup = "capture planning (the page's panel: the same settings)";
constexpr const char* kAccuracyGroup = "accuracy (README: Accuracy)";

// `option`, a value option, named VALUE in the help, expecting `expected` (for the message when
// its value is missing).
CLI::Option* valueOption(CLI::Option* option, CliWording& wording, const std::string& valueName,
                         const std::string& expected);

// A whole number that is not a setting of the page (--cube, --frames, ...), checked as one.
SettingInfo wholeNumberInfo(const std::string& name, int min, int max);

// One setting of the table as an option of `app` (a command or one of its option groups), written
// into `settings` when given.
template <class S>
CLI::Option* addSetting(CLI::App& app, CliWording& wording, const SettingField<S>& field,
                        S& settings);

// --preset and every planner and accuracy setting.
void addSettingOptions(CLI::App& command, CliOptions& options, CliWording& wording);

// After `command` parsed: the preset's value for each setting no option gave.
void applyPreset(const CLI::App& command, CliOptions& options);

}  // namespace reflect
