// Diffuse light's parallax (docs/rough.md, "Parallax from the probe's distances"): what a point of
// a probe-lit object sees about its normal, less what the probe's centre sees about the same
// normal. parallax_feedback.vert computes it once for each vertex of the mesh, and phong.frag
// adds it (mesh.vert's a_ambientParallax, interpolated) to the order-2 harmonics read at the
// centre. The harmonics keep the irradiance's shape; this difference only moves the light from
// where the centre sees it to where the point does, so the eight taps' own error (a fixed
// pattern of directions, a blurred level) is made twice, once each side, and mostly cancels.
// core/irradiance_parallax.h is the same in C++.

// The probe's captured colours, the distance d / (d + 1) in near-plane units in alpha (the sky's
// 1), through a trilinear sampler of the box mip chain.
uniform samplerCube u_parallaxCube;
// The probe's centre (xyz) and the capture's near plane (w).
uniform vec4 u_parallaxProbe;
// The mip levels the taps read their colours (x) and the distances (y) at: between 4 x 4 and 2 x 2
// texels a face for eight taps across a hemisphere, 16 x 16 for the distances (core/
// irradiance_parallax.h's parallaxLevels).
uniform vec2 u_parallaxLevels;

const int kParallaxTaps = 8;  // core/irradiance_parallax.h's
const int kParallaxSteps = 3;

// The distance to what the probe saw along u, in world units (the sky very far).
float parallaxDistance(vec3 u) {
  float a = textureLod(u_parallaxCube, u, u_parallaxLevels.y).a;
  if (a >= 0.999) return 1e6;
  return u_parallaxProbe.w * a / max(1.0 - a, 1e-3);
}

// Where the ray o + t w (o from the probe's centre) meets the surroundings the probe captured, as a
// direction from the centre: t found as the root of |o + t w| = distance(along o + t w), a few
// fixed-point steps from the distance along w itself.
vec3 parallaxSeen(vec3 o, vec3 w) {
  float t = parallaxDistance(w);
  for (int i = 0; i < kParallaxSteps; ++i) {
    float d = parallaxDistance(normalize(o + min(t, 1e4) * w));
    float ow = dot(o, w);
    t = -ow + sqrt(max(ow * ow - dot(o, o) + d * d, 0.0));
  }
  return normalize(o + min(t, 1e4) * w);
}

// E / pi at the point o (from the centre) less E / pi at the centre, both for normal n, from the
// same eight cosine-weighted directions (stratified in the sine squared of their angle from n,
// turned by the golden ratio).
vec3 irradianceParallax(vec3 o, vec3 n) {
  vec3 helper = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 tx = normalize(cross(helper, n));
  vec3 ty = cross(n, tx);
  vec3 shift = vec3(0.0);
  for (int k = 0; k < kParallaxTaps; ++k) {
    float u1 = (float(k) + 0.5) / float(kParallaxTaps);
    float phi = 6.2831853 * fract(float(k) * 0.618034);
    float r = sqrt(u1);
    vec3 w = r * cos(phi) * tx + r * sin(phi) * ty + sqrt(max(1.0 - u1, 0.0)) * n;
    shift += textureLod(u_parallaxCube, parallaxSeen(o, w), u_parallaxLevels.x).rgb -
             textureLod(u_parallaxCube, w, u_parallaxLevels.x).rgb;
  }
  return shift / float(kParallaxTaps);
}
