// `reflect`'s help, written by CLI11 from the options' definitions: this formatter only breaks
// long descriptions into lines, which CLI11 2.1 does not, and names an option's value alone.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>

namespace reflect {

std::shared_ptr<CLI::Formatter> cliHelpFormatter();

}  // namespace reflect
