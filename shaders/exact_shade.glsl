// The exact mode's shading (SEARCH_EXACT): a mirror or glass pixel's ray is traced against the
// scene's triangles (exact_trace.glsl) instead of looked up in a cube map, and what it meets is
// shaded as a capture would shade it: Phong lit as seen from the main camera's eye, a mirror
// reflecting again, glass crossed through both surfaces, a cube-textured object traced from its
// probe centre, the sky (or the clear colour) where nothing is met, every term from shading.glsl.
// src/reference/reference_renderer.h says what the exact answer is; this follows it term by
// term, with one limit: glass met by a ray that has already left a surface sees, for its
// Fresnel-reflected share, the sky along the reflected ray (one ray a bounce: no tree of rays in
// a fragment shader). Like environment_lookup.glsl it defines seenReflected() and
// seenThroughGlass() for environment.frag's main().
#if SEARCH == SEARCH_EXACT
#include "exact_trace.glsl"
#include "shading.glsl"

uniform samplerCube u_exactSky;
uniform int u_exactHasSky;    // 0: the clear colour where nothing is met
uniform vec3 u_exactClear;
uniform int u_exactSelf;      // the object being drawn
uniform vec3 u_exactLight;
uniform vec4 u_exactPhong;    // ambient, diffuse, specular, shininess
uniform vec3 u_exactEye;      // the main camera's eye: captures are lit as seen from it
uniform float u_exactFar;     // the capture's far distance: the world a reflector sees ends there
uniform int u_exactMark;      // 1: alpha 0 on this pass's pixels (the error view's reflector mask)

// The world a reflector sees ends at its probe's far planes, as the main camera's ends at its
// own: a surface farther than the capture's far distance along any axis from `centre` is not
// there (reference_renderer.cpp's radiance()).
bool exactBeyondFar(vec3 p, vec3 centre) {
  vec3 away = abs(p - centre);
  return max(away.x, max(away.y, away.z)) > u_exactFar;
}

vec3 exactBackground(vec3 d) {
  if (u_exactHasSky == 1) return texture(u_exactSky, d).rgb;
  return u_exactClear;
}

// What a Phong surface shows a traced ray: shading.glsl's Phong, lit as the captures are, as seen
// from the main camera's eye.
vec3 exactPhong(vec3 colour, vec3 p, vec3 n) {
  return phongShade(colour, p, n, u_exactLight, u_exactEye, u_exactPhong);
}

// The world normal (interpolated, normalised) of a hit.
vec3 exactNormal(ExactHit h) {
  int base = h.instance * kExactInstance;
  vec3 n0 = exactFetch(u_exactNormals, 3 * h.slot).xyz;
  vec3 n1 = exactFetch(u_exactNormals, 3 * h.slot + 1).xyz;
  vec3 n2 = exactFetch(u_exactNormals, 3 * h.slot + 2).xyz;
  vec3 n = (1.0 - h.u - h.v) * n0 + h.u * n1 + h.v * n2;
  mat3 normalMatrix = mat3(exactFetch(u_exactScene, base).xyz,
                           exactFetch(u_exactScene, base + 1).xyz,
                           exactFetch(u_exactScene, base + 2).xyz);
  return normalize(normalMatrix * n);
}

#if EXACT_GENERAL == 0
// What the ray origin + t dir sees when nothing it can meet is a mirror, glass or cube-textured
// object (the program's variant: src/gfx/program_key.h): one trace, and the Phong surface it
// meets or the sky. `truth`: the direction from the probe centre to what it meets, or its own
// direction when it meets nothing.
vec3 exactRadiance(vec3 origin, vec3 dir, int self, out vec3 truth) {
  ExactHit h = exactTrace(origin, dir, 0.0, self, -1);
  truth = dir;
  vec3 p = origin + h.t * dir;
  if (h.instance < 0 || exactBeyondFar(p, u_probeCentre)) return exactBackground(dir);
  truth = normalize(p - u_probeCentre);
  vec4 look = exactFetch(u_exactScene, h.instance * kExactInstance + 3);
  return clamp(exactPhong(look.rgb, p, exactNormal(h)), 0.0, 1.0);
}
#else
// A ray on its way through the scene: where it is, where it goes, the object it leaves (its rays
// never meet it again), and the glass object it is inside (-1: none) with the internal
// reflections it has made there.
struct ExactRay {
  vec3 origin;
  vec3 dir;
  int leaving;
  int glass;
  int reflections;
};

// Inside glass: the ray leaves through the far surface `h` (refracted out), or reflects inside
// it, kExactMaxInternal times at most; with no far surface (along a silhouette) it goes on.
void exactInsideGlass(inout ExactRay ray, ExactHit h) {
  int g = ray.glass;
  if (h.instance < 0) {
    ray.leaving = g;
    ray.glass = -1;
    return;
  }
  vec3 N = exactNormal(h);
  vec3 facing = dot(ray.dir, N) > 0.0 ? -N : N;
  float n = exactFetch(u_exactScene, g * kExactInstance + 4).z;
  vec3 out_ = refract(ray.dir, facing, n);
  ray.origin = ray.origin + h.t * ray.dir;
  if (dot(out_, out_) > 0.0) {
    ray.dir = normalize(out_);
    ray.leaving = g;
    ray.glass = -1;
  } else {
    ray.dir = reflect(ray.dir, facing);
    if (++ray.reflections == kExactMaxInternal) {
      ray.leaving = g;
      ray.glass = -1;
    }
  }
}

// A mirror (material 1) or glass (2) at p, normal N, met by `ray`: its blend (shading.glsl) and
// the ray it sends on (into the glass where it refracts).
Blend exactReflectorBounce(int material, vec3 colour, vec4 weightsOf, vec3 p, vec3 N,
                           inout ExactRay ray) {
  vec3 toViewer = normalize(-ray.dir);
  bool fresnel = weightsOf.w > 0.5;  // weightsOf: reflection, base, ior, fresnel
  float schlick = schlickWeight(fresnelF0(weightsOf.z), toViewer, N);
  vec3 R = reflect(-toViewer, N);
  ray.origin = p;
  ray.dir = R;
  if (material == 1) return mirrorBlend(colour, weightsOf.x, weightsOf.y, fresnel, schlick);
  vec3 T = refract(-toViewer, N, 1.0 / weightsOf.z);
  bool total = dot(T, T) == 0.0;
  // Glass's Fresnel-reflected share sees the sky along R: one ray a bounce.
  vec3 reflected = fresnel && !total ? clamp(exactBackground(R), 0.0, 1.0) : vec3(0.0);
  if (!total) {
    ray.dir = normalize(T);
    ray.glass = ray.leaving;
    ray.reflections = 0;
  }
  return glassBlend(colour, reflected, total, weightsOf.x, weightsOf.y, fresnel, schlick);
}

// The cube-textured object at p (slot `base`): the ray from its probe centre along its
// object-space position. False where that position is its origin (no direction).
bool exactCubeBounce(int base, vec3 p, inout ExactRay ray) {
  vec4 m0 = exactFetch(u_exactScene, base + 7);
  vec4 m1 = exactFetch(u_exactScene, base + 8);
  vec4 m2 = exactFetch(u_exactScene, base + 9);
  vec3 objectPosition = vec3(dot(m0, vec4(p, 1.0)), dot(m1, vec4(p, 1.0)), dot(m2, vec4(p, 1.0)));
  if (dot(objectPosition, objectPosition) == 0.0) return false;
  ray.origin = exactFetch(u_exactScene, base + 5).xyz;
  ray.dir = normalize(objectPosition);
  return true;
}

// What the ray origin + t dir (t > 0) sees, clamped as a capture texel is (the reference's
// radiance): among the objects but `self`, or, with `inside`, first across glass object `self`
// to where it leaves. `truth`: the direction from the probe centre to what the ray (once out of
// the glass) meets, or its own direction when it meets nothing.
vec3 exactRadiance(vec3 origin, vec3 dir, int self, bool inside, out vec3 truth) {
  // Each bounce at a mirror, glass or cube-textured object gives colour = its blend of what it
  // sees, clamped; the blends are kept and unwound at the end.
  Blend blends[kExactMaxBounces];
  int links = 0;
  ExactRay ray = ExactRay(origin, dir, self, inside ? self : -1, 0);
  int depth = 1;
  bool first = true;
  truth = dir;
  vec3 result = exactBackground(dir);
  for (int step = 0; step < 64; ++step) {
    bool inGlass = ray.glass >= 0;
    float tMin = inGlass ? exactFetch(u_exactScene, ray.glass * kExactInstance + 6).x : 0.0;
    ExactHit h = exactTrace(ray.origin, ray.dir, tMin, inGlass ? -1 : ray.leaving, ray.glass);
    if (inGlass) {
      exactInsideGlass(ray, h);
      continue;
    }
    vec3 p = ray.origin + h.t * ray.dir;
    if (h.instance >= 0 && ray.leaving >= 0 &&
        exactBeyondFar(p, exactFetch(u_exactScene, ray.leaving * kExactInstance + 5).xyz)) {
      h.instance = -1;
    }
    if (first) {
      first = false;
      truth = h.instance >= 0 ? normalize(p - u_probeCentre) : ray.dir;
    }
    int base = max(h.instance, 0) * kExactInstance;
    vec4 look = exactFetch(u_exactScene, base + 3);
    int material = int(look.w + 0.5);
    if (h.instance < 0 || (material != 0 && depth > kExactMaxBounces)) {
      result = exactBackground(ray.dir);
      break;
    }
    if (material == 0) {
      result = clamp(exactPhong(look.rgb, p, exactNormal(h)), 0.0, 1.0);
      break;
    }
    ray.leaving = h.instance;
    Blend blend = Blend(vec3(0.0), 1.0);  // cube-textured: what its own ray sees, as it is
    if (material != 1 && material != 2) {
      if (!exactCubeBounce(base, p, ray)) {
        result = exactBackground(vec3(0.0, 0.0, 1.0));
        break;
      }
    } else {
      blend = exactReflectorBounce(material, look.rgb, exactFetch(u_exactScene, base + 4), p,
                                   exactNormal(h), ray);
    }
    blends[links] = blend;
    ++links;
    ++depth;
  }
  for (int k = kExactMaxBounces - 1; k >= 0; --k) {
    if (k < links) result = clamp(blended(blends[k], result), 0.0, 1.0);
  }
  return result;
}
#endif

// The mirror's reflected ray from `origin` along `R`, traced: what it sees, and in `measured`
// the direction from the probe centre to what it meets.
vec3 exactReflected(vec3 origin, vec3 R, out vec3 measured) {
#if EXACT_GENERAL == 0
  return exactRadiance(origin, R, u_exactSelf, measured);
#else
  return exactRadiance(origin, R, u_exactSelf, false, measured);
#endif
}

#if ROUGH == 1
#include "ggx.glsl"

uniform float u_exactAlpha;  // the drawn rough mirror's lobe alpha (core/ggx.h ggxAlpha)
uniform int u_exactLobeRays; // AccuracySettings::lobeRays

// A rough mirror (core/ggx.h says what it sees): the lobe average sum(w L) / sum(w) over
// u_exactLobeRays rays l = reflect(-v, h), h from the fixed Hammersley set, the same for every
// pixel (an error with structure, never noise), each traced as the perfect mirror's one ray. The
// mirrors those rays meet stay perfect mirrors (exactRadiance's bounces): the reference follows
// a rough one's lobe there, and that difference is part of this mode's measured error. Point 0
// is (0, 0), whose half vector is the normal: its ray is the perfect mirror's, whose truth
// `measured` keeps (the lookup-direction output and the face-use view read it).
vec3 seenOverLobe(vec3 origin, vec3 R, out vec3 measured) {
  vec3 v = normalize(u_viewPosition - v_worldPosition);
  vec3 n = normalize(v_worldNormal);
  // Both sides of a triangle are shaded alike: the lobe lies around the side facing the viewer.
  if (dot(n, v) < 0.0) n = -n;
  float nDotV = dot(n, v);
  uint count = uint(max(u_exactLobeRays, 1));
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  measured = R;
  for (uint k = 0u; k < count; ++k) {
    vec3 h = ggxHalfVector(hammersley(k, count), u_exactAlpha, n);
    vec3 l = reflect(-v, h);
    float w = lobeSampleWeight(nDotV, dot(n, l), dot(n, h), dot(v, h), u_exactAlpha);
    if (w <= 0.0) continue;
    vec3 truth;
    sum += w * exactReflected(origin, l, truth);
    weights += w;
    if (k == 0u) measured = truth;
  }
  // No lobe above the surface (its normal at right angles to the view): the perfect mirror's ray.
  if (weights <= 0.0) return exactReflected(origin, R, measured);
  return sum / weights;
}

#endif

// What the ray refracted into the drawn glass at `origin` along `dir` sees once out of it. The
// general tracer walks the glass's own triangles to its far side. Through the Phong objects alone
// (EXACT_GENERAL 0: frosted glass traced for a narrow lobe, seen in another probe's capture, a
// second bounce; gfx/environment_binding.cpp's lobeCentreAlone) a sphere's far side is in closed
// form (glass_sphere_exit.glsl), another shape's is skipped, and the ray goes on from there: the
// general walk in every texel of four probes' faces cost more than the rest of the capture. (In
// the main pass too it lost 2.9 dB on the 0.25 sphere: its neighbours are not Phong objects.)
vec3 exactThroughSelf(vec3 origin, vec3 dir, out vec3 truth) {
#if EXACT_GENERAL == 1
  return exactRadiance(origin, dir, u_exactSelf, true, truth);
#else
  vec3 exitPoint = origin;
  vec3 d = dir;
  if (u_twoSurfaces == 1 && u_glassSphere.w > 0.0) leaveGlassSphere(exitPoint, d);
  return exactRadiance(exitPoint, d, u_exactSelf, truth);
#endif
}

#if ROUGH == 1
// Rough (frosted) glass's light through (core/ggx.h says what it is): the mean, over the
// u_exactLobeRays microfacet normals h of the fixed set around n, of what the view ray I
// refracted through h sees once out of the object (its far surface crossed as polished glass).
// A normal the ray cannot enter through (total reflection, or a ray that does not point into the
// object) is left out. Point 0's normal is n itself: its ray is the smooth surface's T, whose
// truth `measured` keeps.
vec3 transmittedOverLobe(vec3 origin, vec3 I, vec3 n, vec3 T, out vec3 measured) {
  uint count = uint(max(u_exactLobeRays, 1));
  vec3 sum = vec3(0.0);
  float rays = 0.0;
  measured = T;
  for (uint k = 0u; k < count; ++k) {
    vec3 h = ggxHalfVector(hammersley(k, count), u_exactAlpha, n);
    vec3 t = refract(I, h, u_eta);
    if (dot(t, t) == 0.0 || dot(t, n) >= 0.0) continue;
    vec3 truth;
    sum += exactThroughSelf(origin, normalize(t), truth);
    rays += 1.0;
    if (k == 0u) measured = truth;
  }
  if (rays == 0.0) return exactThroughSelf(origin, normalize(T), measured);
  return sum / rays;
}
#endif

vec3 seenReflected(vec3 origin, vec3 R, out vec3 measured) {
#if ROUGH == 1
  return seenOverLobe(origin, R, measured);
#else
  return exactReflected(origin, R, measured);
#endif
}

// Glass, traced (environment_lookup.glsl's seenThroughGlass() with rays for lookups): the
// refracted ray through the object, and the reflected one only where Fresnel weighs it in or the
// refraction is total (each traced ray costs a walk). `measured`: the last traced ray's truth.
// Rough glass traces a lobe of rays for each (seenOverLobe, transmittedOverLobe).
void seenThroughGlass(vec3 origin, vec3 I, vec3 N, vec3 T, bool total, out vec3 reflected,
                      out vec3 refracted, out vec3 measured) {
  reflected = vec3(0.0);
  refracted = vec3(0.0);
  measured = reflect(I, N);
  for (int ray = 0; ray < 2; ++ray) {
    bool wanted = ray == 0 ? (u_fresnel == 1 || total) : !total;
    if (!wanted) continue;
    vec3 truth;
#if ROUGH == 1
    vec3 c = ray == 0 ? seenOverLobe(origin, reflect(I, N), truth)
                      : transmittedOverLobe(origin, I, N, normalize(T), truth);
#else
    vec3 c = ray == 0 ? exactReflected(origin, reflect(I, N), truth)
                      : exactThroughSelf(origin, normalize(T), truth);
#endif
    if (ray == 0) {
      reflected = c;
    } else {
      refracted = c;
    }
    measured = truth;
  }
  if (total) refracted = reflected;
}
#endif
