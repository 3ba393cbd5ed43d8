#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "core/mesh_closure.h"
#include "core/obj_loader.h"

namespace reflect {
namespace {

const std::string kModels = std::string(MODEL_DIR) + "/";

// A unit cube as an OBJ exporter writes it: four vertices of its own a face (each face's normal),
// so positions repeat across faces and only welding them closes it.
MeshData splitCube() {
  MeshData mesh;
  const glm::vec3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    // Two axes across the face with u x v = n, so the corners run counter-clockwise from outside.
    const glm::vec3 u = glm::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 v = glm::cross(n, u);
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    for (const auto& [s, t] :
         {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}}) {
      mesh.vertices.push_back({n + static_cast<float>(s) * u + static_cast<float>(t) * v, n});
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  }
  mesh.bounds = computeBounds(mesh.vertices);
  return mesh;
}

TEST(MeshClosure, ASolidWithSplitSeamsIsClosedOutward) {
  EXPECT_TRUE(isClosedOutward(splitCube()));
}

TEST(MeshClosure, AMissingTriangleOpensIt) {
  MeshData cube = splitCube();
  cube.indices.resize(cube.indices.size() - 3);
  EXPECT_FALSE(isClosedOutward(cube));
}

TEST(MeshClosure, OneFlippedTriangleIsNotConsistentlyWound) {
  MeshData cube = splitCube();
  std::swap(cube.indices[1], cube.indices[2]);
  EXPECT_FALSE(isClosedOutward(cube));
}

TEST(MeshClosure, AnInsideOutSolidIsNotOutward) {
  MeshData cube = splitCube();
  for (size_t i = 0; i < cube.indices.size(); i += 3)
    std::swap(cube.indices[i + 1], cube.indices[i + 2]);
  EXPECT_FALSE(isClosedOutward(cube));
}

TEST(MeshClosure, ATriangleMetTwiceTheSameWayIsNotASolid) {
  MeshData cube = splitCube();
  for (int i = 0; i < 3; ++i) cube.indices.push_back(cube.indices[static_cast<size_t>(i)]);
  EXPECT_FALSE(isClosedOutward(cube));
}

TEST(MeshClosure, TrianglesThatRepeatAPositionCoverNothingAndAreLeftOut) {
  MeshData cube = splitCube();
  cube.indices.insert(cube.indices.end(), {0u, 0u, 1u, 4u, 4u, 4u});
  EXPECT_TRUE(isClosedOutward(cube));
}

TEST(MeshClosure, EmptyOrBrokenIndicesAreNotClosed) {
  EXPECT_FALSE(isClosedOutward(MeshData{}));
  MeshData cube = splitCube();
  cube.indices[5] = 1000;  // past the vertices
  EXPECT_FALSE(isClosedOutward(cube));
}

TEST(MeshClosure, TheShippedModels) {
  auto load = [](const std::string& name) {
    Result<LoadedMesh> r = loadObjFile(kModels + name);
    EXPECT_TRUE(r.ok()) << name;
    return r.ok() ? r.value().mesh : MeshData{};
  };
  EXPECT_TRUE(isClosedOutward(load("sphere.obj")));
  EXPECT_TRUE(isClosedOutward(load("cube.obj")));
  EXPECT_TRUE(isClosedOutward(load("sonic.obj")));
  EXPECT_FALSE(isClosedOutward(load("mario.obj")));  // 148 edges of holes
  EXPECT_FALSE(isClosedOutward(load("quad.obj")));   // a ground seen from both sides
}

}  // namespace
}  // namespace reflect
