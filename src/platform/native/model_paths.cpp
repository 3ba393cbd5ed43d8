#include "platform/native/model_paths.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>
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

std::vector<std::string> shippedSceneNames() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry :
       std::filesystem::directory_iterator(builtInAssetDirectory() + "/scenes", error)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  auto byDefault = std::find(names.begin(), names.end(), "ex12-2");
  if (byDefault != names.end()) std::rotate(names.begin(), byDefault, byDefault + 1);
  return names;
}

namespace {

std::string shippedScenePath(const std::string& name) {
  return builtInAssetDirectory() + "/scenes/" + name + ".json";
}

bool isShippedScene(const std::string& name) {
  const std::vector<std::string> names = shippedSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string checkSceneName(const std::string& nameOrPath) {
  std::error_code error;
  if (isShippedScene(nameOrPath) || std::filesystem::is_regular_file(nameOrPath, error)) return {};
  std::string shipped;
  for (const std::string& name : shippedSceneNames())
    shipped += (shipped.empty() ? "" : ", ") + name;
  return nameOrPath + ": no such scene (shipped: " + shipped + ") and no such .json file";
}

Result<Scene> loadNamedScene(const std::string& nameOrPath) {
  if (isShippedScene(nameOrPath)) return loadSceneFile(shippedScenePath(nameOrPath));
  std::string problem = checkSceneName(nameOrPath);
  if (!problem.empty()) return Result<Scene>::failure(problem);
  return loadSceneFile(nameOrPath);
}

std::string loadSceneModels(Demo& demo, const std::string& userDirectory,
                            std::vector<std::string>* warnings) {
  auto keepWarnings = [&] {
    if (warnings) {
      warnings->insert(warnings->end(), demo.lastWarnings().begin(), demo.lastWarnings().end());
    }
  };
  if (!userDirectory.empty() && !std::filesystem::is_directory(userDirectory)) {
    return userDirectory + ": not a folder";
  }
  // The user's file where there is one (a built-in model it would replace is not parsed at all),
  // the built-in one elsewhere.
  for (const std::string& name : demo.scene().meshNames()) {
    std::string path = builtInModelDirectory() + "/" + name;
    if (!userDirectory.empty()) {
      const std::string user = userDirectory + "/" + name;
      if (std::filesystem::exists(user)) {
        path = user;
      } else {
        const std::string notice = user + " not found, using the built-in " + name;
        if (warnings) {
          warnings->push_back(notice);  // the caller prints each once
        } else {
          std::fprintf(stderr, "reflect: %s\n", notice.c_str());
        }
      }
    }
    const std::string error = demo.loadMesh(name, path);
    if (!error.empty()) return error;
    keepWarnings();
  }
  return loadSkybox(demo);
}

}  // namespace reflect
