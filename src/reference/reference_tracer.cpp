#include "reference/reference_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/cube_sampling.h"
#include "core/float_limits.h"
#include "core/ggx.h"
#include "core/reference_shading.h"
#include "core/trace_limits.h"

namespace reflect {
namespace {

// The lobe rays of a rough mirror seen in another's lobe (lobeAverage).
constexpr uint32_t kNestedLobeRays = 8;

glm::vec3 saturate(const glm::vec3& c) {
  return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace

Crossing crossGlass(RTCScene only, const std::vector<WorldMesh>& meshes, int object, float n,
                    const glm::vec3& entry, const glm::vec3& inside) {
  const float epsilon = meshes[static_cast<size_t>(object)].selfEpsilon;
  return crossGlassInterior(entry, inside, n, [&](const glm::vec3& from, const glm::vec3& dir) {
    const Hit far = trace(only, meshes, from, dir, epsilon, kInfinity);
    return FarSurface{far.object >= 0, far.position, far.normal};
  });
}

Tracer::Lobe Tracer::lobeAt(const Hit& hit, const glm::vec3& toViewer, Path path) const {
  Path next = path.next();
  ++next.roughSurfaces;
  // Both sides of a triangle are shaded alike: the lobe lies around the side facing the viewer.
  return {ggxAlpha(scene.objects[static_cast<size_t>(hit.object)].roughness),
          glm::dot(hit.normal, toViewer) < 0.0f ? -hit.normal : hit.normal,
          LobeSampler(seed, hit.position, toViewer), lobeRaysOn(path), next};
}

uint32_t Tracer::lobeRaysOn(Path path) const {
  if (path.roughSurfaces == 0) return static_cast<uint32_t>(std::max(lobeSamples, 1));
  return path.roughSurfaces == 1 ? kNestedLobeRays : 1u;
}

glm::vec3 Tracer::background(const glm::vec3& dir) const {
  return skybox ? glm::vec3(sampleCubeLinear(*skybox, dir)) : scene.clearColour;
}

glm::vec3 Tracer::radiance(int leaving, const glm::vec3& origin, const glm::vec3& dir, Path path,
                           Hit* met) const {
  Hit hit = trace(world.excluding(leaving), meshes, origin, dir, 0.0f, kInfinity);
  const glm::vec3 away = glm::abs(hit.position - centres[static_cast<size_t>(leaving)]);
  if (hit.object >= 0 && std::max({away.x, away.y, away.z}) > scene.capture.far) hit = Hit{};
  if (met) *met = hit;
  if (hit.object < 0) return background(dir);
  if (scene.objects[static_cast<size_t>(hit.object)].material != Material::Phong &&
      path.depth > kMaxBounces) {
    return background(dir);
  }
  return saturate(shade(hit, glm::normalize(-dir), path, nullptr));
}

glm::vec3 Tracer::shade(const Hit& hit, const glm::vec3& toViewer, Path path,
                        Directions* dirs) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
  const PhongLight& light = scene.light;
  switch (object.material) {
    case Material::Phong: {  // shaders/phong.frag, unclamped
      const glm::vec4 terms(light.ambient, light.diffuse, light.specular, light.shininess);
      // Probe light is one bounce: only the eye's own view of the object takes it.
      if (object.probeLit() && path.depth == 0) {
        return phongLit(object.colour, hit.position, hit.normal, light.position, eye,
                        diffuseLight(hit, path), terms);
      }
      return phongShade(object.colour, hit.position, hit.normal, light.position, eye, terms);
    }
    case Material::Mirror:
      return mirror(hit, toViewer, path, dirs);
    case Material::Glass:
      return glass(hit, toViewer, path, dirs);
    case Material::CubeTextured:
      return cubeTextured(hit, path, dirs);
  }
  return scene.clearColour;
}

// The direction from object's probe centre to what a ray met (its own direction on a miss).
glm::vec3 Tracer::trueDirection(int object, const Hit& met, const glm::vec3& dir) const {
  return met.object >= 0 ? glm::normalize(met.position - centres[static_cast<size_t>(object)])
                         : glm::normalize(dir);
}

// shaders/environment.frag (mirror) with the exact environment.
glm::vec3 Tracer::mirror(const Hit& hit, const glm::vec3& toViewer, Path path,
                         Directions* dirs) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
  const float schlick = schlickWeight(fresnelF0(object.ior), toViewer, hit.normal);
  const glm::vec3 r = glm::reflect(-toViewer, hit.normal);
  Hit met;
  glm::vec3 env;
  if (!object.rough()) {
    env = radiance(hit.object, hit.position, r, path.next(), &met);
  } else {
    env = lobeAverage(hit, toViewer, path);
    // A rough mirror's lookup and true directions are its lobe centre's: the perfect mirror's.
    if (dirs) radiance(hit.object, hit.position, r, path.next(), &met);
  }
  if (dirs) *dirs = {r, trueDirection(hit.object, met, r)};
  return blended(
      mirrorBlend(object.colour, object.reflection, object.base, object.fresnel, schlick), env);
}

// A rough mirror's environment (core/ggx.h): the lobe average sum(w L) / sum(w) over lobe samples
// l = reflect(-v, h), each traced as the perfect mirror traces its one ray. The first rough
// mirror on a path: `lobeSamples` shifted Hammersley points (lobe_sampler.h) and that ratio,
// consistent, with a bias of order 1 / S far below its noise. A rough mirror met by one of those
// rays (seen in a rough reflection) would make that S^2 rays a pixel: it traces
// kNestedLobeRays (from the third rough mirror on a path, one) and divides the mean of their w L by
// the lobe's albedo E[w] instead of by their own weights, which keeps it unbiased, so the S rays of
// the lobe before it average its noise out. Only the clamp of what that surface shows (a capture
// texel's) applies to the few-ray estimate: its bright reflections come out a little dark.
glm::vec3 Tracer::lobeAverage(const Hit& hit, const glm::vec3& toViewer, Path path) const {
  const Lobe lobe = lobeAt(hit, toViewer, path);
  const auto& [alpha, n, sampler, count, next] = lobe;
  const float nDotV = glm::dot(n, toViewer);
  const bool first = path.roughSurfaces == 0 && lobeSamples > 1;
  glm::vec3 sum(0.0f);
  float weights = 0.0f;
  for (uint32_t k = 0; k < count; ++k) {
    const glm::vec3 h = ggxHalfVector(sampler.point(k, count), alpha, n);
    const glm::vec3 l = glm::reflect(-toViewer, h);
    const float w =
        lobeSampleWeight(nDotV, glm::dot(n, l), glm::dot(n, h), glm::dot(toViewer, h), alpha);
    if (w <= 0.0f) continue;
    sum += w * radiance(hit.object, hit.position, l, next, nullptr);
    weights += w;
  }
  if (!first && nDotV > 0.0f) {
    const size_t i = static_cast<size_t>(hit.object);
    const float albedo = i < lobeAlbedos.size() ? lobeAlbedos[i].at(nDotV) : 1.0f;
    return sum / (static_cast<float>(count) * albedo);
  }
  if (weights > 0.0f) return sum / weights;
  // No lobe above the surface (its normal at right angles to the view): the perfect mirror's ray.
  return radiance(hit.object, hit.position, glm::reflect(-toViewer, hit.normal), path.next(),
                  nullptr);
}

// shaders/environment.frag (glass), with the refracted ray followed through the object. Rough
// (frosted) glass averages both over its lobe: the reflection as a rough mirror's (lobeAverage),
// the light through over the refracted rays of the lobe's microfacet normals (transmittedAverage).
glm::vec3 Tracer::glass(const Hit& hit, const glm::vec3& toViewer, Path path,
                        Directions* dirs) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(hit.object)];
  const float n = clampedIor(object.ior);
  const float schlick = schlickWeight(fresnelF0(object.ior), toViewer, hit.normal);
  const glm::vec3 i = -toViewer;
  const glm::vec3 t = glm::refract(i, hit.normal, 1.0f / n);
  const bool total = glm::dot(t, t) == 0.0f;
  // What the reflection shows (rough glass: its lobe); `met` (may be null) gets what the
  // reflected ray itself meets, the lobe's centre.
  const auto reflectedRay = [&](Hit* met) {
    const glm::vec3 r = glm::reflect(i, hit.normal);
    if (!object.rough()) return radiance(hit.object, hit.position, r, path.next(), met);
    if (met) radiance(hit.object, hit.position, r, path.next(), met);
    return lobeAverage(hit, toViewer, path);
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
    std::optional<glm::vec3> through;
    if (object.rough()) through = transmittedAverage(hit, toViewer, n, path);
    // The polished surface's own refracted ray: what polished glass shows, and rough glass's
    // directions (its lobe's centre) or its view where no microfacet lets the ray in.
    if (!through || dirs) {
      const Crossing c = crossGlass(world.only(hit.object), meshes, hit.object, n, hit.position,
                                    glm::normalize(t));
      Hit met;
      const glm::vec3 smooth = radiance(hit.object, c.point, c.direction, path.next(), &met);
      if (!through) through = smooth;
      if (dirs) *dirs = {glm::normalize(t), trueDirection(hit.object, met, c.direction)};
    }
    refracted = *through;
    if (object.fresnel) reflected = reflectedRay(nullptr);
  }
  return blended(glassBlend(object.colour, reflected, total, object.reflection, object.base,
                            object.fresnel, schlick),
                 refracted);
}

// Rough glass's light through (core/ggx.h): the mean over microfacet normals h drawn as the
// lobe's (ggxHalfVector, the points lobeAverage's sampler gives, counted as it counts them) of
// what the view ray refracted through h sees once it has crossed the object, whose far surface
// is polished. Normals the ray cannot enter through (total reflection, or a refracted ray that
// does not point into the object) are left out; with none left, nothing (the caller traces the
// polished surface's ray).
std::optional<glm::vec3> Tracer::transmittedAverage(const Hit& hit, const glm::vec3& toViewer,
                                                    float ior, Path path) const {
  const auto [alpha, n, sampler, count, next] = lobeAt(hit, toViewer, path);
  glm::vec3 sum(0.0f);
  uint32_t rays = 0;
  for (uint32_t k = 0; k < count; ++k) {
    const glm::vec3 h = ggxHalfVector(sampler.point(k, count), alpha, n);
    const glm::vec3 t = glm::refract(-toViewer, h, 1.0f / ior);
    if (glm::dot(t, t) == 0.0f || glm::dot(t, n) >= 0.0f) continue;
    const Crossing c = crossGlass(world.only(hit.object), meshes, hit.object, ior, hit.position,
                                  glm::normalize(t));
    sum += radiance(hit.object, c.point, c.direction, next, nullptr);
    ++rays;
  }
  if (rays == 0) return std::nullopt;
  return sum / static_cast<float>(rays);
}

// Cosine-weighted directions about the interpolated normal (as phong.frag evaluates the
// irradiance at it, whichever side faces the eye), from the seeded shifted Hammersley points:
// u -> (sqrt(u1) cos 2 pi u2, sqrt(u1) sin 2 pi u2, sqrt(1 - u1)). The mean of what they see is
// E / pi.
glm::vec3 Tracer::diffuseLight(const Hit& hit, Path path) const {
  const glm::vec3 n = glm::normalize(hit.normal);
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 tangent = glm::normalize(glm::cross(helper, n));
  const glm::vec3 bitangent = glm::cross(n, tangent);
  const LobeSampler sampler(seed ^ 0x9e3779b9u, hit.position, n);
  const uint32_t count = static_cast<uint32_t>(std::max(diffuseSamples, 1));
  glm::vec3 sum(0.0f);
  for (uint32_t k = 0; k < count; ++k) {
    const glm::vec2 u = sampler.point(k, count);
    const float r = std::sqrt(u.x);
    const float phi = 6.28318531f * u.y;
    const glm::vec3 d = r * std::cos(phi) * tangent + r * std::sin(phi) * bitangent +
                        std::sqrt(std::max(0.0f, 1.0f - u.x)) * n;
    sum += radiance(hit.object, hit.position, glm::normalize(d), path.next(), nullptr);
  }
  return sum / static_cast<float>(count);
}

// shaders/cube_textured.frag: the ray from the probe centre along the object-space position.
glm::vec3 Tracer::cubeTextured(const Hit& hit, Path path, Directions* dirs) const {
  const glm::vec3 c = centres[static_cast<size_t>(hit.object)];
  if (glm::dot(hit.objectPosition, hit.objectPosition) == 0.0f) {
    // The object's origin itself: a zero lookup vector, undefined in GL.
    if (dirs) *dirs = {glm::vec3(0, 0, 1), glm::vec3(0, 0, 1)};
    return background(glm::vec3(0.0f));
  }
  const glm::vec3 d = glm::normalize(hit.objectPosition);
  Hit met;
  const glm::vec3 colour = radiance(hit.object, c, d, path.next(), &met);
  if (dirs) *dirs = {d, trueDirection(hit.object, met, d)};
  return colour;
}

}  // namespace reflect
