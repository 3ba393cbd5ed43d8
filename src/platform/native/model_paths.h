// Where the native build finds its assets: the project's own (assets/ in the source tree), or a
// user's folder of course models.
#pragma once

#include <string>

#include "app/demo.h"
#include "core/result.h"
#include "core/scene.h"

namespace reflect {

// The project's assets folder (compiled-in path to the source tree's assets/).
std::string builtInAssetDirectory();
// Its models/ folder.
std::string builtInModelDirectory();

// A scene by file path, or by name from assets/scenes ("ex12-1" -> assets/scenes/ex12-1.json).
Result<Scene> loadNamedScene(const std::string& nameOrPath);

// Loads every scene mesh from the built-in folder, then, if `userDirectory` is not empty, each
// one that exists there by the same file name; then the scene's skybox images (paths relative to
// the assets folder). Returns "" or the first error (naming the file).
std::string loadSceneModels(Demo& demo, const std::string& userDirectory);

}  // namespace reflect
