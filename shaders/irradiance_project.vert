// Projects a probe's captured cube on the order-2 spherical harmonics (irradiance.glsl): vertex i
// (of nine, drawn with the rasteriser off) writes coefficient i, which transform feedback stores
// in the probe's irradiance buffer, read by phong.frag as a uniform block (AMBIENT_PROBE). No
// read-back: the coefficients stay on the GPU.
// The cube is read at the mip level whose faces are u_grid texels square (8 for the usual face
// sizes: the box chain the capture generated), one texel centre a sample, each weighed by the solid angle it spans,
// dw ~ (2 / grid)^2 / (1 + s^2 + t^2)^(3/2); the weights are then scaled to sum to 4 pi.
// The coefficient's w is unused (0): std140 lays a vec3 array out as vec4s anyway.
// (#version and precision are prepended by ShaderProgram.)
uniform samplerCube u_probe;
uniform float u_lod;
uniform int u_grid;

out vec4 v_coefficient;

#include "irradiance.glsl"

// A direction of face f (GL order +X, -X, +Y, -Y, +Z, -Z) at face coordinates (s, t) in
// [-1, 1]. Each face's square is covered once; which way s and t run on it does not matter to a
// sum over the whole sphere.
vec3 faceDirection(int f, float s, float t) {
  if (f == 0) return vec3(1.0, t, s);
  if (f == 1) return vec3(-1.0, t, s);
  if (f == 2) return vec3(s, 1.0, t);
  if (f == 3) return vec3(s, -1.0, t);
  if (f == 4) return vec3(s, t, 1.0);
  return vec3(s, t, -1.0);
}

void main() {
  int i = gl_VertexID;
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  float step = 2.0 / float(u_grid);
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < u_grid; ++y) {
      float t = -1.0 + (float(y) + 0.5) * step;
      for (int x = 0; x < u_grid; ++x) {
        float s = -1.0 + (float(x) + 0.5) * step;
        vec3 d = faceDirection(f, s, t);
        float r2 = 1.0 + s * s + t * t;
        float w = 1.0 / (r2 * sqrt(r2));
        vec3 n = d * inversesqrt(r2);
        sum += w * shBasis(n, i) * textureLod(u_probe, d, u_lod).rgb;
        weights += w;
      }
    }
  }
  float scale = 4.0 * 3.14159265 / weights * shBandFactor(i);
  v_coefficient = vec4(sum * scale, 0.0);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
