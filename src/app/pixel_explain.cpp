#include "app/pixel_explain.h"

#include <algorithm>
#include <cmath>

#include "app/held_trees.h"
#include "app/text_line.h"
#include "core/accuracy_settings.h"
#include "core/cube_cross.h"
#include "core/cube_sampling.h"
#include "core/fresnel.h"
#include "core/irradiance.h"
#include "core/irradiance_parallax.h"
#include "core/reference_shading.h"
#include "core/settings_schema.h"
#include "gfx/cube_readback.h"
#include "gfx/offscreen_target.h"
#include "gfx/probe_irradiance.h"

namespace reflect {
namespace {

// What the exact ray meets, and the colour the reference would give it.
struct ExactSight {
  SurfacePoint met;
  bool beyondFar = false;
  bool shaded = true;  // false: it meets a reflector, not traced further here
  glm::vec3 colour{0.0f};
};

// The level-0 trees the demo already holds (the exact mode's), or one built here for a mesh that
// has none yet. The demo's trees are shared without ownership: they outlive this explanation.
SceneBvh placedObjects(const Demo& demo, double seconds) {
  const MeshTreeLookup held = heldTrees(demo);
  return placeScene(
      demo.scene(), seconds,
      [&demo, &held](const std::string& name) -> std::shared_ptr<const MeshBvh> {
        if (std::shared_ptr<const MeshBvh> tree = held(name)) return tree;
        const MeshData* mesh = demo.meshLevel(name, 0);
        if (mesh == nullptr) return nullptr;
        return std::make_shared<const MeshBvh>(
            buildMeshBvh(std::shared_ptr<const MeshData>(std::shared_ptr<const MeshData>(), mesh)));
      });
}

glm::vec3 background(const Demo& demo, const glm::vec3& direction) {
  const CubeFaces* sky = demo.skyboxFaces();
  return sky ? glm::vec3(sampleCubeLinear(*sky, direction)) : demo.scene().clearColour;
}

// As the reference's radiance(): the first object met, leaving out the reflector itself; past
// the capture's far plane (a box around the probe centre) nothing was captured, so it is the sky.
ExactSight exactAlong(const Demo& demo, const SceneBvh& placed, const TraceRay& ray, int reflector,
                      const glm::vec3& probeCentre) {
  const Scene& scene = demo.scene();
  ExactSight sight;
  sight.met = firstSurface(placed, ray, 0.0f, reflector);
  if (sight.met.object >= 0) {
    const glm::vec3 away = glm::abs(sight.met.position - probeCentre);
    sight.beyondFar = std::max({away.x, away.y, away.z}) > scene.capture.far;
  }
  if (sight.met.object < 0 || sight.beyondFar) {
    sight.colour = background(demo, ray.direction);
    return sight;
  }
  const SceneObject& object = scene.objects[static_cast<size_t>(sight.met.object)];
  if (object.material != Material::Phong) {
    sight.shaded = false;
    return sight;
  }
  const PhongLight& light = scene.light;
  sight.colour = glm::clamp(
      phongShade(object.colour, sight.met.position, sight.met.normal, light.position,
                 demo.camera().eye(),
                 glm::vec4(light.ambient, light.diffuse, light.specular, light.shininess)),
      glm::vec3(0.0f), glm::vec3(1.0f));
  return sight;
}

// A probe-lit figure's irradiance at the surface's normal: the probe's colour faces read back and
// projected on the CPU, as irradiance_project.vert projects them (WebGL2 cannot map the GPU's
// buffer; PixelExplain.AProbeLitFigureNamesTheIrradianceItsPixelWasLitWith holds the two
// together). Nothing for any other pixel.
std::string readIrradiance(const Demo& demo, const SurfacePoint& surface, PixelExplanation& e) {
  const ProbePlan* light = e.object >= 0 ? demo.lastPlan().irradianceOf(e.object) : nullptr;
  if (light == nullptr) return {};
  const CubeCaptureTarget* target =
      demo.renderer() ? demo.renderer()->probeTarget(light->reflector) : nullptr;
  if (target == nullptr) {
    return "the probe of object " + std::to_string(light->reflector + 1) + " has not been captured";
  }
  Result<CubeFaces> faces = readCubeFaces(*target, FacesChannel::Colour);
  if (!faces) return faces.error();
  e.surfacePoint = surface.position;
  e.normal = surface.normal;
  e.irradianceProbe = light->reflector;
  // Projected as the GPU projects them: from the box chain's level the projection reads.
  const int size = target->faceSize();
  const int factor = size / std::max(size >> ProbeIrradiance::levelFor(size), 1);
  const CubeFaces read = shrinkFaces(faces.value(), factor);
  const std::optional<float> set =
      demo.scene().objects[static_cast<size_t>(e.object)].ambientRadius;
  e.irradianceRadius = set ? *set : 0.0f;
  e.irradianceDirection =
      irradianceDirection(surface.normal, surface.position, light->centre, e.irradianceRadius);
  // Where no radius is set, mesh.vert's parallax from the probe's distances, from the faces
  // as captured (the GPU reads their box chain as irradianceParallax does): at the triangle's
  // corners, blended by the point's weights, as the rasteriser interpolates the vertex shader's.
  e.irradianceParallax = glm::vec3(0.0f);
  for (size_t k = 0; k < 3 && !set; ++k) {
    e.irradianceParallax +=
        surface.weights[static_cast<int>(k)] *
        irradianceParallax(faces.value(), surface.cornerPositions[k], light->centre,
                           surface.cornerNormals[k], demo.scene().capture.near);
  }
  e.irradiance =
      glm::max(irradianceAt(projectIrradiance(read), e.irradianceDirection) + e.irradianceParallax,
               glm::vec3(0.0f));
  return {};
}

// Why pixel `e` has no numbers to explain, or "" when it is a probed mirror or glass pixel.
std::string noExplanation(const Demo& demo, const PixelExplanation& e) {
  if (e.object < 0) return "the view ray meets nothing there: the pixel shows the background";
  const SceneObject& object = demo.scene().objects[static_cast<size_t>(e.object)];
  const std::string what = "object " + std::to_string(e.object + 1) + " (" + object.mesh + ")";
  if (const ProbePlan* light = demo.lastPlan().irradianceOf(e.object)) {
    // A probe-lit figure: it looks no reflection up, but its ambient comes from a probe.
    const glm::vec3& c = light->centre;
    const glm::vec3& n = e.normal;
    const glm::vec3& d = e.irradianceDirection;
    const glm::ivec3 rgb = colourBytes(e.irradiance);
    const float radius = e.irradianceRadius;
    const glm::vec3& p = e.irradianceParallax;
    const std::string along =
        radius > 0.0f
            ? formatLine(
                  " and it is read along %.3f, %.3f, %.3f (the surroundings taken %.2f from the "
                  "centre: ambientRadius)",
                  d.x, d.y, d.z, radius)
            : formatLine(
                  ", plus %+.3f, %+.3f, %+.3f for what this point sees that the centre does not "
                  "(8 taps followed to the probe's distances)",
                  p.x, p.y, p.z);
    return what + formatLine(
                      " is phong, lit by probe: its ambient is the irradiance of object "
                      "%d's probe (centre %.2f, %.2f, %.2f), order-2 spherical harmonics "
                      "at its normal, %s. Here the normal is %.3f, %.3f, %.3f%s; the "
                      "irradiance E / pi = %.3f, %.3f, %.3f (RGB %d %d %d; the constant "
                      "ambient would be %.2f)",
                      light->reflector + 1, c.x, c.y, c.z,
                      light->projectIrradiance ? "projected this frame" : "as last projected", n.x,
                      n.y, n.z, along.c_str(), e.irradiance.r, e.irradiance.g, e.irradiance.b,
                      rgb.r, rgb.g, rgb.b, demo.scene().light.ambient);
  }
  if (object.material != Material::Mirror && object.material != Material::Glass) {
    return what + " is " + materialName(object.material) +
           ", not a mirror or glass: it looks nothing up";
  }
  if (object.environment == Environment::Skybox) {
    return what +
           " reflects the static skybox: its lookup is the ray's direction alone, exact "
           "for a sky infinitely far away; there is no probe to explain";
  }
  if (demo.lastPlan().traces(e.object)) {
    const std::vector<int>& narrow = demo.lastPlan().narrowTraced;
    const bool forced = std::find(narrow.begin(), narrow.end(), e.object) != narrow.end();
    return what + "'s rays were traced exactly this frame (" +
           (forced ? "search: planned traces a lobe too narrow for lobe taps"
                   : "search: exact, or search: planned found tracing cheaper") +
           "): there is no probe lookup to explain";
  }
  if (demo.lastPlan().probeOf(e.object) == nullptr) {
    return what + " has no probe captured this frame";
  }
  return {};
}

// The view ray's surface, the reflected or refracted ray, and the ray the lookups stand for.
void followRays(const Demo& demo, const SceneBvh& placed, const SurfacePoint& surface,
                PixelExplanation& e) {
  const SceneObject& object = demo.scene().objects[static_cast<size_t>(e.object)];
  e.surfacePoint = surface.position;
  e.normal = surface.normal;
  e.viewRay = glm::normalize(surface.position - e.eye);
  e.reflected = glm::reflect(e.viewRay, e.normal);
  e.lookupRay = {e.surfacePoint, e.reflected};
  if (object.material != Material::Glass) return;
  e.glass = followGlass(placed, surface, e.viewRay, clampedIor(object.ior),
                        demo.accuracySettings().glassSurfaces == 2);
  e.lookupRay = {e.glass.exitPoint, e.glass.leaving};
}

// The search the renderer drew object `object` with, by name.
std::string searchOf(const Demo& demo, int object) {
  return searchName(searchDrawnWith(demo, object));
}

// The main pass drawn again into a float target, mirrors and glass writing `output`; pixel
// (x, y)'s RGB.
Result<glm::vec3> drawnValue(Demo& demo, int output, int x, int y, int width, int height) {
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height, true);
  if (!target) return Result<glm::vec3>::failure(target.error());
  demo.renderLookupDirections(target.value().framebuffer(), width, height, output);
  const std::vector<glm::vec3> values = target.value().readFloats();
  return values[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
}

// Where the search landed: the GPU's `measured`, in near-plane units from the probe centre; a
// unit vector is the ray's direction itself (the search met nothing, or there was none).
std::string readSearch(Demo& demo, PixelExplanation& e) {
  Result<glm::vec3> measured =
      drawnValue(demo, SceneRenderer::kOutputSearchPoint, e.x, e.y, e.width, e.height);
  if (!measured) return measured.error();
  const glm::vec3 m = measured.value();
  e.searchAtInfinity = e.search == "plain" || std::abs(glm::length(m) - 1.0f) < 1e-5f;
  e.searchDirection = glm::normalize(m);
  if (!e.searchAtInfinity) e.searchPoint = e.probeCentre + m * demo.scene().capture.near;
  return {};
}

// The colours each lookup returns, from the probe's colour cube read back.
std::string readLookupColours(const Demo& demo, PixelExplanation& e) {
  const ProbePlan* probe = demo.lastPlan().probeOf(e.object);
  const CubeCaptureTarget* target =
      demo.renderer() ? demo.renderer()->probeTarget(probe->reflector) : nullptr;
  if (target == nullptr)
    return "the probe of object " + std::to_string(e.object + 1) + " has not been captured";
  Result<CubeFaces> faces = readCubeFaces(*target, FacesChannel::Colour);
  if (!faces) return faces.error();
  e.courseColour = glm::vec3(sampleCubeLinear(faces.value(), e.courseDirection));
  e.searchColour = glm::vec3(sampleCubeLinear(faces.value(), e.searchDirection));
  return {};
}

// The pixel as the exact environment would make it: the material's mix of what the lookup ray
// (and, for glass, its reflection) really sees.
glm::vec3 exactPixel(const Demo& demo, const SceneBvh& placed, const PixelExplanation& e) {
  const SceneObject& object = demo.scene().objects[static_cast<size_t>(e.object)];
  const float schlick = schlickWeight(fresnelF0(object.ior), -e.viewRay, e.normal);
  if (object.material == Material::Mirror) {
    return blended(
        mirrorBlend(object.colour, object.reflection, object.base, object.fresnel, schlick),
        e.exactColour);
  }
  const glm::vec3 reflected =
      e.glass.totalAtEntry
          ? e.exactColour
          : exactAlong(demo, placed, {e.surfacePoint, e.reflected}, e.object, e.probeCentre).colour;
  return blended(glassBlend(object.colour, reflected, e.glass.totalAtEntry, object.reflection,
                            object.base, object.fresnel, schlick),
                 e.exactColour);
}

}  // namespace

Result<PixelExplanation> explainPixel(Demo& demo, int x, int y, int width, int height) {
  PixelExplanation e;
  e.x = x;
  e.y = y;
  e.width = width;
  e.height = height;
  e.seconds = demo.clock().seconds();
  e.eye = demo.camera().eye();
  const std::optional<TraceRay> view = pixelRay(demo.camera(), x, y, width, height);
  if (!view) {
    e.outside = true;
    e.message = "pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                std::to_string(width) + "x" + std::to_string(height) + " frame (x 0.." +
                std::to_string(width - 1) + ", y 0.." + std::to_string(height - 1) + ")";
    return e;
  }
  const SceneBvh placed = placedObjects(demo, e.seconds);
  const SurfacePoint surface = firstSurface(placed, *view);
  e.object = surface.object;
  if (std::string error = readIrradiance(demo, surface, e); !error.empty()) {
    return Result<PixelExplanation>::failure(error);
  }
  e.message = noExplanation(demo, e);
  if (e.object >= 0) {
    e.mesh = demo.scene().objects[static_cast<size_t>(e.object)].mesh;
    e.material = demo.scene().objects[static_cast<size_t>(e.object)].material;
    e.lobe = explainLobe(demo, e.object);
  }
  if (!e.message.empty()) return e;

  followRays(demo, placed, surface, e);
  e.search = searchOf(demo, e.object);
  e.probeCentre = demo.lastPlan().probeOf(e.object)->centre;
  e.courseDirection = e.lookupRay.direction;
  const ExactSight sight = exactAlong(demo, placed, e.lookupRay, e.object, e.probeCentre);
  e.exactObject = sight.met.object;
  e.exactBeyondFar = sight.beyondFar;
  e.exactHit = sight.met.position;
  e.exactShaded = sight.shaded;
  e.exactColour = sight.colour;
  e.exactDirection = sight.met.object >= 0 && !sight.beyondFar
                         ? glm::normalize(sight.met.position - e.probeCentre)
                         : e.lookupRay.direction;
  e.courseErrorDeg = angleDegrees(e.courseDirection, e.exactDirection);

  std::string error = readSearch(demo, e);
  if (error.empty()) error = readLookupColours(demo, e);
  if (!error.empty()) return Result<PixelExplanation>::failure(error);
  e.searchErrorDeg = angleDegrees(e.searchDirection, e.exactDirection);
  Result<glm::vec3> frame = drawnValue(demo, SceneRenderer::kOutputColour, x, y, width, height);
  if (!frame) return Result<PixelExplanation>::failure(frame.error());
  e.frameColour = glm::clamp(frame.value(), glm::vec3(0.0f), glm::vec3(1.0f));
  if (e.exactShaded) {
    e.exactPixelColour = glm::clamp(exactPixel(demo, placed, e), glm::vec3(0.0f), glm::vec3(1.0f));
  }
  return e;
}

std::vector<RaySegment> pickSegments(const PixelExplanation& e) {
  std::vector<RaySegment> segments;
  if (!e.message.empty()) return segments;
  constexpr float kOpenLength = 5.0f;  // a ray with no end point
  const glm::vec3 white(1.0f), yellow(1.0f, 0.9f, 0.1f), red(1.0f, 0.15f, 0.15f);
  const glm::vec3 green(0.1f, 1.0f, 0.3f), blue(0.2f, 0.5f, 1.0f);
  const auto cross = [&segments](const glm::vec3& p, const glm::vec3& colour) {
    const float arm = 0.08f;
    for (int axis = 0; axis < 3; ++axis) {
      glm::vec3 d(0.0f);
      d[axis] = arm;
      segments.push_back({p - d, p + d, colour});
    }
  };
  const bool exactEnds = e.exactObject >= 0 && !e.exactBeyondFar;
  const glm::vec3 exactEnd =
      exactEnds ? e.exactHit : e.lookupRay.origin + kOpenLength * e.lookupRay.direction;
  const float lookupLength = glm::length(exactEnd - e.probeCentre);
  segments.push_back({e.eye, e.surfacePoint, white});
  if (e.material == Material::Glass && !e.glass.totalAtEntry) {
    segments.push_back({e.surfacePoint, e.glass.exitPoint, yellow});
  }
  segments.push_back({e.lookupRay.origin, exactEnd, blue});
  segments.push_back({e.probeCentre, e.probeCentre + lookupLength * e.courseDirection, red});
  const glm::vec3 searchEnd =
      e.searchAtInfinity ? e.probeCentre + lookupLength * e.searchDirection : e.searchPoint;
  segments.push_back({e.probeCentre, searchEnd, green});
  cross(e.probeCentre, red);
  cross(searchEnd, green);
  cross(exactEnd, blue);
  return segments;
}

glm::ivec3 colourBytes(const glm::vec3& colour) {
  return glm::ivec3(glm::round(glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f)) * 255.0f));
}

}  // namespace reflect
