// Per-fragment Phong with the course's constants (shading.glsl's phongShade); AMBIENT_PROBE: its
// ambient from the nearest live probe's irradiance (a probe-lit object in the main pass).
in vec3 v_worldPosition;
in vec3 v_worldNormal;

uniform vec3 u_colour;
uniform vec3 u_lightPosition;
uniform vec3 u_viewPosition;
uniform float u_ambient;
uniform float u_diffuse;
uniform float u_specular;
uniform float u_shininess;

#include "capture_output.glsl"
#include "shading.glsl"

#if AMBIENT_PROBE
// The nearest live probe's irradiance (irradiance_project.vert wrote it): E(n) / pi =
// sum c_i Y_i(n), c_i in .rgb, read at the probe's centre.
layout(std140) uniform ProbeIrradiance {
  vec4 u_irradiance[9];
};
// The probe's centre (xyz) and the object's ambientRadius (w; 0: none set, the parallax then comes
// from the probe's distances, mesh.vert's v_ambientParallax).
uniform vec4 u_irradianceProxy;
// What the point sees less what the centre sees (irradiance_parallax.glsl), 0 with a set radius.
in vec3 v_ambientParallax;

#include "irradiance.glsl"

// sum_i u_irradiance[i] Y_i(n): E(n) / pi.
vec3 probeLightAt(vec3 n) {
  vec4 a, b;
  float c;
  shBasisAll(n, a, b, c);
  return (u_irradiance[0] * a.x + u_irradiance[1] * a.y + u_irradiance[2] * a.z +
          u_irradiance[3] * a.w + u_irradiance[4] * b.x + u_irradiance[5] * b.y +
          u_irradiance[6] * b.z + u_irradiance[7] * b.w + u_irradiance[8] * c)
      .rgb;
}

// core/irradiance.h's irradianceDirection: the normal, or with a set radius the direction from the
// probe's centre to where the normal's ray leaves the sphere the surroundings are taken to lie on.
vec3 irradianceDirection(vec3 n) {
  float radius = u_irradianceProxy.w;
  if (radius <= 0.0) return n;
  vec3 o = v_worldPosition - u_irradianceProxy.xyz;
  float on = dot(o, n);
  float t = -on + sqrt(max(on * on - dot(o, o) + radius * radius, 0.0));
  vec3 d = o + max(t, 0.0) * n;
  float len = length(d);
  return len > 1e-6 ? d / len : n;
}

vec3 probeAmbient(vec3 normal) {
  return max(probeLightAt(irradianceDirection(normal)) + v_ambientParallax, vec3(0.0));
}
#endif

void main() {
  vec3 N = normalize(v_worldNormal);
  vec4 terms = vec4(u_ambient, u_diffuse, u_specular, u_shininess);
#if AMBIENT_PROBE
  vec3 colour = phongLit(u_colour, v_worldPosition, N, u_lightPosition, u_viewPosition,
                         probeAmbient(N), terms);
#else
  vec3 colour = phongShade(u_colour, v_worldPosition, N, u_lightPosition, u_viewPosition, terms);
#endif
  writeOutputs(colour, v_worldPosition, N, false);
}
