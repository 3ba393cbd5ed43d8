// Where the native build finds models: the project's own in assets/models, or a user's folder.
#pragma once

#include <string>

#include "app/demo.h"

namespace reflect {

// The project's models (compiled-in path to the source tree's assets/models).
std::string builtInModelDirectory();
// Loads every scene mesh from the built-in folder, then, if `userDirectory` is not empty, each
// one that exists there by the same file name. Returns "" or the first error (naming the file).
std::string loadSceneModels(Demo& demo, const std::string& userDirectory);

}  // namespace reflect
