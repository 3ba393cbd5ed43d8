// Wavefront OBJ to MeshData (core/obj_stream.h parses it, in pieces), hardened for what users
// bring: quads and polygons (triangulated), several objects, missing .mtl files, CR CR LF line
// ends, files without normals (computed), relative indices; faces that name normals or texture
// coordinates the file does not define (computed normals; texture coordinates are not used), with
// a warning; and rejected with a message naming the file: garbage, no geometry, vertex indices out
// of range, non-finite numbers, sizes past the limits.
#pragma once

#include <string>
#include <vector>

#include "core/mesh_data.h"
#include "core/result.h"

namespace reflect {

struct ObjLimits {
  size_t maxBytes = 64u << 20;       // the course's largest model is 11.5 MB
  size_t maxTriangles = 4'000'000u;  // 27x the course's mario
};

// A loaded model and what the loader let pass but the user should hear about, each message once
// per file: "NAME: faces name normals the file does not define (first on line 12); using
// computed normals".
struct LoadedMesh {
  MeshData mesh;
  std::vector<std::string> warnings;
};

// `name` is used in every message (usually the path or URL the text came from).
Result<LoadedMesh> parseObj(const std::string& text, const std::string& name,
                            const ObjLimits& limits = {});
// Reads the file in pieces of kObjReadPiece bytes, each parsed as it is read.
Result<LoadedMesh> loadObjFile(const std::string& path, const ObjLimits& limits = {});
inline constexpr size_t kObjReadPiece = 1u << 20;

}  // namespace reflect
