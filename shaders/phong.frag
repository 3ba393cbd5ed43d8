// Per-fragment Phong with the course's constants (shading.glsl's phongShade).
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

void main() {
  vec3 N = normalize(v_worldNormal);
  vec4 terms = vec4(u_ambient, u_diffuse, u_specular, u_shininess);
  vec3 colour = phongShade(u_colour, v_worldPosition, N, u_lightPosition, u_viewPosition, terms);
  writeOutputs(colour, v_worldPosition, N, false);
}
