// The material and environment names of scene files, the page and the CLI (settings_schema.h).
#include <string>

#include "core/enum_names.h"
#include "core/settings_schema.h"

namespace reflect {

namespace {

constexpr EnumName<Material> kMaterialNames[] = {{Material::Phong, "phong"},
                                                 {Material::Mirror, "mirror"},
                                                 {Material::Glass, "glass"},
                                                 {Material::CubeTextured, "cube-textured"}};
constexpr EnumName<Environment> kEnvironmentNames[] = {{Environment::LiveProbe, "live"},
                                                       {Environment::Skybox, "skybox"}};

}  // namespace

const char* materialName(Material material) {
  return nameIn(kMaterialNames, material);
}

bool parseMaterial(const std::string& name, Material* material) {
  return parseIn(kMaterialNames, name, material);
}

const char* environmentName(Environment environment) {
  return nameIn(kEnvironmentNames, environment);
}

bool parseEnvironment(const std::string& name, Environment* environment) {
  return parseIn(kEnvironmentNames, name, environment);
}

}  // namespace reflect
