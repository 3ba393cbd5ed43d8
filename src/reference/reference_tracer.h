// How the reference follows a ray through the scene and shades what it meets (the rules are in
// reference_renderer.h), on the Embree scene of embree_scene.h, with the shading terms of
// reference_shading.h (shaders/shading.glsl's).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/glass_crossing.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "reference/embree_scene.h"
#include "reference/lobe_sampler.h"

namespace reflect {

// How a ray refracted into a glass object crosses it: where it leaves and along what.
using Crossing = GlassCrossing;

// From `entry` (on glass object `object`, of index n) along the refracted direction `inside`:
// core/glass_crossing.h's rule, the far surfaces found by Embree in the object alone (`only`).
Crossing crossGlass(RTCScene only, const std::vector<WorldMesh>& meshes, int object, float n,
                    const glm::vec3& entry, const glm::vec3& inside);

// A reflector pixel's plain lookup direction and the true one (see ReferenceFrame).
struct Directions {
  glm::vec3 lookup{0.0f};
  glm::vec3 truth{0.0f};
};

// Where a ray is on its way from the eye: the reflective surfaces it has left (the bounce limit
// counts them), and of those the rough ones (mirrors and glass), whose lobes already average it
// over many rays (a rough surface it meets then traces fewer: Tracer::lobeAverage).
struct Path {
  int depth = 0;
  int roughSurfaces = 0;
  Path next() const { return {depth + 1, roughSurfaces}; }
};

struct Tracer {
  const Scene& scene;
  const std::vector<WorldMesh>& meshes;
  const EmbreeWorld& world;
  const CubeFaces* skybox;
  const std::vector<glm::vec3>& centres;  // per object: probe centre (bounds centre if none)
  glm::vec3 eye;
  // Rough mirrors (SceneObject::rough()): the lobe samples a pixel's own rough mirror averages,
  // and the seed of their random points (lobe_sampler.h). A rough mirror seen in another's lobe
  // traces fewer (lobeAverage() says why).
  int lobeSamples = 512;  // ReferenceOptions's
  uint32_t seed = 1;
  // Per object: its lobe's albedo (rough mirrors; the others' are empty).
  std::vector<LobeAlbedoTable> lobeAlbedos;
  // Probe-lit objects: the cosine-weighted rays their diffuse light averages.
  int diffuseSamples = 4096;  // ReferenceOptions's

  // What a ray sees where it meets nothing: the sky along it, or the clear colour.
  glm::vec3 background(const glm::vec3& dir) const;

  // What the ray origin + t dir (t > 0) sees among the objects other than `leaving`, clamped as
  // a capture texel is. `path`: what the ray has met so far. The world a
  // reflector sees ends at its probe's far planes, as the main camera's ends at its own: a
  // surface farther than the capture's far distance along any axis from the probe centre is
  // not there (the floor's far reaches at a grazing reflection show the background).
  glm::vec3 radiance(int leaving, const glm::vec3& origin, const glm::vec3& dir, Path path,
                     Hit* met) const;

  // The colour of surface `hit` seen along -toViewer (unit), unclamped; `dirs` (reflectors
  // only, may be null) gets its lookup and true directions.
  glm::vec3 shade(const Hit& hit, const glm::vec3& toViewer, Path path, Directions* dirs) const;

 private:
  glm::vec3 trueDirection(int object, const Hit& met, const glm::vec3& dir) const;
  // The lobe rays a rough surface traces at this point of a path: lobeSamples for the first rough
  // surface, kNestedLobeRays for one seen in its lobe, then one (lobeAverage() says why).
  uint32_t lobeRaysOn(Path path) const;
  // What a rough surface's lobe at `hit` starts from, the same for its reflection and (frosted
  // glass) the light through: alpha, the normal facing the viewer, the seeded points, how many
  // rays (lobeRaysOn), and the path its rays go on with.
  struct Lobe {
    float alpha;
    glm::vec3 n;
    LobeSampler sampler;
    uint32_t count;
    Path next;
  };
  Lobe lobeAt(const Hit& hit, const glm::vec3& toViewer, Path path) const;
  glm::vec3 mirror(const Hit& hit, const glm::vec3& toViewer, Path path, Directions* dirs) const;
  glm::vec3 lobeAverage(const Hit& hit, const glm::vec3& toViewer, Path path) const;
  glm::vec3 glass(const Hit& hit, const glm::vec3& toViewer, Path path, Directions* dirs) const;
  std::optional<glm::vec3> transmittedAverage(const Hit& hit, const glm::vec3& toViewer, float ior,
                                              Path path) const;
  glm::vec3 cubeTextured(const Hit& hit, Path path, Directions* dirs) const;
  // A probe-lit object's ambient at `hit`: the mean of what diffuseSamples cosine-weighted rays
  // about its normal see (E / pi), the light phong.frag's probeAmbient approximates.
  glm::vec3 diffuseLight(const Hit& hit, Path path) const;
};

}  // namespace reflect
