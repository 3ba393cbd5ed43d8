#include "reference/reference_renderer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>

#include "core/cube_sampling.h"
#include "core/frustum.h"
#include "core/normal_matrix.h"
#include "core/probe_layout.h"

namespace reflect {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

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
Result<WorldMesh> placeMesh(const MeshData& mesh, const glm::mat4& model, bool objectPositions) {
  for (uint32_t index : mesh.indices) {
    if (index >= mesh.vertices.size()) {
      return Result<WorldMesh>::failure("reference: mesh " + mesh.name +
                                        " has an index out of range");
    }
  }
  const glm::mat3 normalMatrix = normalMatrixOf(glm::mat3(model));
  WorldMesh w;
  w.indices = &mesh.indices;
  w.positions.reserve(mesh.vertices.size());
  w.normals.reserve(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) {
    w.positions.push_back(glm::vec3(model * glm::vec4(v.position, 1.0f)));
    w.normals.push_back(normalMatrix * v.normal);
    if (objectPositions) w.objectPositions.push_back(v.position);
  }
  const Bounds world = transformBounds(mesh.bounds, model);
  w.selfEpsilon = std::max(1e-5f * glm::length(world.max - world.min), 1e-7f);
  return w;
}

// Embree's errors, collected by the device callback.
struct ErrorLog {
  std::mutex mutex;
  std::string first;
};

void onEmbreeError(void* user, RTCError code, const char* message) {
  auto* log = static_cast<ErrorLog*>(user);
  std::lock_guard<std::mutex> lock(log->mutex);
  if (log->first.empty()) {
    log->first = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                 (message ? message : "(no message)");
  }
}

// Owns the device and its scenes: all() holds every object; for each reflector r (mirror, glass,
// cube-textured), excluding(r) holds every object but r (what r's rays may meet); for each glass
// object g, only(g) holds g alone (where a ray inside g leaves it).
class EmbreeWorld {
 public:
  EmbreeWorld() = default;
  EmbreeWorld(const EmbreeWorld&) = delete;
  EmbreeWorld& operator=(const EmbreeWorld&) = delete;
  ~EmbreeWorld() {
    for (RTCScene s : scenes_) rtcReleaseScene(s);
    if (device_) rtcReleaseDevice(device_);
  }

  std::string build(const std::vector<WorldMesh>& meshes, const std::vector<int>& reflectors,
                    const std::vector<int>& glass) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) return "Embree: rtcNewDevice failed";
    rtcSetDeviceErrorFunction(device_, onEmbreeError, &errors_);
    all_ = newScene(meshes, [](int) { return true; });
    for (int r : reflectors) excluding_[r] = newScene(meshes, [r](int i) { return i != r; });
    for (int g : glass) only_[g] = newScene(meshes, [g](int i) { return i == g; });
    return error();
  }

  std::string error() {
    std::lock_guard<std::mutex> lock(errors_.mutex);
    return errors_.first;
  }

  RTCScene all() const { return all_; }
  RTCScene excluding(int object) const {
    auto it = excluding_.find(object);
    return it == excluding_.end() ? all_ : it->second;
  }
  RTCScene only(int object) const {
    auto it = only_.find(object);
    return it == only_.end() ? nullptr : it->second;
  }

 private:
  template <typename Keep>
  RTCScene newScene(const std::vector<WorldMesh>& meshes, Keep keep) {
    RTCScene scene = rtcNewScene(device_);
    scenes_.push_back(scene);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    for (size_t i = 0; i < meshes.size(); ++i) {
      if (!keep(static_cast<int>(i))) continue;
      const WorldMesh& m = meshes[i];
      const size_t triangles = m.indices->size() / 3;
      if (triangles == 0) continue;
      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      // New (Embree-owned, padded) buffers rather than shared ones: Embree may read past the
      // last vertex with 16-byte loads.
      auto* vertices = static_cast<float*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                  sizeof(float) * 3, m.positions.size()));
      auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(uint32_t) * 3, triangles));
      if (vertices && indices) {
        for (size_t v = 0; v < m.positions.size(); ++v) {
          vertices[v * 3 + 0] = m.positions[v].x;
          vertices[v * 3 + 1] = m.positions[v].y;
          vertices[v * 3 + 2] = m.positions[v].z;
        }
        std::copy(m.indices->begin(),
                  m.indices->begin() + static_cast<std::ptrdiff_t>(triangles * 3), indices);
      }
      rtcCommitGeometry(geometry);
      rtcAttachGeometryByID(scene, geometry, static_cast<unsigned>(i));
      rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene);
    return scene;
  }

  RTCDevice device_ = nullptr;
  ErrorLog errors_;
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
          const glm::vec3& dir, float tnear, float tfar) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = org.x;
  rh.ray.org_y = org.y;
  rh.ray.org_z = org.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.time = 0.0f;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.object = static_cast<int>(rh.hit.geomID);
  const WorldMesh& m = meshes[rh.hit.geomID];
  const uint32_t* tri = m.indices->data() + static_cast<size_t>(rh.hit.primID) * 3;
  // Embree's barycentrics: p = (1 - u - v) p0 + u p1 + v p2, what the rasteriser interpolates.
  const float u = rh.hit.u;
  const float v = rh.hit.v;
  const float w = 1.0f - u - v;
  hit.position = w * m.positions[tri[0]] + u * m.positions[tri[1]] + v * m.positions[tri[2]];
  hit.normal =
      glm::normalize(w * m.normals[tri[0]] + u * m.normals[tri[1]] + v * m.normals[tri[2]]);
  if (!m.objectPositions.empty()) {
    hit.objectPosition = w * m.objectPositions[tri[0]] + u * m.objectPositions[tri[1]] +
                         v * m.objectPositions[tri[2]];
  }
  return hit;
}

// How a ray refracted into a glass object crosses it: where it leaves and along what.
struct Crossing {
  glm::vec3 point{0.0f};      // the last surface point
  glm::vec3 direction{0.0f};  // the ray that goes on from it
  int internalReflections = 0;
  bool exited = false;  // refracted out (false: still inside after the limit, or no far surface)
};

// From `entry` (on glass object `object`, of index n) along the refracted direction `inside`:
// the far surface, refract(D, N_in, n) out of it, or on total internal reflection reflect(D, N_in)
// and on, kMaxInternalReflections times at most. N_in is the surface's interpolated normal
// turned to face the ray (the inward normal at an exit).
Crossing crossGlass(RTCScene only, const std::vector<WorldMesh>& meshes, int object, float n,
                    const glm::vec3& entry, const glm::vec3& inside) {
  const float epsilon = meshes[static_cast<size_t>(object)].selfEpsilon;
  Crossing c;
  c.point = entry;
  c.direction = inside;
  for (;;) {
    const Hit far = trace(only, meshes, c.point, c.direction, epsilon, kInfinity);
    if (far.object < 0) return c;  // no far surface (a ray along a silhouette): on from here
    const glm::vec3 facing = glm::dot(c.direction, far.normal) > 0.0f ? -far.normal : far.normal;
    const glm::vec3 out = glm::refract(c.direction, facing, n);
    c.point = far.position;
    if (glm::dot(out, out) > 0.0f) {
      c.direction = glm::normalize(out);
      c.exited = true;
      return c;
    }
    c.direction = glm::reflect(c.direction, facing);
    if (++c.internalReflections == kMaxInternalReflections) return c;
  }
}

// shaders/phong.frag, unclamped.
glm::vec3 phong(const Scene& scene, const glm::vec3& colour, const Hit& hit,
                const glm::vec3& viewPosition) {
  const PhongLight& light = scene.light;
  const glm::vec3 n = hit.normal;
  const glm::vec3 l = glm::normalize(light.position - hit.position);
  const glm::vec3 v = glm::normalize(viewPosition - hit.position);
  const float nDotL = std::max(glm::dot(n, l), 0.0f);
  glm::vec3 result = colour * (light.ambient + light.diffuse * nDotL);
  if (nDotL > 0.0f) {
    const glm::vec3 r = glm::reflect(-l, n);
    result += glm::vec3(light.specular *
                        std::pow(std::clamp(glm::dot(r, v), 0.0f, 1.0f), light.shininess));
  }
  return result;
}

glm::vec3 saturate(const glm::vec3& c) {
  return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

// environment.frag's Schlick term: F0 + (1 - F0) (1 - clamp(V.N, 0, 1))^5, F0 from the index.
float schlick(float ior, const glm::vec3& toViewer, const glm::vec3& normal) {
  const float n = std::max(ior, 1e-3f);
  const float f0 = ((n - 1.0f) / (n + 1.0f)) * ((n - 1.0f) / (n + 1.0f));
  const float cosine = std::clamp(glm::dot(toViewer, normal), 0.0f, 1.0f);
  return f0 + (1.0f - f0) * std::pow(1.0f - cosine, 5.0f);
}

// A reflector pixel's plain lookup direction and the true one (see ReferenceFrame).
struct Directions {
  glm::vec3 lookup{0.0f};
  glm::vec3 truth{0.0f};
};

struct Tracer {
  const Scene& scene;
  const std::vector<WorldMesh>& meshes;
  const EmbreeWorld& world;
  const CubeFaces* skybox;
  const std::vector<glm::vec3>& centres;  // per object: probe centre (bounds centre if none)
  glm::vec3 eye;

  // What a ray sees where it meets nothing: the sky along it, or the clear colour.
  glm::vec3 background(const glm::vec3& dir) const {
    return skybox ? glm::vec3(sampleCubeLinear(*skybox, dir)) : scene.clearColour;
  }

  // What the ray origin + t dir (t > 0) sees among the objects other than `leaving`, clamped as
  // a capture texel is. `depth` counts the reflective surfaces the ray has left. The world a
  // reflector sees ends at its probe's far planes, as the main camera's ends at its own: a
  // surface farther than the capture's far distance along any axis from the probe centre is
  // not there (the floor's far reaches at a grazing reflection show the background).
  glm::vec3 radiance(int leaving, const glm::vec3& origin, const glm::vec3& dir, int depth,
                     Hit* met) const {
    Hit hit = trace(world.excluding(leaving), meshes, origin, dir, 0.0f, kInfinity);
    const glm::vec3 away = glm::abs(hit.position - centres[static_cast<size_t>(leaving)]);
    if (hit.object >= 0 && std::max({away.x, away.y, away.z}) > scene.capture.far) hit = Hit{};
    if (met) *met = hit;
    if (hit.object < 0) return background(dir);
    if (scene.objects[static_cast<size_t>(hit.object)].material != Material::Phong &&
        depth > kMaxBounces) {
      return background(dir);
    }
    return saturate(shade(hit, glm::normalize(-dir), depth, nullptr));
  }

  // The colour of surface `hit` seen along -toViewer (unit), unclamped.
  glm::vec3 shade(const Hit& hit, const glm::vec3& toViewer, int depth, Directions* dirs) const {
    const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
    switch (object.material) {
      case Material::Phong:
        return phong(scene, object.colour, hit, eye);
      case Material::Mirror:
        return mirror(hit, toViewer, depth, dirs);
      case Material::Glass:
        return glass(hit, toViewer, depth, dirs);
      case Material::CubeTextured:
        return cubeTextured(hit, depth, dirs);
    }
    return scene.clearColour;
  }

  // The direction from object's probe centre to what a ray met (its own direction on a miss).
  glm::vec3 trueDirection(int object, const Hit& met, const glm::vec3& dir) const {
    return met.object >= 0 ? glm::normalize(met.position - centres[static_cast<size_t>(object)])
                           : glm::normalize(dir);
  }

  // shaders/environment.frag (mirror) with the exact environment.
  glm::vec3 mirror(const Hit& hit, const glm::vec3& toViewer, int depth, Directions* dirs) const {
    const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
    const glm::vec3 r = glm::reflect(-toViewer, hit.normal);
    Hit met;
    const glm::vec3 env = radiance(hit.object, hit.position, r, depth + 1, &met);
    if (dirs) *dirs = {r, trueDirection(hit.object, met, r)};
    if (object.fresnel)
      return glm::mix(object.colour, env, schlick(object.ior, toViewer, hit.normal));
    return object.reflection * env + object.base * object.colour;
  }

  // shaders/environment.frag (glass), with the refracted ray followed through the object.
  glm::vec3 glass(const Hit& hit, const glm::vec3& toViewer, int depth, Directions* dirs) const {
    const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
    const float n = std::max(object.ior, 1e-3f);
    const glm::vec3 i = -toViewer;
    const glm::vec3 t = glm::refract(i, hit.normal, 1.0f / n);
    const bool total = glm::dot(t, t) == 0.0f;
    const auto reflectedRay = [&](Hit* met) {
      return radiance(hit.object, hit.position, glm::reflect(i, hit.normal), depth + 1, met);
    };
    glm::vec3 reflected(0.0f);
    glm::vec3 refracted(0.0f);
    if (total) {
      Hit met;
      reflected = reflectedRay(&met);
      refracted = reflected;
      const glm::vec3 r = glm::reflect(i, hit.normal);
      if (dirs) *dirs = {r, trueDirection(hit.object, met, r)};
    } else {
      const Crossing c = crossGlass(world.only(hit.object), meshes, hit.object, n, hit.position,
                                    glm::normalize(t));
      Hit met;
      refracted = radiance(hit.object, c.point, c.direction, depth + 1, &met);
      if (dirs) *dirs = {glm::normalize(t), trueDirection(hit.object, met, c.direction)};
      if (object.fresnel) reflected = reflectedRay(nullptr);
    }
    if (object.fresnel) {
      return glm::mix(refracted, reflected, total ? 1.0f : schlick(n, toViewer, hit.normal));
    }
    return object.reflection * refracted + object.base * object.colour;
  }

  // shaders/cube_textured.frag: the ray from the probe centre along the object-space position.
  glm::vec3 cubeTextured(const Hit& hit, int depth, Directions* dirs) const {
    const glm::vec3 c = centres[static_cast<size_t>(hit.object)];
    if (glm::dot(hit.objectPosition, hit.objectPosition) == 0.0f) {
      // The object's origin itself: a zero lookup vector, undefined in GL.
      if (dirs) *dirs = {glm::vec3(0, 0, 1), glm::vec3(0, 0, 1)};
      return background(glm::vec3(0.0f));
    }
    const glm::vec3 d = glm::normalize(hit.objectPosition);
    Hit met;
    const glm::vec3 colour = radiance(hit.object, c, d, depth + 1, &met);
    if (dirs) *dirs = {d, trueDirection(hit.object, met, d)};
    return colour;
  }
};

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

}  // namespace

glm::vec3 probeCentre(const Scene& scene, const MeshLookup& meshes, double seconds, int object) {
  return probeCentres(scene, meshes, seconds).at(static_cast<size_t>(object));
}

Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const CubeFaces* skybox, const LookCamera& camera,
                                       double seconds, int width, int height, int threads) {
  const auto start = std::chrono::steady_clock::now();
  if (width < 1 || height < 1) {
    return Result<ReferenceFrame>::failure("reference frame size must be positive");
  }
  if (!scene.skybox.empty() && !skybox) {
    return Result<ReferenceFrame>::failure(
        "reference: the scene has a skybox; its faces must be given");
  }
  if (skybox) {
    const std::string error = checkSkybox(*skybox);
    if (!error.empty()) return Result<ReferenceFrame>::failure(error);
  }

  // World-space meshes at this animation time.
  std::vector<WorldMesh> world(scene.objects.size());
  std::vector<int> reflectors;
  std::vector<int> glass;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    const MeshData* mesh = meshes(object.mesh);
    if (!mesh)
      return Result<ReferenceFrame>::failure("reference: mesh " + object.mesh + " is not loaded");
    Result<WorldMesh> placed = placeMesh(*mesh, scene.modelMatrix(object, seconds),
                                         object.material == Material::CubeTextured);
    if (!placed) return Result<ReferenceFrame>::failure(placed.error());
    world[i] = placed.take();
    if (object.material != Material::Phong) reflectors.push_back(static_cast<int>(i));
    if (object.material == Material::Glass) glass.push_back(static_cast<int>(i));
  }
  const std::vector<glm::vec3> centres = probeCentres(scene, meshes, seconds);

  EmbreeWorld embree;
  std::string error = embree.build(world, reflectors, glass);
  if (!error.empty()) return Result<ReferenceFrame>::failure(error);

  // The GL camera: clip = (P * V, multiplied in float as the renderer does) * world.
  const glm::mat4 viewProj =
      camera.projection(static_cast<float>(width) / static_cast<float>(height)) * camera.view();
  const glm::dmat4 inverseViewProj = glm::inverse(glm::dmat4(viewProj));
  const auto unproject = [&](double ndcX, double ndcY, double ndcZ) {
    const glm::dvec4 p = inverseViewProj * glm::dvec4(ndcX, ndcY, ndcZ, 1.0);
    return glm::dvec3(p) / p.w;
  };

  const size_t pixelCount = static_cast<size_t>(width) * static_cast<size_t>(height);
  ReferenceFrame frame;
  frame.image.width = width;
  frame.image.height = height;
  frame.image.pixels.assign(pixelCount * 4, 255);
  frame.objectIds.assign(pixelCount, -1);
  frame.reflectorMask.assign(pixelCount, 0);
  std::vector<Directions> directions(pixelCount);

  const Tracer tracer{scene, world, embree, skybox, centres, camera.eye()};
  const auto renderRow = [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      // Pixel centres: GL's window y counts from the bottom, the image's rows from the top.
      const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
      const double ndcY = 1.0 - (y + 0.5) / height * 2.0;
      const glm::dvec3 nearPoint = unproject(ndcX, ndcY, -1.0);
      const glm::dvec3 farPoint = unproject(ndcX, ndcY, 1.0);
      const glm::vec3 ray(farPoint - nearPoint);
      // Parametrised from the near plane (t = 0) to the far plane (t = 1): GL clips outside.
      const Hit hit = trace(embree.all(), world, glm::vec3(nearPoint), ray, 0.0f, 1.0f);
      glm::vec3 colour = tracer.background(ray);
      frame.objectIds[p] = hit.object;
      if (hit.object >= 0) {
        const glm::vec3 toViewer = glm::normalize(camera.eye() - hit.position);
        const bool reflector =
            scene.objects[static_cast<size_t>(hit.object)].material != Material::Phong;
        frame.reflectorMask[p] = reflector ? 1 : 0;
        colour = tracer.shade(hit, toViewer, 0, reflector ? &directions[p] : nullptr);
      }
      uint8_t* out = &frame.image.pixels[p * 4];
      out[0] = toByte(colour.r);
      out[1] = toByte(colour.g);
      out[2] = toByte(colour.b);
      out[3] = 255;
    }
  };

  int threadCount = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  threadCount = std::clamp(threadCount, 1, std::max(1, height));
  if (threadCount == 1) {
    for (int y = 0; y < height; ++y) renderRow(y);
  } else {
    // Interleaved rows balance the work (the sphere's rows cost more than the sky's).
    std::vector<std::thread> pool;
    for (int k = 0; k < threadCount; ++k) {
      pool.emplace_back([&, k] {
        for (int y = k; y < height; y += threadCount) renderRow(y);
      });
    }
    for (std::thread& t : pool) t.join();
  }
  error = embree.error();
  if (!error.empty()) return Result<ReferenceFrame>::failure(error);

  for (size_t p = 0; p < pixelCount; ++p) {
    if (!frame.reflectorMask[p]) continue;
    frame.lookupDirs.push_back(directions[p].lookup);
    frame.trueDirs.push_back(directions[p].truth);
  }
  frame.renderMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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

  const float n = std::max(ior, 1e-3f);
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
