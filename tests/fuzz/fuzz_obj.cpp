// libFuzzer target: parseObj (the validating pre-pass, then tinyobjloader) on arbitrary bytes.
// Besides crashes and sanitizer reports, it aborts when a mesh that parseObj accepted breaks what
// the renderer relies on: whole triangles, indices in range, finite positions, unit normals,
// bounds that hold every vertex; and when a rejection's message or a warning does not name the
// input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/obj_loader.h"

namespace {

constexpr const char* kName = "fuzz.obj";

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_obj: invariant broken: %s\n", what);
  std::abort();
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void checkMesh(const reflect::MeshData& mesh) {
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) fail("indices are not whole triangles");
  if (mesh.vertices.empty()) fail("triangles without vertices");
  for (uint32_t index : mesh.indices) {
    if (index >= mesh.vertices.size()) fail("index out of range");
  }
  for (const reflect::Vertex& v : mesh.vertices) {
    if (!finite(v.position)) fail("non-finite position");
    if (!finite(v.normal)) fail("non-finite normal");
    if (std::fabs(glm::length(v.normal) - 1.0f) > 1e-3f) fail("normal is not unit length");
    if (glm::any(glm::lessThan(v.position, mesh.bounds.min)) ||
        glm::any(glm::greaterThan(v.position, mesh.bounds.max))) {
      fail("vertex outside the bounds");
    }
  }
  if (mesh.name != kName) fail("mesh not named after its source");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // Small limits: the validator's limits themselves are under test, and inputs stay fast.
  reflect::ObjLimits limits;
  limits.maxBytes = 256u << 10;
  limits.maxTriangles = 20'000u;
  const std::string text(reinterpret_cast<const char*>(data), size);
  reflect::Result<reflect::LoadedMesh> mesh = reflect::parseObj(text, kName, limits);
  if (mesh) {
    checkMesh(mesh.value().mesh);
    // At most one warning for undefined normals and one for texture coordinates, not one a face.
    if (mesh.value().warnings.size() > 2) fail("more than one warning per problem");
    for (const std::string& warning : mesh.value().warnings) {
      if (warning.rfind(std::string(kName) + ": ", 0) != 0) {
        fail("warning does not start with the input's name");
      }
    }
  } else if (mesh.error().rfind(std::string(kName) + ": ", 0) != 0) {
    fail("error message does not start with the input's name");
  } else if (mesh.error().find("refers to a vertex that does not exist") != std::string::npos) {
    // parseObj's last guard caught what the validating pre-pass let through: the two read the
    // text differently, so the user gets a message without a line number. Find those.
    fail("the pre-pass accepted indices tinyobjloader reads out of range");
  }
  return 0;
}
