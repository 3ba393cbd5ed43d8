// The CPU's side of "pick a pixel" (app/pixel_explain.h, `reflect explain`): the camera ray through
// a pixel's centre, what it meets among the placed meshes (core's BVH, the trees the exact mode
// traces), the surface there as the raster shades it (the interpolated vertex normal, as
// mesh.vert and environment.frag use it), the path of a refracted ray through a glass mesh, and
// the angle between two directions. No GL: the unit tests and the Embree reference check it.
#pragma once

#include <array>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/bvh.h"
#include "core/camera.h"
#include "core/scene.h"

namespace reflect {

struct TraceRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit length
};

// The camera ray through the centre of pixel (x, y) of a width x height frame, (0, 0) being the
// top-left pixel (the PNG's first pixel): from the near plane, unprojected in double as the
// reference does (reference_renderer.cpp). nullopt for a pixel outside the frame.
std::optional<TraceRay> pixelRay(const LookCamera& camera, int x, int y, int width, int height);

// Each scene object's level-0 tree by mesh name (null: not traced).
using MeshTreeLookup = std::function<std::shared_ptr<const MeshBvh>(const std::string& mesh)>;

// The scene's objects placed at `seconds`, as intersectScene walks them (instance i = object i).
SceneBvh placeScene(const Scene& scene, double seconds, const MeshTreeLookup& trees);

// A point met on a placed mesh.
struct SurfacePoint {
  int object = -1;  // -1: nothing met
  float t = 0.0f;   // along the ray that met it
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // unit, the interpolated vertex normal in world space (outward)
  // The triangle met, as the rasteriser has it: its corners in world space (positions, unit
  // normals) and the point's barycentric weights, for what a vertex shader computes at them.
  std::array<glm::vec3, 3> cornerPositions{};
  std::array<glm::vec3, 3> cornerNormals{};
  glm::vec3 weights{0.0f};
};

// The first surface along `ray` (t in (tMin, infinity)), leaving out object `skip`; with
// `only` >= 0, that object alone.
SurfacePoint firstSurface(const SceneBvh& scene, const TraceRay& ray, float tMin = 0.0f,
                          int skip = -1, int only = -1);

// How far past a surface of object `object` a ray starts so that it does not meet the surface it
// leaves: 1e-5 of its world box's diagonal (the exact tracer's self epsilon, bvh_pack.cpp).
float selfEpsilon(const SceneBvh& scene, int object);

// A refracted ray through glass object `entry.object`, from its entry point `entry` for the view
// ray `incoming` (unit): refracted in (air to n = ior), and, with `twoSurfaces`, on to its far
// side and out (n to air), reflected inside where that is total (at most
// kMaxInternalReflections times), as the reference's crossGlass does but on the mesh's own tree.
struct GlassRoute {
  bool totalAtEntry = false;  // the view ray is reflected, not refracted (no path inside)
  glm::vec3 inside{0.0f};     // the refracted direction entering (unit)
  bool exited = false;        // it left the object (else `leaving` is its last direction)
  glm::vec3 exitPoint{0.0f};  // where it leaves (the entry point with one surface)
  glm::vec3 leaving{0.0f};    // the direction it leaves along (unit)
  int internalReflections = 0;
};
GlassRoute followGlass(const SceneBvh& scene, const SurfacePoint& entry, const glm::vec3& incoming,
                       float ior, bool twoSurfaces);

// The angle between two directions (any length, not zero), in degrees.
double angleDegrees(const glm::vec3& a, const glm::vec3& b);

}  // namespace reflect
