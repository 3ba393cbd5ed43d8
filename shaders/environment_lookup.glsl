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

// The colour the environment shows for the ray from world point `origin` along `d`, and in
// `direction` the direction it was looked up along.
vec3 environmentAlong(vec3 origin, vec3 d, out vec3 direction) {
  direction = d;
#if SEARCH == SEARCH_LINEAR
  direction = linearSearch(origin, d);
#elif SEARCH == SEARCH_HIERARCHICAL
  SearchResult found = searchDepths((origin - u_probeCentre) / u_distanceUnit, d);
  if (found.layer != 0) {
    direction = found.point;
    return surfaceColour(found.point, found.layer);
  }
#endif
  return texture(u_environment, direction).rgb;
}

// Glass seen through both surfaces: the refracted ray crosses the sphere and leaves it at the
// far side, refracted again (n to air). Inside a sphere a ray meets the far side at the angle it
// entered, so it always leaves; the loop covers the total internal reflection other shapes would
// have. `origin` and `d` become the leaving ray.
void leaveGlassSphere(inout vec3 origin, inout vec3 d) {
  vec3 centre = u_glassSphere.xyz;
  for (int bounce = 0; bounce < 4; ++bounce) {
    vec3 offset = origin - centre;
    float b = dot(offset, d);
    float c = dot(offset, offset) - u_glassSphere.w * u_glassSphere.w;
    float t = -b + sqrt(max(b * b - c, 0.0));  // the far root: the ray starts on the surface
    origin += t * d;
    vec3 inward = -normalize(origin - centre);
    vec3 out_ = refract(d, inward, 1.0 / u_eta);
    if (dot(out_, out_) > 0.0) {
      d = out_;
      return;
    }
    d = reflect(d, inward);
  }
}

#if ROUGH == 1
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
  vec3 seen = environmentAlong(origin, R, measured);
#if ROUGH == 1
  seen = roughSeen(seen, measured, u_roughLod);
#endif
  return seen;
}

// Glass at `origin` (view ray I, normal N, refracted ray T, `total` where T is zero): what the
// reflected ray sees, and what the refracted one sees once out of the object (the reflected
// one's at total internal reflection, where all the light is reflected: a zero vector is no
// direction to look a cube map up along). `measured`: the direction of the last lookup. Rough
// (frosted) glass reads both from the prefiltered levels: the reflection as a rough mirror's, the
// light through around the ray refracted by the smooth surface, at its own, narrower level.
void seenThroughGlass(vec3 origin, vec3 I, vec3 N, vec3 T, bool total, out vec3 reflected,
                      out vec3 refracted, out vec3 measured) {
  vec3 R = reflect(I, N);
#if ROUGH == 1
  R = specularDominantDirection(N, R, u_roughAlpha);
#endif
  reflected = environmentAlong(origin, R, measured);
#if ROUGH == 1
  reflected = roughSeen(reflected, measured, u_roughLod);
#endif
  refracted = reflected;
  if (total) return;
  vec3 exitPoint = origin;
#if GLASS_EXIT == 1
  if (u_twoSurfaces == 1) leaveGlassMesh(exitPoint, T);
#else
  if (u_twoSurfaces == 1) leaveGlassSphere(exitPoint, T);
#endif
  refracted = environmentAlong(exitPoint, T, measured);
#if ROUGH == 1
  refracted = roughSeen(refracted, measured, u_refractLod);
#endif
}
#endif
