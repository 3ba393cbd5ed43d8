#include "platform/native/cli_settings.h"

#include <cctype>
#include <cstdio>

#include "core/presets.h"
#include "platform/native/cli_validators.h"

namespace reflect {
namespace {

using nlohmann::json;
using Kind = SettingInfo::Kind;

// A setting's default as its help shows it: "on", "every-frame", "2", "0.5".
std::string shownDefault(const json& value, Kind kind) {
  if (kind == Kind::Flag) return value.get<bool>() ? "on" : "off";
  if (value.is_string()) return value.get<std::string>();
  if (!value.is_number_float()) return value.dump();
  char text[32];
  std::snprintf(text, sizeof text, "%g", value.get<double>());
  return text;
}

// N for a whole number, X for a number, the setting's name in capitals for a choice.
std::string valueName(const SettingInfo& info) {
  if (info.kind == Kind::Number) return "X";
  if (info.kind != Kind::Choice) return "N";
  std::string name;
  for (char c : info.name) name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

void addPreset(CLI::App& command, CliOptions& o, CliWording& wording) {
  std::vector<std::string> names;
  std::string help = "start from a named preset (the options given beside it override it):";
  for (const Preset& p : presets()) {
    names.push_back(p.name);
    help += " " + p.name + " (" + p.help + ");";
  }
  help.pop_back();
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  valueOption(command.add_option("--preset", o.preset, help), wording, "NAME", "one of " + list)
      ->check(oneOf(names))
      ->group(kPlannerGroup);
}

}  // namespace

CLI::Option* valueOption(CLI::Option* option, CliWording& wording, const std::string& valueName,
                         const std::string& expected) {
  wording.expected[option->get_name()] = expected;
  return option->type_name(valueName)->check(notAnOption(expected));
}

SettingInfo wholeNumberInfo(const std::string& name, int min, int max) {
  SettingInfo info;
  info.name = name;
  info.kind = Kind::Integer;
  info.min = min;
  info.max = max;
  return info;
}

template <class S>
CLI::Option* addSetting(CLI::App& app, CliWording& wording, const SettingField<S>& field,
                        S& settings) {
  const SettingInfo& info = field.info;
  const std::string byDefault = shownDefault(field.get(S{}), info.kind);
  if (info.kind == Kind::Flag) {
    auto set = [&field, &settings](std::int64_t on) { field.set(settings, json(on > 0)); };
    return app
        .add_flag_function(info.optionName(), set, info.help + " (default " + byDefault + ")")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
        ->check(flagValue());
  }
  // The value has passed the checks below: a choice's name, or a number.
  auto set = [&field, &settings](const std::string& text) {
    field.set(settings, settingJson(field.info, text));
  };
  CLI::Option* option = app.add_option_function<std::string>(
      info.optionName(), set, info.help + " (default " + byDefault + "; " + info.expected() + ")");
  wording.expected[option->get_name()] = info.expected();
  option->type_name(valueName(info));
  checkAsSetting(option, info);
  return option;
}

template CLI::Option* addSetting(CLI::App&, CliWording&, const SettingField<PlannerSettings>&,
                                 PlannerSettings&);
template CLI::Option* addSetting(CLI::App&, CliWording&, const SettingField<AccuracySettings>&,
                                 AccuracySettings&);
template CLI::Option* addSetting(CLI::App&, CliWording&, const SettingField<ViewSettings>&,
                                 ViewSettings&);

void addSettingOptions(CLI::App& command, CliOptions& o, CliWording& wording) {
  addPreset(command, o, wording);
  for (const auto& field : plannerFields()) {
    addSetting(command, wording, field, o.planner)->group(kPlannerGroup);
  }
  for (const auto& field : accuracyFields()) {
    addSetting(command, wording, field, o.accuracy)->group(kAccuracyGroup);
  }
}

void applyPreset(const CLI::App& command, CliOptions& o) {
  const Preset* preset = findPreset(o.preset);
  if (preset == nullptr) return;
  for (const auto& field : plannerFields()) {
    if (command.count(field.info.optionName()) == 0)
      field.set(o.planner, field.get(preset->planner));
  }
  for (const auto& field : accuracyFields()) {
    if (command.count(field.info.optionName()) == 0) {
      field.set(o.accuracy, field.get(preset->accuracy));
    }
  }
}

}  // namespace reflect
