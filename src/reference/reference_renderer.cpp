// The frame: the scene placed at its time, one primary ray per pixel (interleaved rows on a pool
// of threads), each shaded by the tracer (reference_tracer.h) on the Embree scene
// (embree_scene.h); and the glass paths the tests follow.
#include "reference/reference_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "core/float_limits.h"
#include "core/fresnel.h"
#include "core/frustum.h"
#include "core/ggx.h"
#include "core/probe_layout.h"
#include "reference/embree_scene.h"
#include "reference/reference_tracer.h"

namespace reflect {
namespace {

uint8_t toByte(float c) {
  return static_cast<uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// Every object's probe centre (probeCentre()), at once.
std::vector<glm::vec3> probeCentres(const Scene& scene, const MeshLookup& meshes, double seconds) {
  std::vector<ProbeCandidate> candidates;
  std::vector<glm::vec3> centres;
  for (const SceneObject& o : scene.objects) {
    const MeshData* mesh = meshes(o.mesh);
    const glm::mat4 model = scene.modelMatrix(o, seconds);
    const Bounds world = transformBounds(mesh ? mesh->bounds : Bounds{}, model);
    candidates.push_back(ProbeCandidate{o.needsLiveProbe(), o.probeGroup, o.probeCentre, world});
    centres.push_back(world.centre());
  }
  for (const ProbeLayout& probe : layoutProbes(candidates)) {
    for (int member : probe.members) centres[static_cast<size_t>(member)] = probe.centre;
  }
  return centres;
}

std::string checkSkybox(const CubeFaces& faces) {
  const int n = faces[0].width;
  for (const RgbaImage& face : faces) {
    if (face.width < 1 || face.width != n || face.height != n ||
        face.pixels.size() != static_cast<size_t>(n) * static_cast<size_t>(n) * 4) {
      return "reference: the skybox faces must be six equal, non-empty RGBA squares";
    }
  }
  return {};
}

// The scene's objects in world space at one time, and which of them are reflectors and glass
// (the Embree scenes their rays need).
struct PlacedScene {
  std::vector<WorldMesh> meshes;
  std::vector<int> reflectors;
  std::vector<int> glass;
};

Result<PlacedScene> placeScene(const Scene& scene, const MeshLookup& meshes, double seconds) {
  PlacedScene placed;
  placed.meshes.resize(scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    const MeshData* mesh = meshes(object.mesh);
    if (!mesh)
      return Result<PlacedScene>::failure("reference: mesh " + object.mesh + " is not loaded");
    Result<WorldMesh> world = placeMesh(*mesh, scene.modelMatrix(object, seconds),
                                        object.material == Material::CubeTextured);
    if (!world) return Result<PlacedScene>::failure(world.error());
    placed.meshes[i] = world.take();
    // Rays leave reflectors, and probe-lit objects' diffuse rays leave them: neither meets itself.
    if (object.material != Material::Phong || object.probeLit()) {
      placed.reflectors.push_back(static_cast<int>(i));
    }
    if (object.material == Material::Glass) placed.glass.push_back(static_cast<int>(i));
  }
  return placed;
}

// "" when the arguments can make a frame, else why not.
std::string checkArguments(const Scene& scene, const CubeFaces* skybox, int width, int height) {
  if (width < 1 || height < 1) return "reference frame size must be positive";
  if (!scene.skybox.empty() && !skybox) {
    return "reference: the scene has a skybox; its faces must be given";
  }
  return skybox ? checkSkybox(*skybox) : std::string();
}

// renderRow(y) for every row y < height, on `threads` threads (<= 0: one a core).
template <typename RenderRow>
void forEachRow(int height, int threads, const RenderRow& renderRow) {
  int threadCount = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  threadCount = std::clamp(threadCount, 1, std::max(1, height));
  if (threadCount == 1) {
    for (int y = 0; y < height; ++y) renderRow(y);
    return;
  }
  // Interleaved rows balance the work (the sphere's rows cost more than the sky's).
  std::vector<std::thread> pool;
  for (int k = 0; k < threadCount; ++k) {
    pool.emplace_back([&, k] {
      for (int y = k; y < height; y += threadCount) renderRow(y);
    });
  }
  for (std::thread& t : pool) t.join();
}

// The GL camera's primary rays: clip = (P * V, multiplied in float as the renderer does) *
// world, unprojected in double from the near plane (t = 0) to the far plane (t = 1).
class PrimaryRays {
 public:
  PrimaryRays(const LookCamera& camera, int width, int height) : width_(width), height_(height) {
    const glm::mat4 viewProj =
        camera.projection(static_cast<float>(width) / static_cast<float>(height)) * camera.view();
    inverseViewProj_ = glm::inverse(glm::dmat4(viewProj));
  }
  // Pixel (x, y)'s centre: GL's window y counts from the bottom, the image's rows from the top.
  void at(int x, int y, glm::vec3& origin, glm::vec3& ray) const {
    const double ndcX = (x + 0.5) / width_ * 2.0 - 1.0;
    const double ndcY = 1.0 - (y + 0.5) / height_ * 2.0;
    const glm::dvec3 nearPoint = unproject(ndcX, ndcY, -1.0);
    const glm::dvec3 farPoint = unproject(ndcX, ndcY, 1.0);
    origin = glm::vec3(nearPoint);
    ray = glm::vec3(farPoint - nearPoint);
  }

 private:
  glm::dvec3 unproject(double ndcX, double ndcY, double ndcZ) const {
    const glm::dvec4 p = inverseViewProj_ * glm::dvec4(ndcX, ndcY, ndcZ, 1.0);
    return glm::dvec3(p) / p.w;
  }
  int width_;
  int height_;
  glm::dmat4 inverseViewProj_{1.0};
};

// Per object: the albedo of a rough mirror's lobe (empty for the others), which the tracer
// divides its few-ray estimates by.
std::vector<LobeAlbedoTable> lobeAlbedosOf(const Scene& scene) {
  std::vector<LobeAlbedoTable> albedos(scene.objects.size());
  for (size_t i = 0; i < albedos.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (o.rough()) albedos[i] = LobeAlbedoTable(ggxAlpha(o.roughness));
  }
  return albedos;
}

ReferenceFrame emptyFrame(int width, int height) {
  const size_t pixelCount = static_cast<size_t>(width) * static_cast<size_t>(height);
  ReferenceFrame frame;
  frame.image.width = width;
  frame.image.height = height;
  frame.image.pixels.assign(pixelCount * 4, 255);
  frame.objectIds.assign(pixelCount, -1);
  frame.reflectorMask.assign(pixelCount, 0);
  return frame;
}

// Pixel p's primary ray shaded into `frame` (its colour, object and reflector mask) and, for a
// reflector, its directions.
void shadePixel(const Tracer& tracer, const PrimaryRays& rays, int x, int y, size_t p,
                ReferenceFrame& frame, Directions& directions) {
  glm::vec3 origin, ray;
  rays.at(x, y, origin, ray);
  const Hit hit = trace(tracer.world.all(), tracer.meshes, origin, ray, 0.0f, 1.0f);
  glm::vec3 colour = tracer.background(ray);
  frame.objectIds[p] = hit.object;
  if (hit.object >= 0) {
    const glm::vec3 toViewer = glm::normalize(tracer.eye - hit.position);
    const bool reflector =
        tracer.scene.objects[static_cast<size_t>(hit.object)].material != Material::Phong;
    frame.reflectorMask[p] = reflector ? 1 : 0;
    colour = tracer.shade(hit, toViewer, Path{}, reflector ? &directions : nullptr);
  }
  uint8_t* out = &frame.image.pixels[p * 4];
  out[0] = toByte(colour.r);
  out[1] = toByte(colour.g);
  out[2] = toByte(colour.b);
  out[3] = 255;
}

}  // namespace

glm::vec3 probeCentre(const Scene& scene, const MeshLookup& meshes, double seconds, int object) {
  return probeCentres(scene, meshes, seconds).at(static_cast<size_t>(object));
}

Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const CubeFaces* skybox, const LookCamera& camera,
                                       double seconds, int width, int height, int threads) {
  ReferenceOptions options;
  options.threads = threads;
  return renderReference(scene, meshes, skybox, camera, seconds, width, height, options);
}

Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const CubeFaces* skybox, const LookCamera& camera,
                                       double seconds, int width, int height,
                                       const ReferenceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string error = checkArguments(scene, skybox, width, height);
  if (!error.empty()) return Result<ReferenceFrame>::failure(error);
  Result<PlacedScene> placed = placeScene(scene, meshes, seconds);
  if (!placed) return Result<ReferenceFrame>::failure(placed.error());
  const PlacedScene& world = placed.value();
  const std::vector<glm::vec3> centres = probeCentres(scene, meshes, seconds);
  EmbreeWorld embree;
  error = embree.build(world.meshes, world.reflectors, world.glass);
  if (!error.empty()) return Result<ReferenceFrame>::failure(error);

  ReferenceFrame frame = emptyFrame(width, height);
  std::vector<Directions> directions(frame.objectIds.size());
  const Tracer tracer{scene,
                      world.meshes,
                      embree,
                      skybox,
                      centres,
                      camera.eye(),
                      options.lobeSamples,
                      options.seed,
                      lobeAlbedosOf(scene),
                      options.diffuseSamples};
  const PrimaryRays rays(camera, width, height);
  forEachRow(height, options.threads, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      shadePixel(tracer, rays, x, y, p, frame, directions[p]);
    }
  });
  error = embree.error();
  if (!error.empty()) return Result<ReferenceFrame>::failure(error);

  for (size_t p = 0; p < directions.size(); ++p) {
    if (!frame.reflectorMask[p]) continue;
    frame.lookupDirs.push_back(directions[p].lookup);
    frame.trueDirs.push_back(directions[p].truth);
  }
  frame.renderMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  frame.options = options;
  return frame;
}

Result<std::vector<GlassPath>> traceGlass(const MeshData& mesh, const glm::mat4& model, float ior,
                                          const std::vector<GlassRay>& rays) {
  Result<WorldMesh> placed = placeMesh(mesh, model, false);
  if (!placed) return Result<std::vector<GlassPath>>::failure(placed.error());
  std::vector<WorldMesh> meshes;
  meshes.push_back(placed.take());
  EmbreeWorld embree;
  std::string error = embree.build(meshes, {0}, {0});
  if (!error.empty()) return Result<std::vector<GlassPath>>::failure(error);

  const float n = clampedIor(ior);
  std::vector<GlassPath> paths;
  for (const GlassRay& ray : rays) {
    GlassPath& path = paths.emplace_back();
    const glm::vec3 i = glm::normalize(ray.direction);
    const Hit hit = trace(embree.all(), meshes, ray.origin, i, 0.0f, kInfinity);
    if (hit.object < 0) continue;
    path.entry = hit.position;
    path.entryNormal = hit.normal;
    const glm::vec3 t = glm::refract(i, hit.normal, 1.0f / n);
    if (glm::dot(t, t) == 0.0f) continue;
    path.entered = true;
    path.inside = glm::normalize(t);
    const Crossing c = crossGlass(embree.only(0), meshes, 0, n, hit.position, path.inside);
    path.exited = c.exited;
    path.exit = c.point;
    path.direction = c.direction;
    path.internalReflections = c.internalReflections;
  }
  error = embree.error();
  if (!error.empty()) return Result<std::vector<GlassPath>>::failure(error);
  return paths;
}

}  // namespace reflect
