// Mirror and glass: the environment (live probe or static skybox) looked up along the reflected
// or refracted view ray, mixed with the base colour. The course's mirror is the fixed mix
// 0.78 x environment + 0.3 x base (the weights sum past 1, so bright reflections clip to white);
// with Fresnel on, Schlick's approximation weighs reflection against the base (mirror) or against
// refraction (glass) instead.
//
// Where a ray meets the live probe's surroundings is found by the search SEARCH picks when the
// program is built (src/gfx/program_key.h; a runtime switch would not do: software rasterisers
// run both sides of a branch): SEARCH_PLAIN the course's lookup along the ray's direction,
// SEARCH_LINEAR the linear search of linear_search.glsl, SEARCH_HIERARCHICAL the walk of
// depth_search.glsl, SEARCH_EXACT no lookup at all: the ray traced by exact_trace.glsl (one hook
// at the top of main). A reflector that needs no search (a skybox environment, or a probe whose
// surroundings are all far enough that the plain lookup is within half a texel) is drawn with
// the SEARCH_PLAIN program.
in vec3 v_worldPosition;
in vec3 v_worldNormal;

uniform vec3 u_colour;
uniform vec3 u_viewPosition;
uniform float u_reflectionWeight;
uniform float u_baseWeight;
uniform float u_eta;          // n1 / n2 for refract(): air to the material
uniform float u_fresnelF0;    // ((n - 1) / (n + 1))^2
uniform int u_fresnel;        // 0 fixed mix, 1 Schlick
uniform int u_twoSurfaces;    // glass: 1 refracts in and out (of u_glassSphere, or with
                              // GLASS_EXIT 1 its interior map: glass_exit.glsl), 0 at entry only
uniform vec4 u_glassSphere;   // world centre and radius of the glass object, for its exit
uniform samplerCube u_environment;
uniform samplerCube u_environment2;  // the probe's second layer (depth_search.glsl, 2 layers)
uniform vec3 u_probeCentre;
uniform float u_distanceUnit;  // the capture's near plane (depths are stored in its units)
uniform int u_outputDirection; // 1: write the looked-up direction instead (for measuring)

#include "capture_output.glsl"
#include "linear_search.glsl"
#include "depth_search.glsl"
#include "exact_trace.glsl"
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

void main() {
#if SEARCH == SEARCH_EXACT  // hook: the exact mode traces every ray instead (exact_trace.glsl)
  exactMain();
  return;
#endif
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_viewPosition);
  vec3 reflectedDirection;
  vec3 reflected = environmentAlong(v_worldPosition, reflect(I, N), reflectedDirection);
  float schlick = u_fresnelF0 + (1.0 - u_fresnelF0) * pow(1.0 - clamp(dot(-I, N), 0.0, 1.0), 5.0);
  vec3 colour;
  vec3 measured = reflectedDirection;
#if REFRACTS == 1
  vec3 T = refract(I, N, u_eta);
  // Past the critical angle refract() returns a zero vector, and sampling a cube map with it is
  // undefined: all the light is reflected there.
  bool total = dot(T, T) == 0.0;
  vec3 refracted = reflected;
  if (!total) {
    vec3 origin = v_worldPosition;
#if GLASS_EXIT == 1
    if (u_twoSurfaces == 1) leaveGlassMesh(origin, T);
#else
    if (u_twoSurfaces == 1) leaveGlassSphere(origin, T);
#endif
    refracted = environmentAlong(origin, T, measured);
  }
  colour = u_fresnel == 1 ? mix(refracted, reflected, total ? 1.0 : schlick)
                          : u_reflectionWeight * refracted + u_baseWeight * u_colour;
#else
  colour = u_fresnel == 1 ? mix(u_colour, reflected, schlick)
                          : u_reflectionWeight * reflected + u_baseWeight * u_colour;
#endif
  if (u_outputDirection == 1) colour = normalize(measured);
  writeOutputs(colour, v_worldPosition, N, false);
}
