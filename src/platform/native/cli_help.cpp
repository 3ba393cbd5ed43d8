#include "platform/native/cli_help.h"

#include <string>

namespace reflect {
namespace {

constexpr size_t kHelpColumn = 28;  // where option descriptions start
constexpr size_t kHelpWidth = 100;

// `text` broken into lines of at most `width` characters, at spaces; its own line breaks kept.
std::string wrap(const std::string& text, size_t width) {
  std::string out;
  size_t lineLength = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find_first_of(" \n", start);
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
    if (end < text.size() && text[end] == '\n') {
      out += '\n';
      lineLength = 0;
    }
    start = end + 1;
  }
  return out;
}

class WrappingFormatter : public CLI::Formatter {
 public:
  WrappingFormatter() { column_width(kHelpColumn); }

  std::string make_option_desc(const CLI::Option* option) const override {
    return wrap(CLI::Formatter::make_option_desc(option), kHelpWidth - kHelpColumn);
  }

  // Only the value's name ("--csv FILE"): what an option needs or excludes, its help says.
  std::string make_option_opts(const CLI::Option* option) const override {
    const std::string value = option->get_type_name();
    return option->get_type_size() == 0 || value.empty() ? std::string() : " " + value;
  }

  std::string make_description(const CLI::App* app) const override {
    const std::string text = wrap(CLI::Formatter::make_description(app), kHelpWidth);
    return text.empty() ? text : text + "\n";  // a blank line before the usage
  }
};

}  // namespace

std::shared_ptr<CLI::Formatter> cliHelpFormatter() {
  return std::make_shared<WrappingFormatter>();
}

}  // namespace reflect
