// `reflect`: the native, headless entry point (EGL surfaceless). Same scene, same shaders as the
// page; writes PNGs and prints timings. It parses the command line (cli_options), makes the GL
// context and hands over to the command (native_commands, src/bench/bench_commands).
#include <cstdio>
#include <string>
#include <vector>

#include "platform/native/cli_options.h"
#include "platform/native/egl_context.h"
#include "platform/native/native_commands.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "reflect: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  auto parsed = reflect::parseCli(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed) return fail(parsed.error());
  const reflect::CliOptions& o = parsed.value();
  if (o.command == "help") {
    std::fputs(reflect::cliHelp(o.helpTopic).c_str(), stdout);
    return 0;
  }
  auto context = reflect::HeadlessGlContext::create();
  if (!context) return fail(context.error());
  if (o.command == "bench") std::printf("GL: %s\n", context.value()->description().c_str());
  const std::string error = o.command == "render"    ? reflect::runRenderCommand(o)
                            : o.command == "explain" ? reflect::runExplainCommand(o)
                                                     : reflect::runBenchCommand(o);
  return error.empty() ? 0 : fail(error);
}
