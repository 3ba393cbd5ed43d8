#include "reference/reference_renderer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>

#include <glm/gtc/matrix_inverse.hpp>

#include "core/frustum.h"
#include "core/probe_layout.h"

namespace reflect {
namespace {

// Object-space mesh moved to world space as mesh.vert does (in float, like the GPU).
struct WorldMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // inverse-transpose(model3x3) * normal, not normalised
  const std::vector<uint32_t>* indices = nullptr;
};

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

// Owns the device and its scenes: scenes[0] holds every object, and for each reflector r,
// excluding[r] holds every object but r (what r's reflected rays may hit).
class EmbreeWorld {
 public:
  EmbreeWorld() = default;
  EmbreeWorld(const EmbreeWorld&) = delete;
  EmbreeWorld& operator=(const EmbreeWorld&) = delete;
  ~EmbreeWorld() {
    for (RTCScene s : scenes_) rtcReleaseScene(s);
    if (device_) rtcReleaseDevice(device_);
  }

  std::string build(const std::vector<WorldMesh>& meshes, const std::vector<int>& reflectors) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) return "Embree: rtcNewDevice failed";
    rtcSetDeviceErrorFunction(device_, onEmbreeError, &errors_);
    all_ = newScene(meshes, -1);
    for (int r : reflectors) excluding_[r] = newScene(meshes, r);
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

 private:
  RTCScene newScene(const std::vector<WorldMesh>& meshes, int skip) {
    RTCScene scene = rtcNewScene(device_);
    scenes_.push_back(scene);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    for (size_t i = 0; i < meshes.size(); ++i) {
      if (static_cast<int>(i) == skip) continue;
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
  std::vector<RTCScene> scenes_;
};

struct Hit {
  int object = -1;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // interpolated and normalised
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
  return hit;
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

struct Tracer {
  const Scene& scene;
  const std::vector<WorldMesh>& meshes;
  const EmbreeWorld& world;
  glm::vec3 eye;

  // What a reflector's reflected ray sees: the Phong colour (lit as seen from the main eye, as
  // the course's capture pass does) of the first other object, clamped as a capture texel is;
  // a mirror again for another reflector; the clear colour on a miss.
  glm::vec3 environment(int reflector, const glm::vec3& origin, const glm::vec3& dir, int depth,
                        Hit* first) const {
    const Hit hit = trace(world.excluding(reflector), meshes, origin, dir, 0.0f,
                          std::numeric_limits<float>::infinity());
    if (first) *first = hit;
    if (hit.object < 0) return scene.clearColour;
    const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
    if (object.material == Material::Mirror) {
      if (depth >= kMaxMirrorBounces) return scene.clearColour;
      return saturate(mirror(hit, glm::normalize(-dir), depth + 1, nullptr, nullptr));
    }
    return saturate(phong(scene, object.colour, hit, eye));
  }

  // shaders/environment.frag (mirror) with the exact environment. `toViewer` is V (unit, surface to
  // viewer).
  glm::vec3 mirror(const Hit& hit, const glm::vec3& toViewer, int depth, glm::vec3* lookup,
                   Hit* envHit) const {
    const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
    const glm::vec3 r = glm::reflect(-toViewer, hit.normal);
    if (lookup) *lookup = r;
    const glm::vec3 env = environment(hit.object, hit.position, r, depth, envHit);
    if (object.fresnel) {
      const float n = std::max(object.ior, 1e-3f);
      const float f0 = ((n - 1.0f) / (n + 1.0f)) * ((n - 1.0f) / (n + 1.0f));
      const float cosine = std::clamp(glm::dot(toViewer, hit.normal), 0.0f, 1.0f);
      const float schlick = f0 + (1.0f - f0) * std::pow(1.0f - cosine, 5.0f);
      return glm::mix(object.colour, env, schlick);
    }
    return object.reflection * env + object.base * object.colour;
  }
};

uint8_t toByte(float c) {
  return static_cast<uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

glm::vec3 probeCentre(const Scene& scene, const MeshLookup& meshes, double seconds, int object) {
  std::vector<ProbeCandidate> candidates;
  for (const SceneObject& o : scene.objects) {
    const MeshData* mesh = meshes(o.mesh);
    const glm::mat4 model = scene.modelMatrix(o, seconds);
    const Bounds local = mesh ? mesh->bounds : Bounds{};
    candidates.push_back(ProbeCandidate{o.needsLiveProbe(), o.probeGroup, o.probeCentre,
                                        transformBounds(local, model)});
  }
  for (const ProbeLayout& probe : layoutProbes(candidates)) {
    for (int member : probe.members) {
      if (member == object) return probe.centre;
    }
  }
  return glm::vec3(scene.modelMatrix(scene.objects[static_cast<size_t>(object)], seconds)[3]);
}

Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const LookCamera& camera, double seconds, int width,
                                       int height, int threads) {
  const auto start = std::chrono::steady_clock::now();
  if (width < 1 || height < 1) {
    return Result<ReferenceFrame>::failure("reference frame size must be positive");
  }
  if (!scene.skybox.empty()) {
    return Result<ReferenceFrame>::failure("reference: scenes with a skybox are not supported");
  }

  // World-space meshes at this animation time.
  std::vector<WorldMesh> world(scene.objects.size());
  std::vector<int> reflectors;
  std::vector<glm::vec3> centres(scene.objects.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (object.material != Material::Phong &&
        !(object.material == Material::Mirror && object.environment == Environment::LiveProbe)) {
      return Result<ReferenceFrame>::failure(
          "reference: object " + std::to_string(i) + " (" + object.mesh +
          "): only Phong objects and live-probe mirrors are supported");
    }
    const MeshData* mesh = meshes(object.mesh);
    if (!mesh)
      return Result<ReferenceFrame>::failure("reference: mesh " + object.mesh + " is not loaded");
    const glm::mat4 model = scene.modelMatrix(object, seconds);
    const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(model));
    WorldMesh& w = world[i];
    w.indices = &mesh->indices;
    w.positions.reserve(mesh->vertices.size());
    w.normals.reserve(mesh->vertices.size());
    for (const Vertex& v : mesh->vertices) {
      w.positions.push_back(glm::vec3(model * glm::vec4(v.position, 1.0f)));
      w.normals.push_back(normalMatrix * v.normal);
    }
    for (uint32_t index : mesh->indices) {
      if (index >= mesh->vertices.size()) {
        return Result<ReferenceFrame>::failure("reference: mesh " + object.mesh +
                                               " has an index out of range");
      }
    }
    if (object.material == Material::Mirror) {
      reflectors.push_back(static_cast<int>(i));
      centres[i] = probeCentre(scene, meshes, seconds, static_cast<int>(i));
    }
  }

  EmbreeWorld embree;
  std::string error = embree.build(world, reflectors);
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
  std::vector<glm::vec3> lookup(pixelCount, glm::vec3(0.0f));
  std::vector<glm::vec3> truth(pixelCount, glm::vec3(0.0f));

  const Tracer tracer{scene, world, embree, camera.eye()};
  const auto renderRow = [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      // Pixel centres: GL's window y counts from the bottom, the image's rows from the top.
      const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
      const double ndcY = 1.0 - (y + 0.5) / height * 2.0;
      const glm::dvec3 nearPoint = unproject(ndcX, ndcY, -1.0);
      const glm::dvec3 farPoint = unproject(ndcX, ndcY, 1.0);
      // Parametrised from the near plane (t = 0) to the far plane (t = 1): GL clips outside.
      const Hit hit = trace(embree.all(), world, glm::vec3(nearPoint),
                            glm::vec3(farPoint - nearPoint), 0.0f, 1.0f);
      glm::vec3 colour = scene.clearColour;
      frame.objectIds[p] = hit.object;
      if (hit.object >= 0) {
        const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
        if (object.material == Material::Mirror) {
          frame.reflectorMask[p] = 1;
          const glm::vec3 toViewer = glm::normalize(camera.eye() - hit.position);
          glm::vec3 r;
          Hit envHit;
          colour = tracer.mirror(hit, toViewer, 0, &r, &envHit);
          lookup[p] = r;
          truth[p] =
              envHit.object >= 0
                  ? glm::normalize(envHit.position - centres[static_cast<size_t>(hit.object)])
                  : r;
        } else {
          colour = phong(scene, object.colour, hit, camera.eye());
        }
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
    frame.lookupDirs.push_back(lookup[p]);
    frame.trueDirs.push_back(truth[p]);
  }
  frame.renderMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return frame;
}

}  // namespace reflect
