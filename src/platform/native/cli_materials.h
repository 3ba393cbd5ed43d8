// `--material INDEX:NAME=VALUE[,NAME=VALUE...]`: a scene object's material settings changed from
// the command line, as the page's `mat` link key changes them (names from the settings schema:
// type, reflection, base, ior, fresnel, roughness, environment).
#pragma once

#include <string>
#include <vector>

#include "core/scene.h"

namespace reflect {

// Applies each entry to `scene`; "" when all apply, else the first problem, naming the entry.
std::string applyMaterialOptions(const std::vector<std::string>& entries, Scene& scene);

}  // namespace reflect
