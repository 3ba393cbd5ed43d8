// What a mirror or glass pixel sees when its environment is a cube map (a live probe or the static
// skybox): every search but SEARCH_EXACT, whose rays exact_shade.glsl traces instead. Both files
// define the two functions environment.frag's main() calls, seenReflected() and
// seenThroughGlass(), so main() is one for every search. Only the search the program was built
// with is compiled in (the includes below sit inside its #if).
#if SEARCH != SEARCH_EXACT
#if SEARCH == SEARCH_LINEAR
#include "linear_search.glsl"
#elif SEARCH == SEARCH_HIERARCHICAL
#include "depth_search.glsl"
#endif
#include "glass_exit.glsl"

#if SEARCH == SEARCH_HIERARCHICAL
// The colour a probe stored around `p` (relative to its centre) in `layer`: the four nearest
// texels of its face, weighed bilinearly, but only those that hold the same surface (a depth
// within kThickness of p's): at a figure's outline the figure's texels do not bleed into the
// floor beside it, nor the floor's into the figure.
vec3 surfaceColour(vec3 p, int layer) {
  int f = faceOf(p);
  vec3 right = u_faceRight[f], up = u_faceUp[f], axis = u_faceAxis[f];
  float z = dot(p, axis);
  vec2 st = vec2(dot(p, right), dot(p, up)) / z;
  float n = float(u_faceSize);
  vec2 texel = (st * 0.5 + 0.5) * n - 0.5;
  ivec2 first = ivec2(floor(texel));
  vec2 w = texel - vec2(first);
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      ivec2 t = clamp(first + ivec2(i, j), ivec2(0), ivec2(u_faceSize - 1));
      uvec4 codes = cellCodes(t, f, 0);
      uint code = layer == 2 ? codes.b : codes.r;
      float weight = (i == 0 ? 1.0 - w.x : w.x) * (j == 0 ? 1.0 - w.y : w.y);
      if (abs(decodeDepth(code) - z) > kThickness * z) weight = 0.0;
      vec2 centre = (vec2(t) + 0.5) / n * 2.0 - 1.0;
      vec3 direction = axis + centre.x * right + centre.y * up;
      vec3 c = layer == 2 ? texture(u_environment2, direction).rgb
                          : texture(u_environment, direction).rgb;
      sum += weight * c;
      total += weight;
    }
  }
  if (total > 0.0) return sum / total;
  return layer == 2 ? texture(u_environment2, p).rgb : texture(u_environment, p).rgb;
}
#endif

// The colour the environment shows for the ray from world point `origin` along `d`; in
// `direction` the direction it was looked up along, and in `hitDistance` how far from `origin`
// the search met a stored surface (world units; -1 where it met none or does not search).
vec3 environmentMet(vec3 origin, vec3 d, out vec3 direction, out float hitDistance) {
  direction = d;
  hitDistance = -1.0;
#if SEARCH == SEARCH_LINEAR
  direction = linearSearch(origin, d);
#elif SEARCH == SEARCH_HIERARCHICAL
  SearchResult found = searchDepths((origin - u_probeCentre) / u_distanceUnit, d);
  if (found.layer != 0) {
    direction = found.point;
    hitDistance = length(u_probeCentre + found.point * u_distanceUnit - origin);
    return surfaceColour(found.point, found.layer);
  }
#endif
  return texture(u_environment, direction).rgb;
}

vec3 environmentAlong(vec3 origin, vec3 d, out vec3 direction) {
  float hitDistance;
  return environmentMet(origin, d, direction, hitDistance);
}

// Where a ray refracted into glass at `origin` leaves it: through the far side (the sphere's closed
// form, or the interior map with GLASS_EXIT 1) where both surfaces are drawn, else at once.
void leaveGlass(inout vec3 origin, inout vec3 d) {
#if GLASS_EXIT == 1
  if (u_twoSurfaces == 1) leaveGlassMesh(origin, d);
#else
  if (u_twoSurfaces == 1) leaveGlassSphere(origin, d);
#endif
}

#if ROUGH == 1 && ROUGH_TAPS == 1
// Rough mirrors and frosted glass reading a live probe (docs/rough.md, "Lobe taps"): the lobe is
// sampled where the pixel sees it, for its real view, from the capture's own box chain.
uniform samplerCube u_lobeSource;  // the probe's colour cube with its box chain, read trilinearly
uniform int u_lobeTaps;            // AccuracySettings::lobeTaps
uniform float u_refractAlpha;      // rough glass: the light through's lobe alpha (core/ggx.h
                                   // transmissionRoughness, squared)

// The taps read a level this much finer than their share of the lobe covers: the box chain's
// texels are wider than a GGX tap's footprint (measured on rough-spheres at t = 1.5 and 3.5 s,
// 16 taps: -1, -0.5, -0.25, 0, 0.5, 1 and 1.5 tried; -0.5 best at roughness 0.75 and 1, within
// 0.2 dB of the best elsewhere).
const float kLobeTapLodBias = -0.5;
// One tap for a whole lobe of alpha reads level log2(faceTexels alpha sqrt(6)): there a texel's
// solid angle, 4 pi / (6 faceTexels^2), is the lobe's at its peak, 1 / pdf(h = n) = 4 pi alpha^2.
const float kLobeWidthTexels = 2.449;

// The box-chain level a lobe sample reads: the one whose texel covers its `share` of the lobe
// (steradians), kLobeTapLodBias finer; unclamped.
float lobeSampleLevel(float share, float texelSolidAngle) {
  return 0.5 * log2(share / texelSolidAngle) + kLobeTapLodBias;
}

// One lobe tap along l (its `share` of the lobe, steradians) read from the box chain: towards the
// point hitDistance along it from `offset` (relative to the probe centre, world units), its
// footprint shrunk as the probe centre sees that point from farther away; along l where
// hitDistance <= 0 (nothing met).
vec3 tapSeen(vec3 offset, vec3 l, float hitDistance, float share, float texelSolidAngle) {
  vec3 towards = l;
  if (hitDistance > 0.0) {
    towards = offset + l * hitDistance;
    share *= hitDistance * hitDistance / dot(towards, towards);
  }
  float lod = max(lobeSampleLevel(share, texelSolidAngle), 0.0);
  return textureLod(u_lobeSource, towards, lod).rgb;
}

#if SEARCH == SEARCH_HIERARCHICAL && CAPTURE_OUTPUT == 0
// A wide lobe's quarter spans tens of degrees, and a tap far from its median ray can miss what
// that ray met: where the median ray passes a neighbour's outline, every tap of the quarter jumps
// from the neighbour to the wall behind it at once, a sharp arc across the roughness-1 sphere
// (docs/rough.md, "Each quarter searched"). So on lobes wider than WIDE_LOBE_ALPHA (core
// kWideLobeAlpha) each tap checks its quarter's point and the central ray's point against the
// depths the probe stored around them, at the tap's own level, and blends towards the central
// point by how much better the depths hold it: a blend, not a choice, so it varies smoothly from
// pixel to pixel. Fully from alpha 1; kDepthCheckSlack (relative depth) keeps two points that
// both nearly fit from swinging the blend. On narrower lobes the check measured a loss (0.5 dB
// at roughness 0.5, t = 1.5 and 3.5 s): there a quarter's taps lie close to its median ray.
const float kDepthCheckSlack = 0.1;

// The tap along l, from `offset`, taken to meet the scene `quarter` away (its quarter's search),
// or `central` away (the central ray's), blended as above.
vec3 tapSeenChecked(vec3 offset, vec3 l, float quarter, float central, float alpha, float share,
                    float texelSolidAngle) {
  vec3 seen = tapSeen(offset, l, quarter, share, texelSolidAngle);
  if (quarter == central || alpha <= float(WIDE_LOBE_ALPHA)) return seen;
  int level = clamp(int(lobeSampleLevel(share, texelSolidAngle)), 0, u_topLevel);
  vec3 far = l * 1e4;  // nothing met: a point far along l
  vec3 quarterPoint = quarter > 0.0 ? (offset + l * quarter) / u_distanceUnit : far;
  vec3 centralPoint = central > 0.0 ? (offset + l * central) / u_distanceUnit : far;
  float quarterOff = storedDepthMismatch(quarterPoint, level);
  if (quarterOff <= 0.0) return seen;  // the depths hold the quarter's point: nothing to blend
  float centralOff = storedDepthMismatch(centralPoint, level);
  float wide = min((alpha - float(WIDE_LOBE_ALPHA)) / (1.0 - float(WIDE_LOBE_ALPHA)), 1.0);
  float towardsCentral =
      wide * clamp((quarterOff - centralOff) / (quarterOff + centralOff + kDepthCheckSlack), 0.0,
                   1.0);
  if (towardsCentral <= 0.0) return seen;
  return mix(seen, tapSeen(offset, l, central, share, texelSolidAngle), towardsCentral);
}
#endif

// The lobe of alpha around normal n, seen from direction v, at world point `origin`: sum(w L) /
// sum(w) over u_lobeTaps fixed Hammersley half vectors (core/ggx.h's weights, as the exact mode's
// lobe rays and the reference), each tap read from the box chain at the level whose texel covers
// its share of the lobe, 1 / (taps pdf) (filtered importance sampling). `quarterDistance` (world
// units; <= 0: nothing met) is how far from `origin` each quarter of the lobe (by azimuth around
// n: the Hammersley set's taps in order) meets the scene, `central` how far the central ray does:
// every tap of a quarter is taken to meet it as far away (on a wide lobe, checked against the
// central ray's distance: tapSeenChecked), so it is looked up from the probe centre towards that
// point.
vec3 lobeSeen(vec3 origin, vec3 n, vec3 v, float alpha, vec4 quarterDistance, float central) {
  float faceTexels = float(textureSize(u_lobeSource, 0).x);
  float texelSolidAngle = 4.0 * kGgxPi / (6.0 * faceTexels * faceTexels);
  float nDotV = max(dot(n, v), 0.0);
  mat3 frame = frameAround(n);
  vec3 offset = origin - u_probeCentre;
  uint taps = uint(max(u_lobeTaps, 1));
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (uint k = 0u; k < taps; ++k) {
    float nDotH;
    vec3 h = ggxHalfVectorInFrame(hammersley(k, taps), alpha, frame, nDotH);
    vec3 l = reflect(-v, h);
    float vDotH = dot(v, h);
    float w = lobeSampleWeight(nDotV, dot(n, l), nDotH, vDotH, alpha);
    if (w <= 0.0) continue;
    // The tap's share of the lobe: its density is D (n.h) / (4 v.h) over directions l.
    float share = 4.0 * vDotH / (float(taps) * ggxDistribution(nDotH, alpha) * nDotH);
    float hitDistance = quarterDistance[k * 4u / taps];
#if SEARCH == SEARCH_HIERARCHICAL && CAPTURE_OUTPUT == 0
    vec3 seen = tapSeenChecked(offset, l, hitDistance, central, alpha, share, texelSolidAngle);
#else
    vec3 seen = tapSeen(offset, l, hitDistance, share, texelSolidAngle);
#endif
    sum += w * seen;
    weights += w;
  }
  // No lobe above the surface (seen edge on): what the central ray met.
  return weights > 0.0 ? sum / weights : textureLod(u_lobeSource, reflect(-v, n), 0.0).rgb;
}

#if SEARCH == SEARCH_HIERARCHICAL && CAPTURE_OUTPUT == 0
// How far a rough mirror's lobe meets the scene, searched: first along its dominant direction R
// (to one texel, as a sharp mirror's ray; in `measured` the direction it was looked up along),
// then once per quarter of the lobe, from its median half vector, down only to the level
// kQuarterSearchLevels finer than the quarter's footprint and for at most kQuarterSearchSteps
// steps: a coarse cell's nearest surface is where a blurred quarter mostly lands. One distance
// for the whole lobe (the central ray's) puts every tap on the object the centre meets; at
// roughness 0.5 on rough-spheres the taps then draw a neighbour's reflection where the lobe has
// passed it (docs/rough.md, "Each quarter searched"). A quarter that runs out of steps keeps the
// central distance. One loop for all five, so the search's code is inlined once.
const int kQuarterSearchLevels = 4;
const int kQuarterSearchSteps = 16;
uniform int u_lobeQuarters;  // AccuracySettings::lobeQuarters: 0, the central distance for all

vec4 lobeDistances(vec3 origin, vec3 n, vec3 v, vec3 R, float alpha, out vec3 measured,
                   out float central) {
  float faceTexels = float(textureSize(u_lobeSource, 0).x);
  float texelSolidAngle = 4.0 * kGgxPi / (6.0 * faceTexels * faceTexels);
  mat3 frame = frameAround(n);
  vec3 offset = origin - u_probeCentre;
  central = -1.0;
  vec4 quarters;  // each the central distance until its own search finds one
  measured = R;
  for (int q = 0; q <= 4 * u_lobeQuarters; ++q) {
    vec3 d = R;
    int finest = 0;
    int steps = kMaxSteps;
    if (q > 0) {
      float nDotH;
      vec3 h = ggxHalfVectorInFrame(vec2((float(q) - 0.5) / 4.0, 0.5), alpha, frame, nDotH);
      d = reflect(-v, h);
      float vDotH = max(dot(v, h), 1e-4);
      float share = vDotH / (ggxDistribution(nDotH, alpha) * nDotH);  // 1 / (4 pdf)
      finest = max(int(lobeSampleLevel(share, texelSolidAngle)) - kQuarterSearchLevels, 0);
      steps = kQuarterSearchSteps;
    }
    SearchResult found = searchDepthsTo(offset / u_distanceUnit, d, finest, steps);
    float met = found.layer > 0 ? length(found.point * u_distanceUnit - offset) : -1.0;
    if (q == 0) {
      central = met;
      quarters = vec4(central);
      if (found.layer > 0) measured = found.point;
    } else {
      quarters[q - 1] = found.layer < 0 ? central : met;
    }
  }
  return quarters;
}
#endif

// A rough reflector drawn into another probe's capture is a second bounce, seen small: one tap
// along its lobe's dominant direction `d`, at the level the whole lobe covers.
vec3 lobeSeenOnce(vec3 d, float alpha) {
  float faceTexels = float(textureSize(u_lobeSource, 0).x);
  return textureLod(u_lobeSource, d, log2(max(faceTexels * alpha * kLobeWidthTexels, 1.0))).rgb;
}

#if CAPTURE_OUTPUT == 0
// The view ray I refracted into frosted glass through microfacet normal h (the surface's normal n),
// in `exitPoint` and `t` where it leaves the object; false where it cannot enter there (total
// reflection at h, or a refracted ray that does not point into the object).
bool leftThroughMicrofacet(vec3 origin, vec3 I, vec3 h, vec3 n, out vec3 exitPoint, out vec3 t) {
  t = refract(I, h, u_eta);
  exitPoint = origin;
  if (dot(t, t) == 0.0 || dot(t, n) >= 0.0) return false;
  t = normalize(t);
  leaveGlass(exitPoint, t);
  return true;
}

#if SEARCH == SEARCH_HIERARCHICAL
// How far frosted glass's light through meets the scene, a distance for each quarter of its lobe
// (as a mirror's quarters, lobeDistances): the view ray refracted through the quarter's median
// half vector, out of the object, searched from where it leaves, down only to kQuarterSearchLevels
// finer than the light through's lobe and for at most kQuarterSearchSteps steps. A quarter that
// runs out of steps, or cannot enter, keeps `central`, the distance the smooth surface's refracted
// ray found; one that meets nothing stored looks along its rays (-1). Without it a figure just
// behind the glass is drawn by every tap or by none, as the central ray meets it or not
// (docs/rough.md, "The near plane").
vec4 transmittedDistances(vec3 origin, vec3 I, vec3 n, float central) {
  vec4 quarters = vec4(central);
  if (u_lobeQuarters == 0) return quarters;
  float faceTexels = float(textureSize(u_lobeSource, 0).x);
  float lod = log2(max(faceTexels * u_refractAlpha * kLobeWidthTexels, 1.0)) + kLobeTapLodBias;
  int finest = max(int(lod) - kQuarterSearchLevels, 0);
  mat3 frame = frameAround(n);
  for (int q = 0; q < 4; ++q) {
    float nDotH;
    vec3 h = ggxHalfVectorInFrame(vec2((float(q) + 0.5) / 4.0, 0.5), u_roughAlpha, frame, nDotH);
    vec3 exitPoint, t;
    if (!leftThroughMicrofacet(origin, I, h, n, exitPoint, t)) continue;
    vec3 offset = exitPoint - u_probeCentre;
    SearchResult found = searchDepthsTo(offset / u_distanceUnit, t, finest, kQuarterSearchSteps);
    if (found.layer >= 0)
      quarters[q] = found.layer > 0 ? length(found.point * u_distanceUnit - offset) : -1.0;
  }
  return quarters;
}
#endif

// Frosted glass's light through (core/ggx.h says what it is): the mean, over u_lobeTaps of the
// lobe's microfacet normals h around n (the Hammersley set), of what the view ray I refracted
// through h sees once out of the object (its far side crossed as polished glass), each read from
// the box chain at the level its share of the light through covers (transmissionRoughness's
// lobe, split among the taps), towards where its quarter's search met the scene (hitDistances,
// from the exit; transmittedDistances). A normal the ray cannot enter through is left out; none:
// `central`, what the smooth surface's refracted ray sees.
vec3 transmittedTaps(vec3 origin, vec3 I, vec3 n, vec4 hitDistances, vec3 central) {
  float faceTexels = float(textureSize(u_lobeSource, 0).x);
  uint taps = uint(max(u_lobeTaps, 1));
  float lod = log2(max(faceTexels * u_refractAlpha * kLobeWidthTexels, 1.0)) -
              0.5 * log2(float(taps)) + kLobeTapLodBias;
  mat3 frame = frameAround(n);
  vec3 sum = vec3(0.0);
  float rays = 0.0;
  for (uint k = 0u; k < taps; ++k) {
    float nDotH;
    vec3 h = ggxHalfVectorInFrame(hammersley(k, taps), u_roughAlpha, frame, nDotH);
    vec3 exitPoint, t;
    if (!leftThroughMicrofacet(origin, I, h, n, exitPoint, t)) continue;
    float hitDistance = hitDistances[k * 4u / taps];
    vec3 towards = hitDistance > 0.0 ? exitPoint - u_probeCentre + t * hitDistance : t;
    sum += textureLod(u_lobeSource, towards, max(lod, 0.0)).rgb;
    rays += 1.0;
  }
  return rays > 0.0 ? sum / rays : central;
}
#endif

// What a rough surface at `origin` with normal n, seen from the view direction v, reflects (R:
// its lobe's dominant direction; hitDistance: how far the search's ray along R went).
vec3 roughReflected(vec3 origin, vec3 n, vec3 v, vec3 R, float alpha, float hitDistance) {
#if CAPTURE_OUTPUT == 1
  return lobeSeenOnce(R, alpha);
#else
  return lobeSeen(origin, n, v, alpha, vec4(hitDistance), hitDistance);
#endif
}
#elif ROUGH == 1
uniform samplerCube u_prefiltered;  // the probe's rough levels (gfx/probe_prefilter.h)
uniform float u_roughLod;    // roughness x roughLevels: the rough level the reflection reads
uniform float u_refractLod;  // rough glass: the level the light through reads (core/ggx.h
                             // transmissionRoughness x roughLevels)

// A rough lobe read from the probe's prefiltered levels around `centre`, the direction the search
// looked up along (so the distance correction moves the lobe's centre; its width stays as seen
// from the probe centre), at rough level `lod`. Between rough levels 0 and 1 the sharp view the
// search found (`sharp`, level 0: the capture itself) blends with level 1; above, the filtered
// cube's own trilinear filtering blends the two levels around `lod` (its mip i is rough level
// i + 1). Both reads always run: no branch for a software rasteriser to pay twice.
vec3 roughSeen(vec3 sharp, vec3 centre, float lod) {
  vec3 first = textureLod(u_prefiltered, centre, 0.0).rgb;
  vec3 above = textureLod(u_prefiltered, centre, max(lod - 1.0, 0.0)).rgb;
  return lod < 1.0 ? mix(sharp, first, lod) : above;
}
#endif

// The mirror's reflected ray from `origin` along `R`: what it sees, and in `measured` the
// direction it was looked up along.
vec3 seenReflected(vec3 origin, vec3 R, out vec3 measured) {
#if ROUGH == 1 && ROUGH_TAPS == 1
  vec3 v = normalize(u_viewPosition - origin);
  vec3 n = normalize(v_worldNormal);
  if (dot(n, v) < 0.0) n = -n;  // both sides of a triangle are shaded alike
#if SEARCH == SEARCH_HIERARCHICAL && CAPTURE_OUTPUT == 0
  float central;
  vec4 quarterDistance = lobeDistances(origin, n, v, R, u_roughAlpha, measured, central);
  return lobeSeen(origin, n, v, u_roughAlpha, quarterDistance, central);
#endif
#endif
  float hitDistance;
  vec3 seen = environmentMet(origin, R, measured, hitDistance);
#if ROUGH == 1 && ROUGH_TAPS == 1
  seen = roughReflected(origin, n, v, R, u_roughAlpha, hitDistance);
#elif ROUGH == 1
  seen = roughSeen(seen, measured, u_roughLod);
#endif
  return seen;
}

// Glass at `origin` (view ray I, normal N, refracted ray T, `total` where T is zero): what the
// reflected ray sees, and what the refracted one sees once out of the object (the reflected
// one's at total internal reflection, where all the light is reflected: a zero vector is no
// direction to look a cube map up along). `measured`: the direction of the last lookup. Rough
// (frosted) glass blurs both: the reflection as a rough mirror's, the light through around the
// ray refracted by the smooth surface, narrower (core/ggx.h transmissionRoughness); from lobe taps
// (the light through as a lobe seen along its own axis) or from the prefiltered levels.
void seenThroughGlass(vec3 origin, vec3 I, vec3 N, vec3 T, bool total, out vec3 reflected,
                      out vec3 refracted, out vec3 measured) {
  vec3 R = reflect(I, N);
#if ROUGH == 1
  R = specularDominantDirection(N, R, u_roughAlpha);
#endif
  float hitDistance;
  reflected = environmentMet(origin, R, measured, hitDistance);
#if ROUGH == 1 && ROUGH_TAPS == 1
  reflected = roughReflected(origin, N, -I, R, u_roughAlpha, hitDistance);
#elif ROUGH == 1
  reflected = roughSeen(reflected, measured, u_roughLod);
#endif
  refracted = reflected;
  if (total) return;
  vec3 exitPoint = origin;
  leaveGlass(exitPoint, T);
  refracted = environmentMet(exitPoint, T, measured, hitDistance);
#if ROUGH == 1 && ROUGH_TAPS == 1 && CAPTURE_OUTPUT == 1
  refracted = lobeSeenOnce(T, u_refractAlpha);
#elif ROUGH == 1 && ROUGH_TAPS == 1
#if SEARCH == SEARCH_HIERARCHICAL
  vec4 distances = transmittedDistances(origin, I, N, hitDistance);
#else
  vec4 distances = vec4(hitDistance);
#endif
  refracted = transmittedTaps(origin, I, N, distances, refracted);
#elif ROUGH == 1
  refracted = roughSeen(refracted, measured, u_refractLod);
#endif
}
#endif
