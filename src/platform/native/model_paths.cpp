#include "platform/native/model_paths.h"

#include <cstdio>
#include <filesystem>

namespace reflect {

std::string builtInModelDirectory() { return REFLECT_MODEL_DIR; }

std::string loadSceneModels(Demo& demo, const std::string& userDirectory) {
  std::string error = demo.loadMeshesFrom(builtInModelDirectory());
  if (!error.empty() || userDirectory.empty()) return error;
  if (!std::filesystem::is_directory(userDirectory)) {
    return userDirectory + ": not a folder";
  }
  for (const std::string& name : demo.scene().meshNames()) {
    const std::string path = userDirectory + "/" + name;
    if (!std::filesystem::exists(path)) {
      std::fprintf(stderr, "reflect: %s not found, using the built-in %s\n", path.c_str(),
                   name.c_str());
      continue;
    }
    error = demo.loadMesh(name, path);
    if (!error.empty()) return error;
  }
  return {};
}

}  // namespace reflect
