#include "platform/native/model_paths.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/scene_file.h"
#include "core/skybox_faces.h"

namespace reflect {
namespace {

std::string loadSkybox(Demo& demo) {
  const SkyboxSource& source = demo.scene().skybox;
  if (source.empty()) return {};
  const std::string root = builtInAssetDirectory() + "/";
  Result<CubeFaces> faces = Result<CubeFaces>::failure("");
  if (!source.cross.empty()) {
    Result<RgbaImage> cross = readPng(root + source.cross);
    if (!cross) return cross.error();
    faces = facesFromCross(cross.value(), root + source.cross);
  } else {
    std::vector<RgbaImage> images;
    std::array<std::string, 6> names;
    for (size_t i = 0; i < 6; ++i) {
      names[i] = root + source.faces[i];
      Result<RgbaImage> image = readPng(names[i]);
      if (!image) return image.error();
      images.push_back(image.take());
    }
    faces = facesFromImages(std::move(images), names);
  }
  if (!faces) return faces.error();
  return demo.setSkybox(faces.take());
}

}  // namespace

std::string builtInAssetDirectory() {
  return REFLECT_ASSET_DIR;
}
std::string builtInModelDirectory() {
  return builtInAssetDirectory() + "/models";
}

Result<Scene> loadNamedScene(const std::string& nameOrPath) {
  const bool isPath =
      nameOrPath.find('/') != std::string::npos || nameOrPath.find(".json") != std::string::npos;
  return loadSceneFile(isPath ? nameOrPath
                              : builtInAssetDirectory() + "/scenes/" + nameOrPath + ".json");
}

std::string loadSceneModels(Demo& demo, const std::string& userDirectory) {
  std::string error = demo.loadMeshesFrom(builtInModelDirectory());
  if (!error.empty()) return error;
  if (!userDirectory.empty()) {
    if (!std::filesystem::is_directory(userDirectory)) return userDirectory + ": not a folder";
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
  }
  return loadSkybox(demo);
}

}  // namespace reflect
