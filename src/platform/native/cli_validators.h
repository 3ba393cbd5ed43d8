// What each value of `reflect`'s command line must be, as CLI11 validators. CLI11 decides with its
// own validators where it has one (CLI::Range, CLI::IsMember, CLI::ExistingDirectory); a failure
// is worded as the settings schema words the page's (core/settings_schema.h), and CLI11 puts the
// option's name in front: "--cube: 100000 is not in 1..4096". No validator has a description of
// its own: each option's help says what it takes, in words.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/settings_schema.h"

namespace reflect {

// `text` as the JSON value the schema checks (an integer when it reads as one), or null when it is
// not a finite decimal number (hexadecimal, blanks, "nan" and "inf" are not numbers here).
nlohmann::json decimalJson(const std::string& text);

// `text` as the value of the setting `info`: a choice's name, a flag's true or false, a number (or
// null, when it is not one).
nlohmann::json settingJson(const SettingInfo& info, const std::string& text);

// The checks of a value option, first of all: CLI11 takes the word after an option as its value
// even when it is the next option, and then the value is missing.
CLI::Validator notAnOption(const std::string& expected);

// A number, choice or whole number of the settings table (or shaped like one, such as --cube):
// a decimal number, whole where it must be, in range, one of the allowed values.
void checkAsSetting(CLI::Option* option, const SettingInfo& info);

// A flag's value (--mipmaps=false) that CLI11 reads as on or off.
CLI::Validator flagValue();

// A finite decimal number: "--time: nan is not a number of seconds".
CLI::Validator decimalNumber(const std::string& unit);

// The largest frame side llvmpipe and most GPUs allow.
constexpr int kMaxFrameSide = 16384;
std::string frameSizeExpected();  // "WIDTHxHEIGHT with each in 1..16384"
CLI::Validator frameSize();
// "640x480" -> {640, 480}; nothing unless it passes frameSize.
std::optional<glm::ivec2> parseFrameSize(const std::string& text);

CLI::Validator pixelPosition();  // explain --pixel X,Y: two whole numbers, 0 or more
std::optional<glm::ivec2> parsePixelPosition(const std::string& text);
CLI::Validator threeNumbers();  // --eye X,Y,Z
std::optional<glm::vec3> parseThreeNumbers(const std::string& text);
CLI::Validator numberList();  // --times T1,T2,...
std::optional<std::vector<double>> parseNumberList(const std::string& text);
CLI::Validator nameList();  // --only NAME,... (no empty name)
std::vector<std::string> splitNames(const std::string& text);

// One of `names`: "\"x\" is not one of a, b".
CLI::Validator oneOf(const std::vector<std::string>& names);
// A shipped scene's name or a scene file (model_paths' message).
CLI::Validator sceneNameOrFile();
// An existing folder: "DIR: not a folder".
CLI::Validator existingFolder();
// A help topic: one of `commands`, else "unknown command 'X' (try: reflect --help)".
CLI::Validator commandName(const std::vector<std::string>& commands);
// Above 0 (bench --budget: natively there is no display interval to default to).
CLI::Validator positiveBudget();

}  // namespace reflect
