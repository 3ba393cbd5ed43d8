#include "platform/native/cli_materials.h"

#include <nlohmann/json.hpp>

#include "core/settings_schema.h"

namespace reflect {
namespace {

// "0.5" -> 0.5, "true" -> true, "mirror" -> "mirror": a value as the JSON it would be in a file.
nlohmann::json valueOf(const std::string& text) {
  nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
  return parsed.is_discarded() ? nlohmann::json(text) : parsed;
}

std::string applyOne(const std::string& entry, Scene& scene) {
  const std::string what = "--material " + entry + ": ";
  const size_t colon = entry.find(':');
  if (colon == std::string::npos || colon == 0) {
    return what + "expected INDEX:NAME=VALUE[,NAME=VALUE...]";
  }
  const std::string indexText = entry.substr(0, colon);
  if (indexText.find_first_not_of("0123456789") != std::string::npos || indexText.size() > 6) {
    return what + "the object index must be a whole number";
  }
  const size_t index = std::stoul(indexText);
  if (index >= scene.objects.size()) {
    return what + "the scene has objects 0.." + std::to_string(scene.objects.size() - 1);
  }
  nlohmann::json changes = nlohmann::json::object();
  size_t start = colon + 1;
  while (start <= entry.size()) {
    const size_t comma = std::min(entry.find(',', start), entry.size());
    const std::string pair = entry.substr(start, comma - start);
    const size_t equals = pair.find('=');
    if (equals == std::string::npos || equals == 0) return what + "expected NAME=VALUE";
    changes[pair.substr(0, equals)] = valueOf(pair.substr(equals + 1));
    start = comma + 1;
  }
  const std::string error = applySettingsJson(changes, materialFields(), scene.objects[index]);
  return error.empty() ? "" : what + error;
}

}  // namespace

std::string applyMaterialOptions(const std::vector<std::string>& entries, Scene& scene) {
  for (const std::string& entry : entries) {
    const std::string error = applyOne(entry, scene);
    if (!error.empty()) return error;
  }
  return "";
}

}  // namespace reflect
