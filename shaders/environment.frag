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
// depth_search.glsl (those three in environment_lookup.glsl), SEARCH_EXACT no lookup at all: the
// ray traced by exact_shade.glsl. Each defines what main() calls, seenReflected() and
// seenThroughGlass(); the mix is shading.glsl's, the same for every search. A reflector that needs no search (a skybox environment, or a probe whose
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
uniform int u_outputDirection; // 1: write the looked-up direction instead (for measuring), its
                               // alpha saying whose: 2 a cube lookup, 3 a traced ray
                               // (core/face_use.h kLookupMark*: the face-use view reads them);
                               // 2: write `measured` as it is (the search's landing point)


#include "capture_output.glsl"
#include "shading.glsl"
#if ROUGH == 1
// Here, not only where exact_shade.glsl needs it: a file is included once a program, where it is
// first named.
#include "ggx.glsl"
uniform float u_roughAlpha;  // a rough mirror's lobe alpha (core/ggx.h ggxAlpha)
#endif
#include "glass_sphere_exit.glsl"
#include "environment_lookup.glsl"
#include "exact_shade.glsl"

void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_viewPosition);
  float schlick = schlickWeight(u_fresnelF0, -I, N);
  bool fresnel = u_fresnel == 1;
  vec3 measured;
  vec3 colour;
#if REFRACTS == 1
  vec3 T = refract(I, N, u_eta);
  bool total = dot(T, T) == 0.0;  // past the critical angle refract() returns a zero vector
  vec3 reflected, refracted;
  seenThroughGlass(v_worldPosition, I, N, T, total, reflected, refracted, measured);
  colour = blended(glassBlend(u_colour, reflected, total, u_reflectionWeight, u_baseWeight,
                              fresnel, schlick),
                   refracted);
#else
  vec3 R = reflect(I, N);
#if ROUGH == 1 && SEARCH != SEARCH_EXACT
  // A prefiltered lookup reads the lobe where its mass is (core/ggx.h); traced rays need no fit.
  R = specularDominantDirection(N, R, u_roughAlpha);
#endif
  vec3 reflected = seenReflected(v_worldPosition, R, measured);
  colour = blended(mirrorBlend(u_colour, u_reflectionWeight, u_baseWeight, fresnel, schlick),
                   reflected);
#endif
  if (u_outputDirection == 1) colour = normalize(measured);
  if (u_outputDirection == 2) colour = measured;
  writeOutputs(colour, v_worldPosition, N, false);
#if SEARCH == SEARCH_EXACT && CAPTURE_OUTPUT == 0
  if (u_exactMark == 1) fragColour.a = 0.0;
#endif
  // A float target keeps alphas past 1; the lookup-direction pass always draws into one.
  if (u_outputDirection == 1) fragColour.a = SEARCH == SEARCH_EXACT ? 3.0 : 2.0;
}
