// Where the native build finds its assets: the project's own (assets/ in the source tree), or a
// user's folder of course models.
#pragma once

#include <string>
#include <vector>

#include "app/demo.h"
#include "core/result.h"
#include "core/scene.h"

namespace reflect {

// The project's assets folder (compiled-in path to the source tree's assets/).
std::string builtInAssetDirectory();
// Its models/ folder.
std::string builtInModelDirectory();

// The shipped scenes' names (assets/scenes/*.json without the extension): the default, ex12-2,
// first, then by name, as the page's picker lists them.
std::vector<std::string> shippedSceneNames();

// "" when `nameOrPath` is a shipped scene's name or a file; otherwise
// "NAME: no such scene (shipped: ex12-2, ex12-1, ...) and no such .json file".
std::string checkSceneName(const std::string& nameOrPath);

// A scene by name from assets/scenes ("ex12-1" -> assets/scenes/ex12-1.json), or else by file
// path. An unknown name fails with checkSceneName's message.
Result<Scene> loadNamedScene(const std::string& nameOrPath);

// Loads every scene mesh: from `userDirectory` (when not empty) where it has a file of that name,
// from the built-in folder otherwise; then the scene's skybox images (paths relative to the
// assets folder). Returns "" or the first error (naming the file). The loader's warnings
// (each naming its file) are added to `warnings` when it is given.
std::string loadSceneModels(Demo& demo, const std::string& userDirectory,
                            std::vector<std::string>* warnings = nullptr);

}  // namespace reflect
