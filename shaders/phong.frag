// Per-fragment Phong with the course's constants (ambient and diffuse take the object colour,
// white specular only where the light reaches the front of the surface).
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

void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 L = normalize(u_lightPosition - v_worldPosition);
  vec3 V = normalize(u_viewPosition - v_worldPosition);
  float nDotL = max(dot(N, L), 0.0);
  vec3 colour = u_colour * (u_ambient + u_diffuse * nDotL);
  if (nDotL > 0.0) {
    vec3 R = reflect(-L, N);
    colour += vec3(u_specular * pow(clamp(dot(R, V), 0.0, 1.0), u_shininess));
  }
  writeOutputs(colour, v_worldPosition, N, false);
}
