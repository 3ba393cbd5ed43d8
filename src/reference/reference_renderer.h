// The exact answer the raster's cube maps approximate: a ray-traced frame (Embree does the
// ray/triangle work) with the same camera and the same shading as the GLSL, except that wherever
// the raster looks a cube map up (a live probe or the static skybox), the reference follows the
// true ray through the scene instead.
//
// What it mirrors, term by term (shaders/mesh.vert, phong.frag, environment.frag,
// cube_textured.frag, skybox.vert/.frag):
//  - one primary ray per pixel centre through camera.projection(w/h) * camera.view(), from the
//    near plane to the far plane (GL clips there); pixel (x, y) counts rows from the top;
//  - world position, normal and object-space position interpolated over the triangle
//    (N = normalMatrixOf(model3x3) * normal per vertex, interpolated, normalised), both sides of
//    every triangle shaded alike;
//  - Phong: colour * (Ka + Kd max(N.L, 0)) + (N.L > 0 ? Ks pow(clamp(R.V, 0, 1), shininess) : 0),
//    lit as seen from the main camera's eye wherever it is met (the course lights its captures
//    so, and the reference does the same for every ray);
//  - the background where the primary ray meets nothing: the skybox along the view ray (skybox.vert
//    draws it at the far plane, looked up along the ray's direction), or the clear colour; every
//    other ray that meets nothing sees the same, along its own direction (the sky is infinitely
//    far). The skybox is sampled as GL samples it (core/cube_sampling.h: the spec's face table,
//    LINEAR, seamless edges, faces top row first; within one 8-bit level of llvmpipe's);
//  - a mirror: reflection * env(R) + base * colour, or with Fresnel mix(colour, env(R), schlick),
//    R = reflect(-V, N);
//  - glass: with Fresnel mix(refracted, reflected, schlick) (total internal reflection at entry:
//    reflected), else reflection * refracted + base * colour; reflected = env(R), and refracted is
//    what the ray refracted in (T = refract(I, N, 1/n)) sees after it crosses the object: it is
//    traced inside the object's own mesh to the far surface and refracted out there
//    (refract(D, N_in, n), N_in the exit's normal turned to face the ray); on total internal
//    reflection it reflects inside and goes on, up to kMaxInternalReflections times; a ray still
//    inside after that goes on from its last point along its last direction, past the object;
//  - cube-textured (Ex12-1): texture(env, objectPosition), unlit: the ray from the probe centre
//    along normalize(objectPosition) (the object-space position used as a world direction), shaded
//    as what it meets, or the background;
//  - output clamped to [0, 1] and rounded to 8 bits.
// env(d) from a surface point x is what the ray x + t d (t > 0) meets first among the other
// objects, shaded by its own material in turn (a mirror reflects again, glass refracts, a
// cube-textured object shows its own lookup), clamped to [0, 1] as a capture texel is; or the
// background. That is the truth for `environment: "skybox"` objects too: the static sky map
// approximates it (the sky is behind everything else, at infinity).
//
// What differs from the raster on purpose (the truth its cube maps approximate):
//  - env is the true ray from the surface point (from the probe centre for cube-textured objects),
//    never a texel of a capture: no parallax error, no capture resolution, no near plane, no
//    previous-frame cube for another reflector, not quantised to 8 bits;
//  - glass is crossed through both surfaces (the raster refracts once, at entry).
// What the reference leaves out or limits (none of it matters in the shipped scenes):
//  - no Fresnel loss at a glass exit surface and no absorption inside;
//  - a reflected, refracted or looked-up ray never meets the object it leaves, and a ray inside
//    glass meets only that object's own surface: exact for convex reflectors and glass with
//    nothing inside it, as every shipped one is;
//  - a rough mirror (SceneObject::rough(), docs/rough.md) sees the environment averaged over its
//    GGX lobe (core/ggx.h), estimated by Monte Carlo: lobe rays traced as the mirror's one ray,
//    from seeded random points (ReferenceOptions), so the frame carries noise that
//    measureReferenceNoise (reference_noise.h) measures; roughness 0 is the perfect mirror above;
//  - a probe-lit Phong object (SceneObject::probeLit) seen directly from the eye takes as its
//    ambient light the cosine-weighted mean of what its point sees (diffuseSamples rays about its
//    interpolated normal, each traced and shaded as a mirror's ray is, never meeting the object
//    itself), where the raster reads its probe's irradiance; seen in a mirror, through glass or
//    in a capture it keeps the constant ambient (one bounce, as the raster);
//  - the bounce limit: a mirror, glass or cube-textured surface met by a ray that has already
//    left kMaxBounces such surfaces is not followed further: it shows the background along the
//    ray.
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
#include "core/skybox_faces.h"
#include "core/trace_limits.h"

namespace reflect {

// What the reference's Monte Carlo estimates (rough mirrors' lobes) use. The pixels depend on
// the seed and the sample count, never on the threads.
struct ReferenceOptions {
  // Lobe rays a pixel's own rough mirror traces: enough that the estimate's noise is well below
  // the errors it judges (docs/rough.md measures it: rough-spheres, 400x400).
  int lobeSamples = 512;
  // Rays a probe-lit object's pixel averages its diffuse light over (cosine-weighted); its noise
  // is measured as the lobes' is (docs/rough.md, "Diffuse light from the probe").
  int diffuseSamples = 4096;
  uint32_t seed = 1;
  int threads = 0;  // <= 0: std::thread::hardware_concurrency()
};

struct ReferenceFrame {
  RgbaImage image;
  // Per pixel (row-major, top row first): the index of the scene object the primary ray hits,
  // or -1 on a miss.
  std::vector<int> objectIds;
  // Per pixel: 1 where the primary ray hits a mirror, glass or cube-textured object (every pixel
  // whose colour the raster looks up in a cube map: a live probe or the skybox).
  std::vector<uint8_t> reflectorMask;
  // Per reflector pixel, in row-major order (the pixels where reflectorMask is 1), from the probe
  // centre c of the object (for a sky-mapped object, which has no probe, its world bounds' centre):
  //  lookupDirs: the direction the raster's plain lookup uses from c:
  //              mirror: R = reflect(-V, N);
  //              glass: T = refract(I, N, 1/n), the single refraction at entry (R where that is
  //              total internal reflection);
  //              cube-textured: normalize(objectPosition);
  //  trueDirs:   the direction from c to what the true ray really meets (the ray's own direction
  //              when it meets nothing: the sky, infinitely far):
  //              mirror: the reflected ray from the surface point;
  //              glass: the ray that leaves the object after crossing it (the reflected ray at a
  //              total internal reflection on entry);
  //              cube-textured: the ray from c itself, so its direction error is 0: the raster's
  //              error there is the capture's, not the lookup's.
  // meanAngularErrorDegrees(lookupDirs, trueDirs) is the mean angular error of the plain lookup.
  std::vector<glm::vec3> lookupDirs;
  std::vector<glm::vec3> trueDirs;
  double renderMs = 0.0;     // wall time of renderReference (scene build + tracing)
  ReferenceOptions options;  // what it was rendered with
};

// The scene's mesh `name` (level 0, object space), or nullptr when it is not loaded.
using MeshLookup = std::function<const MeshData*(const std::string&)>;

// Renders `scene` at scene time `seconds` (Scene::modelMatrix) as seen by `camera` into a width x
// height frame. `skybox` is the sky the raster draws (six equal squares, GL face order, top row
// first), or nullptr for none: then a ray that meets nothing sees the clear colour. Fails when a
// mesh is missing, the scene names a skybox but none is given, the faces are malformed, the size
// is not positive or Embree reports an error. `threads` <= 0 uses
// std::thread::hardware_concurrency(); the pixels do not depend on it.
Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const CubeFaces* skybox, const LookCamera& camera,
                                       double seconds, int width, int height, int threads = 0);
// The same with the Monte Carlo's options (the seed and samples of rough mirrors' lobes).
Result<ReferenceFrame> renderReference(const Scene& scene, const MeshLookup& meshes,
                                       const CubeFaces* skybox, const LookCamera& camera,
                                       double seconds, int width, int height,
                                       const ReferenceOptions& options);

// The probe centre the raster captures `object`'s cube map from: the world centre of its mesh
// bounds, or of its probe group's joint world bounds, or its explicit centre (as FramePlanner
// computes it). An object without a live probe (Phong, or sky-mapped): its world bounds' centre.
glm::vec3 probeCentre(const Scene& scene, const MeshLookup& meshes, double seconds, int object);

// Rays through one glass object, followed as renderReference follows them (for tests).
struct GlassRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f};  // origin + t direction, t > 0, from outside the object
};
struct GlassPath {
  bool entered = false;   // the ray met the object and refracted into it
  glm::vec3 entry{0.0f};  // where it met the object
  glm::vec3 entryNormal{0.0f};
  glm::vec3 inside{0.0f};     // T = refract(I, N, 1/n), the first direction inside
  bool exited = false;        // it refracted out through a surface
  glm::vec3 exit{0.0f};       // the last surface point: where it left, or its last reflection
  glm::vec3 direction{0.0f};  // the ray that goes on from `exit`
  int internalReflections = 0;
};
// `mesh` placed by `model`, of index `ior`: one path per ray.
Result<std::vector<GlassPath>> traceGlass(const MeshData& mesh, const glm::mat4& model, float ior,
                                          const std::vector<GlassRay>& rays);

}  // namespace reflect
