// libFuzzer target: parseObj (the streaming parser, core/obj_stream.h) on arbitrary bytes.
// Besides crashes and sanitizer reports, it aborts when a mesh that parseObj accepted breaks what
// the renderer relies on: whole triangles, indices in range, finite positions, unit normals,
// bounds that hold every vertex; when a rejection's message or a warning does not name the
// input; and when the same bytes fed in pieces (sizes drawn from the input itself) give another
// mesh or another message.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/obj_loader.h"
#include "core/obj_stream.h"

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
  }
  // The same bytes in pieces of 1..64 bytes (sizes from the input's own bytes) must give the
  // same outcome, byte for byte (past the size limit the two word their refusal differently).
  if (size > limits.maxBytes) return 0;
  reflect::ObjStreamParser parser(kName, limits);
  size_t at = 0;
  for (size_t k = 0; at < size; ++k) {
    const size_t n = std::min<size_t>(1 + data[k % size] % 64, size - at);
    parser.feed(std::string_view(text).substr(at, n));
    at += n;
  }
  reflect::Result<reflect::LoadedMesh> pieces = parser.finish();
  if (static_cast<bool>(pieces) != static_cast<bool>(mesh)) fail("pieces change the outcome");
  if (!mesh) {
    if (pieces.error() != mesh.error()) fail("pieces change the message");
    return 0;
  }
  const reflect::MeshData& a = mesh.value().mesh;
  const reflect::MeshData& b = pieces.value().mesh;
  if (a.indices != b.indices || a.vertices.size() != b.vertices.size())
    fail("pieces change the mesh");
  for (size_t i = 0; i < a.vertices.size(); ++i) {
    if (a.vertices[i].position != b.vertices[i].position ||
        a.vertices[i].normal != b.vertices[i].normal) {
      fail("pieces change a vertex");
    }
  }
  if (mesh.value().warnings != pieces.value().warnings) fail("pieces change the warnings");
  return 0;
}
