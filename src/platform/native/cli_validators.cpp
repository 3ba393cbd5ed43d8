#include "platform/native/cli_validators.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "platform/native/model_paths.h"

namespace reflect {
namespace {

using nlohmann::json;
using Kind = SettingInfo::Kind;

// A validator that decides and words its failure itself; no description (see the header).
CLI::Validator validator(std::function<std::string(std::string&)> check) {
  return CLI::Validator(std::move(check), "");
}

// `decides` (one of CLI11's validators) decides; a failure reads as `message(value)` words it.
CLI::Validator worded(const CLI::Validator& decides,
                      std::function<std::string(const std::string&)> message) {
  return validator([decides, message](std::string& text) {
    return decides(text).empty() ? std::string() : message(text);
  });
}

// The schema's message for `text` as the value of `info`, without the setting's name ("7 is not
// in 1..6"), the way the page words the same value.
std::string schemaMessage(const SettingInfo& info, const std::string& text) {
  const std::string problem = info.check(settingJson(info, text));
  return problem.substr(std::min(problem.size(), info.name.size() + 2));
}

// "12" for 12, 12.0 and 1.2e1: how a whole number reads in the schema's list of allowed values.
std::string canonicalNumber(const std::string& text) {
  const json value = decimalJson(text);
  if (value.is_null()) return text;
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.15g", value.get<double>());
  return shown;
}

// Splits `text` at commas (an empty text is one empty item).
std::vector<std::string> commaItems(const std::string& text) {
  std::vector<std::string> items;
  size_t start = 0;
  for (;;) {
    const size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

}  // namespace

json decimalJson(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) ||
      text.find_first_of("xX") != std::string::npos) {
    return nullptr;  // strtod's hexadecimal floats and leading blanks are not numbers here
  }
  char* end = nullptr;
  errno = 0;
  const long long whole = std::strtoll(text.c_str(), &end, 10);
  if (*end == '\0' && errno == 0) return whole;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !std::isfinite(value)) return nullptr;
  return value;
}

json settingJson(const SettingInfo& info, const std::string& text) {
  if (info.kind == Kind::Choice) return text;
  if (info.kind == Kind::Flag) return text == "true";
  return decimalJson(text);
}

CLI::Validator notAnOption(const std::string& expected) {
  return validator([expected](std::string& text) {
    return text.empty() || text.rfind("--", 0) == 0 ? "missing value (expected " + expected + ")"
                                                    : std::string();
  });
}

void checkAsSetting(CLI::Option* option, const SettingInfo& info) {
  option->check(notAnOption(info.expected()));
  if (info.kind == Kind::Choice) {
    option->check(worded(CLI::IsMember(info.choices),
                         [info](const std::string& text) { return schemaMessage(info, text); }));
    return;
  }
  option->check(validator([info](std::string& text) {
    return decimalJson(text).is_null() ? text + " is not " + info.expected() : std::string();
  }));
  const auto message = [info](const std::string& text) { return schemaMessage(info, text); };
  if (info.kind == Kind::Integer) {
    option->check(validator([message](std::string& text) {
      const double value = decimalJson(text).get<double>();
      return value == std::floor(value) ? std::string() : message(text);
    }));
  }
  option->check(worded(CLI::Range(info.min, info.max), message));
  if (info.kind == Kind::Integer && !info.choices.empty()) {
    option->check(worded(CLI::IsMember(info.choices, canonicalNumber), message));
  }
}

CLI::Validator flagValue() {
  return validator([](std::string& text) {
    try {
      CLI::detail::to_flag_value(text);  // CLI11's own reading of a flag's value
      return std::string();
    } catch (const std::invalid_argument&) {
      return text + " is not true or false";
    }
  });
}

CLI::Validator decimalNumber(const std::string& unit) {
  return validator([unit](std::string& text) {
    return decimalJson(text).is_null() ? text + " is not a number of " + unit : std::string();
  });
}

std::string frameSizeExpected() {
  return "WIDTHxHEIGHT with each in 1.." + std::to_string(kMaxFrameSide);
}

std::optional<glm::ivec2> parseFrameSize(const std::string& text) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  const json sides[2] = {decimalJson(text.substr(0, x)), decimalJson(text.substr(x + 1))};
  for (const json& side : sides) {
    if (side.is_null()) return std::nullopt;
    const double value = side.get<double>();
    if (value != std::floor(value) || value < 1 || value > kMaxFrameSide) return std::nullopt;
  }
  return glm::ivec2(sides[0].get<int>(), sides[1].get<int>());
}

CLI::Validator frameSize() {
  return validator([](std::string& text) {
    return parseFrameSize(text) ? std::string() : text + " is not " + frameSizeExpected();
  });
}

std::optional<glm::ivec2> parsePixelPosition(const std::string& text) {
  const std::vector<std::string> items = commaItems(text);
  if (items.size() != 2) return std::nullopt;
  glm::ivec2 pixel(0);
  for (int k = 0; k < 2; ++k) {
    const json value = decimalJson(items[static_cast<size_t>(k)]);
    if (value.is_null()) return std::nullopt;
    const double number = value.get<double>();
    if (number != std::floor(number) || number < 0 || number >= kMaxFrameSide) return std::nullopt;
    pixel[k] = static_cast<int>(number);
  }
  return pixel;
}

CLI::Validator pixelPosition() {
  return validator([](std::string& text) {
    return parsePixelPosition(text) ? std::string()
                                    : text + " is not a pixel X,Y (two whole numbers from 0)";
  });
}

std::optional<glm::vec3> parseThreeNumbers(const std::string& text) {
  const std::vector<std::string> items = commaItems(text);
  if (items.size() != 3) return std::nullopt;
  glm::vec3 numbers(0.0f);
  for (int k = 0; k < 3; ++k) {
    const json value = decimalJson(items[k]);
    if (value.is_null()) return std::nullopt;
    numbers[k] = value.get<float>();
  }
  return numbers;
}

CLI::Validator threeNumbers() {
  return validator([](std::string& text) {
    return parseThreeNumbers(text) ? std::string() : text + " is not three numbers X,Y,Z";
  });
}

std::optional<std::vector<double>> parseNumberList(const std::string& text) {
  std::vector<double> numbers;
  for (const std::string& item : commaItems(text)) {
    const json value = decimalJson(item);
    if (value.is_null()) return std::nullopt;
    numbers.push_back(value.get<double>());
  }
  return numbers;
}

CLI::Validator numberList() {
  return validator([](std::string& text) {
    return parseNumberList(text) ? std::string() : text + " is not numbers of seconds T1,T2,...";
  });
}

std::vector<std::string> splitNames(const std::string& text) {
  return commaItems(text);
}

CLI::Validator nameList() {
  return validator([](std::string& text) {
    for (const std::string& name : commaItems(text)) {
      if (name.empty()) return text + " has an empty name";
    }
    return std::string();
  });
}

CLI::Validator oneOf(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return worded(CLI::IsMember(names), [list](const std::string& text) {
    return "\"" + text + "\" is not one of " + list;
  });
}

CLI::Validator sceneNameOrFile() {
  return validator([](std::string& text) { return checkSceneName(text); });
}

CLI::Validator existingFolder() {
  return worded(CLI::ExistingDirectory,
                [](const std::string& text) { return text + ": not a folder"; });
}

CLI::Validator commandName(const std::vector<std::string>& commands) {
  return worded(CLI::IsMember(commands), [](const std::string& text) {
    return "unknown command '" + text + "' (try: reflect --help)";
  });
}

CLI::Validator positiveBudget() {
  return worded(CLI::PositiveNumber, [](const std::string&) {
    return std::string(
        "give the frame budget in ms, above 0 (natively there is no display interval to default "
        "to)");
  });
}

}  // namespace reflect
