// The material and environment names of scene files, the page and the CLI (settings_schema.h).
#include <string>

#include "core/settings_schema.h"

namespace reflect {

const char* materialName(Material material) {
  switch (material) {
    case Material::Phong:
      return "phong";
    case Material::Mirror:
      return "mirror";
    case Material::Glass:
      return "glass";
    case Material::CubeTextured:
      return "cube-textured";
  }
  return "?";
}

bool parseMaterial(const std::string& name, Material* material) {
  for (Material m : {Material::Phong, Material::Mirror, Material::Glass, Material::CubeTextured}) {
    if (name == materialName(m)) {
      *material = m;
      return true;
    }
  }
  return false;
}

const char* environmentName(Environment environment) {
  return environment == Environment::Skybox ? "skybox" : "live";
}

bool parseEnvironment(const std::string& name, Environment* environment) {
  for (Environment e : {Environment::LiveProbe, Environment::Skybox}) {
    if (name == environmentName(e)) {
      *environment = e;
      return true;
    }
  }
  return false;
}

}  // namespace reflect
