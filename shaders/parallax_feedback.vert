// The parallax taps (irradiance_parallax.glsl) once for each vertex of a probe-lit mesh, drawn as
// points with the rasteriser off: transform feedback writes each vertex's v_parallax into a buffer
// that mesh.vert then reads as its a_ambientParallax. A software rasteriser shades a vertex shared
// by several triangles more than once in the main pass; the taps, its costliest part, run here
// once a vertex.
// (#version and precision are prepended by ShaderProgram.)
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat3 u_normalMatrix;  // inverse-transpose of u_model's upper 3x3

out vec3 v_parallax;

#include "irradiance_parallax.glsl"

void main() {
  vec3 world = (u_model * vec4(a_position, 1.0)).xyz;
  v_parallax = irradianceParallax(world - u_parallaxProbe.xyz, normalize(u_normalMatrix * a_normal));
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
