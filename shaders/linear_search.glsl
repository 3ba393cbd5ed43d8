// The linear search of the distance-impostor method (Szirmay-Kalos, Aszodi, Lazanyi and Premecz,
// Eurographics 2005), as this project shipped it before the hierarchical search
// (depth_search.glsl), kept as the `linear` search setting for comparison. It reads the distance
// each capture texel stores in alpha (capture_output.glsl) and needs u_probeCentre,
// u_distanceUnit and u_environment from the including shader.
// The direction from the probe centre to where the ray from the surface point x along d meets
// the captured surroundings (the capture's alpha holds each texel's distance from the centre).
// As in the distance-impostor method: a linear search along the ray, parametrised so that a in
// [0, 1) covers the whole ray (t = kSearchScale * a / (1 - a) near-plane units), finds the first
// sample behind the stored surface, then DISTANCE_ITERATIONS secant steps refine the crossing.
//
// A single depth layer cannot tell a ray that meets a surface from one that slips behind an
// occluder (a figure seen from the probe centre, with the floor hidden behind it): both go from
// in front of the stored surface to behind it. At a true crossing the stored distance is
// continuous, so the refined point lies on it; at an occluder's edge it jumps, and the refined
// point stays far from it. Such a crossing would draw a ghost of the occluder's silhouette: the
// search skips it and goes on along the ray.
//
// The constants were chosen on the default scene at t = 0, 2, 4 s (reflector PSNR against the
// ray-traced reference; checked at t = 1, 3, 5, 7 s, where the gain over the old lookup held).
const int kLinearSteps = 12;
// The last linear sample is at t = 12 x kSearchScale near-plane units (48 in the course's
// scenes, whose capture near plane is 1). Scale 2 and 8 lost 0.4 and 1.5 dB against 4.
const float kSearchScale = 4.0;
// A refined crossing counts as a surface when it lies within this fraction of its distance from
// the stored surface. 0.05 and 0.2 lost 0.7 and 0.4 dB against 0.1.
const float kSurfaceTolerance = 0.1;

// The capture stores the clear background at the far plane, and a skybox with alpha 1, which reads
// as 9999 units (the clamp below): infinitely far. Stored distances past kSkyDistance are sky.
const float kSkyDistance = 5000.0;

float storedDistance(vec3 direction) {
  float a = min(textureLod(u_environment, direction, 0.0).a, 0.9999);
  return a / (1.0 - a);
}

vec3 pointAt(vec3 x, vec3 d, float a) {
  return x + kSearchScale * (a / (1.0 - a)) * d;
}

// Positions here are in units of the capture's near plane, as the stored distances are.
float behind(vec3 x, vec3 d, float a) {  // > 0 in front of the stored surface, < 0 behind it
  vec3 p = pointAt(x, d, a);
  return storedDistance(p) - length(p);
}

// One secant refinement of the crossing bracketed by [frontA, backA] (front in front of the
// stored surface, back behind it). Returns the refined point, and in `surface` whether it lies on
// the stored surface (a true crossing) rather than at a depth jump (a ghost); frontA moves to
// the last refined point in front.
vec3 refine(vec3 x, vec3 d, inout float frontA, float frontF, float backA, float backF,
            out bool surface) {
  for (int k = 0; k < DISTANCE_ITERATIONS; ++k) {
    float middle = frontA + (backA - frontA) * frontF / max(frontF - backF, 1e-6);
    float fm = behind(x, d, middle);
    if (fm < 0.0) {
      backA = middle;
      backF = fm;
    } else {
      frontA = middle;
      frontF = fm;
    }
  }
  float hit = frontA + (backA - frontA) * frontF / max(frontF - backF, 1e-6);
  vec3 p = pointAt(x, d, hit);
  surface = abs(storedDistance(p) - length(p)) <= kSurfaceTolerance * length(p);
  return p;
}

vec3 linearSearch(vec3 surfacePoint, vec3 d) {
  vec3 x = (surfacePoint - u_probeCentre) / u_distanceUnit;
  // The linear search runs its whole, fixed length and notes the first two front-to-back
  // crossings; the refinement runs after it, so nothing leaves a loop early. (A search that
  // returned from inside its loop crashed llvmpipe 22.3's compiled shader under some settings
  // of the sweep; in SwiftShader both forms cost the same.)
  float previousA = 0.0;
  float previousF = behind(x, d, 0.0);
  vec4 first = vec4(-1.0);   // frontA, frontF, backA, backF of the first crossing (x < 0: none)
  vec4 second = vec4(-1.0);  // and of the second
  // The farthest sample known to be in front of the stored surface. When no surface is found,
  // its texel is the best guess for what the ray meets: what lies beside an occluder if the ray
  // slipped behind one. Looking up along d instead would show the occluder itself, a ghost
  // beside its true reflection.
  float freeA = 0.0;
  for (int i = 1; i <= kLinearSteps; ++i) {
    float a = float(i) / float(kLinearSteps + 1);
    float f = behind(x, d, a);
    if (previousF >= 0.0 && f < 0.0) {
      if (first.x < 0.0) {
        first = vec4(previousA, previousF, a, f);
      } else if (second.x < 0.0) {
        second = vec4(previousA, previousF, a, f);
      }
    }
    if (f >= 0.0) freeA = a;
    previousA = a;
    previousF = f;
  }
  bool surface = false;
  if (first.x >= 0.0) {
    float frontA = first.x;
    vec3 p = refine(x, d, frontA, first.y, first.z, first.w, surface);
    if (surface) return p;
    if (second.x < 0.0) freeA = max(freeA, frontA);
  }
  if (second.x >= 0.0) {
    float frontA = second.x;
    vec3 p = refine(x, d, frontA, second.y, second.z, second.w, surface);
    if (surface) return p;
  }
  if (previousF >= 0.0) {
    // In front of the stored surface to the end of the search. A skybox is infinitely far: seen
    // along d itself. Anything nearer (the far plane's background, a floor 60 units off) is
    // looked up from where the search ended.
    vec3 last = pointAt(x, d, previousA);
    return previousF + length(last) >= kSkyDistance ? d : last;
  }
  return freeA > 0.0 ? pointAt(x, d, freeA) : d;
}

