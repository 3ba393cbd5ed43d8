// The options of each of `reflect`'s commands, bound to the CliOptions they fill in: `render`,
// `bench` (its modes an option group that CLI11 lets hold at most one) and `help`.
#pragma once

#include <CLI/CLI.hpp>

#include "platform/native/cli_failure.h"
#include "platform/native/cli_options.h"

namespace reflect {

void defineRender(CLI::App& render, CliOptions& options, CliWording& wording);
void defineExplain(CLI::App& explain, CliOptions& options, CliWording& wording);
void defineBench(CLI::App& bench, CliOptions& options, CliWording& wording);
void defineHelp(CLI::App& help, CliOptions& options);

}  // namespace reflect
