// What `reflect` runs once its command line is parsed and a GL context is current: `render`, and
// `bench` in the mode its options select (the drivers are in src/bench/bench_commands.h), on demos
// made from the command line.
#pragma once

#include <string>

#include "platform/native/cli_options.h"

namespace reflect {

// Each prints its report to stdout and the loaders' warnings to stderr ("reflect: warning: ...",
// once each), and returns "" or the error.
std::string runRenderCommand(const CliOptions& options);
std::string runBenchCommand(const CliOptions& options);
// `explain`: renders the frame as render does (nothing written), then prints the explanation of
// options.pixel (app/pixel_explain.h); a pixel outside the frame is an error.
std::string runExplainCommand(const CliOptions& options);

}  // namespace reflect
