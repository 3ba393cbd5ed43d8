// Scene files: assets/scenes/*.json to Scene. Every error names the file and the key path
// ("scenes/x.json: objects[2].material.ior: expected a number from 1 to 4"). The format is
// documented in README ("Scene files").
#pragma once

#include <string>

#include "core/result.h"
#include "core/scene.h"

namespace reflect {

constexpr size_t kMaxSceneFileBytes = 1u << 20;
constexpr size_t kMaxSceneObjects = 256;

Result<Scene> parseSceneJson(const std::string& text, const std::string& source);
// One entry of "objects" (the page adds a dropped model with it), and one "material".
Result<SceneObject> parseSceneObjectJson(const std::string& text, const std::string& source);
// Applies a "material" object (the keys given) to `object`.
std::string applyMaterialJson(const std::string& text, const std::string& source,
                              SceneObject& object);
Result<Scene> loadSceneFile(const std::string& path);

}  // namespace reflect
