// One face of one rough level of a prefiltered probe (gfx/probe_prefilter.h): each texel is the
// capture averaged over the GGX lobe of the level's alpha around the texel's direction, seen
// along that direction (the split sum's view = normal = reflection), each sample weighed by its
// cosine and read from the capture's box chain at the level its share of the lobe covers
// (core/ggx.h's prefilterSourceLod), so that `u_samples` samples do not alias.
#include "ggx.glsl"

uniform samplerCube u_source;
uniform int u_face;        // 0..5, GL order (+X, -X, +Y, -Y, +Z, -Z)
uniform float u_alpha;     // the level's GGX alpha
uniform int u_samples;     // GGX samples a texel
uniform int u_sourceSize;  // the capture's face size at its level 0
uniform float u_targetSize;  // this level's face size

out vec4 fragColour;

// The direction GL's cube lookup maps to face `face` at (s, t) in [-1, 1] (the table of the GL
// ES 3.0 specification, section 3.8.10; core/cube_sampling.h inverts it).
vec3 faceDirection(int face, float s, float t) {
  if (face == 0) return vec3(1.0, -t, -s);
  if (face == 1) return vec3(-1.0, -t, s);
  if (face == 2) return vec3(s, 1.0, t);
  if (face == 3) return vec3(s, -1.0, -t);
  if (face == 4) return vec3(s, -t, 1.0);
  return vec3(-s, -t, -1.0);
}

void main() {
  vec2 st = gl_FragCoord.xy / u_targetSize * 2.0 - 1.0;
  vec3 n = normalize(faceDirection(u_face, st.x, st.y));
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int k = 0; k < u_samples; ++k) {
    vec3 h = ggxHalfVector(hammersley(uint(k), uint(u_samples)), u_alpha, n);
    float nDotH = dot(n, h);
    vec3 l = 2.0 * nDotH * h - n;
    float nDotL = dot(n, l);
    if (nDotL <= 0.0) continue;
    float lod = prefilterSourceLod(nDotH, u_alpha, u_samples, u_sourceSize);
    sum += textureLod(u_source, l, lod).rgb * nDotL;
    total += nDotL;
  }
  fragColour = vec4(total > 0.0 ? sum / total : texture(u_source, n).rgb, 1.0);
}
