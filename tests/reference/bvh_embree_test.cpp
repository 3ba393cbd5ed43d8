// The exact mode's BVH (core/bvh.h: a tree per mesh, a top level over the placed objects) against
// Embree: the same first hit (object and triangle, or nothing) for at least 99.99% of a frame's
// rays, the camera's rays through every pixel and the mirror's reflected rays, on the default
// scene and with a 151k-triangle figure in mario's place.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "core/bvh.h"
#include "core/obj_loader.h"
#include "core/scene.h"
#include "reference/ray_query.h"

namespace reflect {
namespace {

constexpr int kSize = 400;
constexpr double kTime = 2.0;

// A bumpy sphere of 2 * slices * (stacks - 1) triangles filling `bounds`.
MeshData bumpyFigure(const Bounds& bounds, int slices, int stacks) {
  MeshData m;
  m.name = "bumpy figure";
  const glm::vec3 centre = bounds.centre(), half = (bounds.max - bounds.min) * 0.5f;
  for (int i = 0; i <= stacks; ++i) {
    const float theta = 3.14159265f * static_cast<float>(i) / static_cast<float>(stacks);
    for (int j = 0; j < slices; ++j) {
      const float phi = 6.2831853f * static_cast<float>(j) / static_cast<float>(slices);
      const glm::vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta),
                          std::sin(theta) * std::sin(phi));
      const float r = 0.85f + 0.15f * std::sin(7.0f * theta) * std::cos(5.0f * phi);
      m.vertices.push_back({centre + half * dir * r, dir});
    }
  }
  const auto at = [&](int i, int j) { return static_cast<uint32_t>(i * slices + (j % slices)); };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      if (i > 0) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + 1 < stacks) {
        m.indices.insert(m.indices.end(), {at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
      }
    }
  }
  m.bounds = computeBounds(m.vertices);
  return m;
}

// The camera's rays through the pixel centres of a kSize x kSize frame, from the near plane.
std::vector<QueryRay> cameraRays(const Scene& scene) {
  const LookCamera camera(scene.camera);
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(camera.projection(1.0f) * camera.view()));
  std::vector<QueryRay> rays;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double nx = (x + 0.5) / kSize * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / kSize * 2.0;
      const glm::dvec4 n = inverse * glm::dvec4(nx, ny, -1.0, 1.0);
      const glm::dvec4 f = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::vec3 origin(glm::dvec3(n) / n.w);
      rays.push_back({origin, glm::normalize(glm::vec3(glm::dvec3(f) / f.w) - origin), 0.0f});
    }
  }
  return rays;
}

// Compares Embree's first hits with the BVH's for the frame's rays; returns the share that agree.
double agreement(const Scene& scene, const std::map<std::string, MeshData>& meshes,
                 size_t* rayCount) {
  const MeshLookup lookup = [&](const std::string& name) -> const MeshData* {
    auto it = meshes.find(name);
    return it == meshes.end() ? nullptr : &it->second;
  };
  std::map<std::string, std::shared_ptr<const MeshBvh>> trees;
  for (const auto& [name, mesh] : meshes) {
    const auto start = std::chrono::steady_clock::now();
    trees[name] =
        std::make_shared<const MeshBvh>(buildMeshBvh(std::make_shared<const MeshData>(mesh)));
    std::printf("%s: %zu triangles, BVH of %zu nodes, depth %d, built in %.1f ms\n", name.c_str(),
                mesh.triangleCount(), trees[name]->tree.nodes.size(), trees[name]->tree.depth,
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
  }
  std::vector<BvhInstance> instances;
  for (const SceneObject& o : scene.objects) {
    BvhInstance instance;
    instance.mesh = trees.at(o.mesh);
    instance.model = scene.modelMatrix(o, kTime);
    instance.inverse = glm::inverse(instance.model);
    instances.push_back(instance);
  }
  const SceneBvh bvh = buildSceneBvh(instances);

  std::vector<QueryRay> rays = cameraRays(scene);
  auto primary = embreeFirstHits(scene, lookup, kTime, rays);
  EXPECT_TRUE(primary) << primary.error();
  if (!primary) return 0.0;
  // The reflected rays of every pixel that met a mirror (Embree's hit, its geometric normal).
  const size_t cameraRays = rays.size();
  for (size_t i = 0; i < cameraRays; ++i) {
    const QueryHit& h = primary.value()[i];
    if (h.object < 0 || scene.objects[static_cast<size_t>(h.object)].material == Material::Phong) {
      continue;
    }
    const MeshData& mesh = meshes.at(scene.objects[static_cast<size_t>(h.object)].mesh);
    const glm::mat4 model = scene.modelMatrix(scene.objects[static_cast<size_t>(h.object)], kTime);
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = glm::vec3(model *
                       glm::vec4(mesh.vertices[mesh.indices[static_cast<size_t>(h.triangle) * 3 +
                                                            static_cast<size_t>(k)]]
                                     .position,
                                 1.0f));
    }
    const glm::vec3 normal = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    const glm::vec3 at = rays[i].origin + h.t * rays[i].direction;
    rays.push_back({at, glm::reflect(rays[i].direction, normal), 1e-4f});
  }
  auto hits = embreeFirstHits(scene, lookup, kTime, rays);
  EXPECT_TRUE(hits) << hits.error();
  if (!hits) return 0.0;
  size_t same = 0, reflected = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const RayHit mine = intersectScene(bvh, rays[i].origin, rays[i].direction, rays[i].tNear);
    const QueryHit& theirs = hits.value()[i];
    const bool agree =
        mine.instance == theirs.object && (mine.instance < 0 || mine.triangle == theirs.triangle);
    same += agree ? 1 : 0;
    if (i >= cameraRays && theirs.object >= 0) ++reflected;
    if (!agree && i - same < 5) {
      std::printf("differs: ray %zu: BVH object %d triangle %d t %.6g, Embree %d %d t %.6g\n", i,
                  mine.instance, mine.triangle, mine.t, theirs.object, theirs.triangle, theirs.t);
    }
  }
  *rayCount = rays.size();
  std::printf(
      "%zu rays (%zu from the camera, %zu reflected of which %zu meet something): %zu "
      "differ\n",
      rays.size(), cameraRays, rays.size() - cameraRays, reflected, rays.size() - same);
  return static_cast<double>(same) / static_cast<double>(rays.size());
}

std::map<std::string, MeshData> shippedMeshes(const Scene& scene) {
  std::map<std::string, MeshData> meshes;
  for (const std::string& name : scene.meshNames()) {
    auto loaded = loadObjFile(std::string(MODEL_DIR) + "/" + name);
    EXPECT_TRUE(loaded) << loaded.error();
    if (loaded) meshes[name] = loaded.take().mesh;
  }
  return meshes;
}

TEST(BvhAgainstEmbree, DefaultSceneSameFirstHits) {
  const Scene scene = makeDynamicReflectionScene();
  size_t rays = 0;
  const double share = agreement(scene, shippedMeshes(scene), &rays);
  EXPECT_GT(rays, static_cast<size_t>(kSize * kSize));
  EXPECT_GE(share, 0.9999);
}

TEST(BvhAgainstEmbree, HeavyFigureSameFirstHits) {
  const Scene scene = makeDynamicReflectionScene();
  std::map<std::string, MeshData> meshes = shippedMeshes(scene);
  ASSERT_TRUE(meshes.count("mario.obj"));
  meshes["mario.obj"] = bumpyFigure(meshes["mario.obj"].bounds, 400, 190);
  ASSERT_GE(meshes["mario.obj"].triangleCount(), 150000u);
  size_t rays = 0;
  const double share = agreement(scene, meshes, &rays);
  EXPECT_GE(share, 0.9999);
}

}  // namespace
}  // namespace reflect
