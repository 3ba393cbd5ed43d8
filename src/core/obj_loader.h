// Wavefront OBJ to MeshData through tinyobjloader, hardened for what users bring: quads and
// polygons (triangulated), several objects, missing .mtl files, CR CR LF line ends, files
// without normals (computed), relative indices; and rejected with a message naming the file:
// garbage, no geometry, indices out of range, non-finite numbers, sizes past the limits.
#pragma once

#include <string>

#include "core/mesh_data.h"
#include "core/result.h"

namespace reflect {

struct ObjLimits {
  size_t maxBytes = 64u << 20;       // the course's largest model is 11.5 MB
  size_t maxTriangles = 4'000'000u;  // 27x the course's mario
};

// `name` is used in every message (usually the path or URL the text came from).
Result<MeshData> parseObj(const std::string& text, const std::string& name,
                          const ObjLimits& limits = {});
Result<MeshData> loadObjFile(const std::string& path, const ObjLimits& limits = {});

}  // namespace reflect
