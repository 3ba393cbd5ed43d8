// The reference's scene in Embree: the objects' meshes placed in world space as mesh.vert places
// them, an RAII owner of the device and the scenes the reference's rays are traced in, and the
// first hit along a ray, interpolated as the rasteriser interpolates.
#pragma once

#include <embree3/rtcore.h>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh_data.h"
#include "core/result.h"

namespace reflect {

// Object-space mesh moved to world space as mesh.vert does (in float, like the GPU).
struct WorldMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;          // normalMatrixOf(model3x3) * normal, not normalised
  std::vector<glm::vec3> objectPositions;  // mesh.vert's v_objectPosition (cube-textured only)
  const std::vector<uint32_t>* indices = nullptr;
  // How far a ray that starts on this mesh and goes into it skips before it may meet the mesh
  // again: 1e-5 of the mesh's world size (float rounding of the start point is ~1e-7 of it).
  float selfEpsilon = 1e-6f;
};

// The world mesh of `mesh` placed by `model`, or a message.
Result<WorldMesh> placeMesh(const MeshData& mesh, const glm::mat4& model, bool objectPositions);

// Embree's errors, collected by the device callback.
struct EmbreeErrors {
  std::mutex mutex;
  std::string first;
};

// Owns the device and its scenes: all() holds every object; for each reflector r (mirror, glass,
// cube-textured), excluding(r) holds every object but r (what r's rays may meet); for each glass
// object g, only(g) holds g alone (where a ray inside g leaves it). Released on destruction.
class EmbreeWorld {
 public:
  EmbreeWorld() = default;
  EmbreeWorld(const EmbreeWorld&) = delete;
  EmbreeWorld& operator=(const EmbreeWorld&) = delete;
  ~EmbreeWorld();

  // Builds the scenes; returns "" or Embree's first error.
  std::string build(const std::vector<WorldMesh>& meshes, const std::vector<int>& reflectors,
                    const std::vector<int>& glass);
  // Embree's first error so far, or "".
  std::string error();

  RTCScene all() const { return all_; }
  RTCScene excluding(int object) const;
  RTCScene only(int object) const;

 private:
  template <typename Keep>
  RTCScene newScene(const std::vector<WorldMesh>& meshes, Keep keep);

  RTCDevice device_ = nullptr;
  EmbreeErrors errors_;
  RTCScene all_ = nullptr;
  std::map<int, RTCScene> excluding_;
  std::map<int, RTCScene> only_;
  std::vector<RTCScene> scenes_;
};

struct Hit {
  int object = -1;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};          // interpolated and normalised
  glm::vec3 objectPosition{0.0f};  // interpolated (cube-textured meshes only)
};

// The first surface along org + t dir for t in [tnear, tfar].
Hit trace(RTCScene scene, const std::vector<WorldMesh>& meshes, const glm::vec3& org,
          const glm::vec3& dir, float tnear, float tfar);

}  // namespace reflect
