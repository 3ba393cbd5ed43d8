// The exact answer the raster's cube-map reflection approximates: a ray-traced frame (Embree does
// the ray/triangle work) with the same camera and the same shading as the GLSL, except that a
// reflector's environment comes from the true reflected ray from the hit point instead of a cube
// map looked up from the probe centre.
//
// What it mirrors, term by term (shaders/mesh.vert, phong.frag, environment.frag):
//  - one primary ray per pixel centre through camera.projection(w/h) * camera.view(), from the
//    near plane to the far plane (GL clips there); pixel (x, y) counts rows from the top;
//  - world position and normal interpolated over the triangle (N = inverse-transpose(model3x3) *
//    normal per vertex, interpolated, normalised), both sides of every triangle shaded alike;
//  - Phong: colour * (Ka + Kd max(N.L, 0)) + (N.L > 0 ? Ks pow(clamp(R.V, 0, 1), shininess) : 0),
//    viewed from the main camera's eye (also in reflections: the course lights its captures so);
//  - a mirror: reflection * env(reflect(-V, N)) + base * colour, where env is the
//    Phong colour of what the reflected ray from the hit point meets first among the other
//    objects, or the clear colour; output clamped to [0, 1] and rounded to 8 bits.
// A mirror met by a reflected ray is shaded as a mirror again (its own reflected ray, up to
// kMaxMirrorBounces mirrors deep, then the clear colour); the default scene has one mirror.
// Supported: Phong objects and Material::Mirror with a live probe (fixed mix or Fresnel, as
// environment.frag); glass, cube-textured objects and skyboxes are refused with a message.
// One difference from the raster is deliberate: env is clamped to [0, 1] as a capture texel is,
// but not quantised to 8 bits.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/camera.h"
#include "core/image.h"
#include "core/mesh_data.h"
#include "core/result.h"
#include "core/scene.h"

namespace reflect {

inline constexpr int kMaxMirrorBounces = 4;

struct ReferenceFrame {
  RgbaImage image;
  // Per pixel (row-major, top row first): the index of the scene object the primary ray hits,
  // or -1 on a miss.
  std::vector<int> objectIds;
  // Per pixel: 1 where the primary ray hits a mirror.
  std::vector<uint8_t> reflectorMask;
  // Per reflector pixel, in row-major order (the pixels where reflectorMask is 1):
  //  lookupDirs: R = reflect(-V, N), the direction the raster looks its cube map up along (from
  //              the probe centre);
  //  trueDirs:   normalize(hit - c), the direction from the probe centre c to what the reflected
  //              ray from the surface point really hits (R itself when it hits nothing).
  // meanAngularErrorDegrees(lookupDirs, trueDirs) is the mean angular error of the plain lookup.
  std::vector<glm::vec3> lookupDirs;
  std::vector<glm::vec3> trueDirs;
  double renderMs = 0.0;  // wall time of renderReference (scene build + tracing)
};

// The scene's mesh `name` (level 0, object space), or nullptr when it is not loaded.
using MeshLookup = std::function<const MeshData*(const std::string&)>;

// Renders `scene` at scene time `seconds` (Scene::modelMatrix) as seen by `camera` into a width x
// height frame. Fails when a mesh is missing, the size is not positive or Embree reports an error.
// `threads` <= 0 uses std::thread::hardware_concurrency().
Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const LookCamera& camera, double seconds, int width,
                                       int height, int threads = 0);

// The probe centre the raster captures mirror `object`'s cube map from: the world centre of its
// mesh bounds, or of its probe group's joint world bounds (as FramePlanner computes it).
glm::vec3 probeCentre(const Scene& scene, const MeshLookup& meshes, double seconds, int object);

}  // namespace reflect
