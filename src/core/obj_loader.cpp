#include "core/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "core/obj_validation.h"

namespace reflect {
namespace {

glm::vec3 readVec3(const std::vector<tinyobj::real_t>& data, int index) {
  const size_t i = static_cast<size_t>(index) * 3;
  return {data[i], data[i + 1], data[i + 2]};
}

// Area-weighted smooth normals per position, for corners whose file gave none (or a zero one).
std::vector<glm::vec3> smoothNormalsPerPosition(const tinyobj::attrib_t& attrib,
                                                const std::vector<tinyobj::shape_t>& shapes) {
  std::vector<glm::vec3> sums(attrib.vertices.size() / 3, glm::vec3(0.0f));
  for (const tinyobj::shape_t& shape : shapes) {
    const auto& idx = shape.mesh.indices;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
      glm::vec3 a = readVec3(attrib.vertices, idx[t].vertex_index);
      glm::vec3 b = readVec3(attrib.vertices, idx[t + 1].vertex_index);
      glm::vec3 c = readVec3(attrib.vertices, idx[t + 2].vertex_index);
      glm::vec3 areaNormal = glm::cross(b - a, c - a);  // length = 2 x area
      for (size_t k = 0; k < 3; ++k)
        sums[static_cast<size_t>(idx[t + k].vertex_index)] += areaNormal;
    }
  }
  return sums;
}

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
  float len = glm::length(v);
  return (len > 1e-20f && std::isfinite(len)) ? v / len : fallback;
}

// Names the line of the first position or normal that tinyobjloader read as inf or NaN.
std::string firstNonFiniteAttribute(const std::string& text, const tinyobj::attrib_t& attrib) {
  struct Attribute {
    const std::vector<tinyobj::real_t>& values;
    const char* keyword;
  };
  for (const Attribute& attribute :
       {Attribute{attrib.vertices, "v"}, Attribute{attrib.normals, "vn"}}) {
    for (size_t i = 0; i < attribute.values.size(); ++i) {
      if (std::isfinite(attribute.values[i])) continue;
      return lineError(lineOfAttribute(text, attribute.keyword, i / 3),
                       std::string("a number on this '") + attribute.keyword +
                           "' line reads as infinite or NaN (its exponent or digit count is out "
                           "of range)");
    }
  }
  return {};
}

}  // namespace

Result<LoadedMesh> parseObj(const std::string& text, const std::string& name,
                            const ObjLimits& limits) {
  using Out = Result<LoadedMesh>;
  Result<ObjCounts> counts = validateObjText(text, limits);
  if (!counts) return Out::failure(name + ": " + counts.error());

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // ParseFromString ignores mtllib lines: a material file that is not there cannot fail the load,
  // and the scene sets colours itself.
  if (!reader.ParseFromString(text, std::string(), config)) {
    return Out::failure(name + ": " + reader.Error());
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const std::vector<tinyobj::shape_t>& shapes = reader.GetShapes();
  // The pre-pass checked every vertex index, but as it read the text: should tinyobjloader ever
  // read an index differently, refuse rather than read out of bounds.
  const size_t positionCount = attrib.vertices.size() / 3;
  const size_t normalCount = attrib.normals.size() / 3;
  for (const tinyobj::shape_t& shape : shapes) {
    if (shape.mesh.indices.size() % 3 != 0) {
      return Out::failure(name + ": a face did not split into whole triangles");
    }
    for (const tinyobj::index_t& corner : shape.mesh.indices) {
      if (corner.vertex_index < 0 || static_cast<size_t>(corner.vertex_index) >= positionCount) {
        return Out::failure(name + ": a face refers to a vertex that does not exist");
      }
    }
  }

  // The pre-pass read every number with strtof; tinyobjloader has its own reader, which turns
  // some numbers strtof reads as finite into inf or NaN ("0e500", 400 digits then "e-400").
  if (std::string problem = firstNonFiniteAttribute(text, attrib); !problem.empty()) {
    return Out::failure(name + ": " + problem);
  }

  // A normal index the file does not define (past its last `vn`, or a negative one that reached
  // back before the first) is read as none: the corner gets a computed normal, as in other
  // loaders. Texture coordinates are not used at all.
  auto fileNormal = [&](int normalIndex) {
    return normalIndex >= 0 && static_cast<size_t>(normalIndex) < normalCount ? normalIndex : -1;
  };

  std::vector<glm::vec3> computedNormals;  // filled only if some corner needs it
  auto computedNormal = [&](int positionIndex) {
    if (computedNormals.empty()) computedNormals = smoothNormalsPerPosition(attrib, shapes);
    return normalizedOr(computedNormals[static_cast<size_t>(positionIndex)], {0.0f, 1.0f, 0.0f});
  };

  LoadedMesh loaded;
  MeshData& mesh = loaded.mesh;
  mesh.name = name;
  mesh.indices.reserve(counts.value().triangles * 3);
  // A vertex is a (position, normal) pair: the same pair in two faces is one vertex.
  std::unordered_map<uint64_t, uint32_t> vertexOfPair;
  vertexOfPair.reserve(counts.value().positions * 2);
  for (const tinyobj::shape_t& shape : shapes) {
    for (const tinyobj::index_t& corner : shape.mesh.indices) {
      const int normalIndex = fileNormal(corner.normal_index);
      const uint64_t key =
          (static_cast<uint64_t>(static_cast<uint32_t>(corner.vertex_index)) << 32) |
          static_cast<uint32_t>(normalIndex);
      auto [it, inserted] =
          vertexOfPair.try_emplace(key, static_cast<uint32_t>(mesh.vertices.size()));
      if (inserted) {
        Vertex v;
        v.position = readVec3(attrib.vertices, corner.vertex_index);
        v.normal = normalIndex >= 0
                       ? normalizedOr(readVec3(attrib.normals, normalIndex), glm::vec3(0.0f))
                       : glm::vec3(0.0f);
        if (v.normal == glm::vec3(0.0f)) v.normal = computedNormal(corner.vertex_index);
        mesh.vertices.push_back(v);
      }
      mesh.indices.push_back(it->second);
    }
  }
  if (mesh.indices.empty()) return Out::failure(name + ": no triangles after parsing");
  mesh.bounds = computeBounds(mesh.vertices);
  if (size_t line = counts.value().undefinedNormalLine; line != 0) {
    loaded.warnings.push_back(name +
                              ": faces name normals the file does not define (first on line " +
                              std::to_string(line) + "); using computed normals");
  }
  if (size_t line = counts.value().undefinedTexcoordLine; line != 0) {
    loaded.warnings.push_back(
        name + ": faces name texture coordinates the file does not define (first on line " +
        std::to_string(line) + "); ignored, as texture coordinates are not used");
  }
  return loaded;
}

Result<LoadedMesh> loadObjFile(const std::string& path, const ObjLimits& limits) {
  using Out = Result<LoadedMesh>;
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return Out::failure(path + ": cannot open file");
  const std::streamoff size = file.tellg();
  if (size < 0) return Out::failure(path + ": cannot read file");
  if (static_cast<size_t>(size) > limits.maxBytes) {
    return Out::failure(path + ": file is " + std::to_string(size) + " bytes, over the limit of " +
                        std::to_string(limits.maxBytes));
  }
  std::string text(static_cast<size_t>(size), '\0');
  file.seekg(0);
  if (!file.read(text.data(), size)) return Out::failure(path + ": cannot read file");
  return parseObj(text, path, limits);
}

}  // namespace reflect
