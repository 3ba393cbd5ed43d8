// One face of one rough level of a prefiltered probe (gfx/probe_prefilter.h): each texel is the
// capture averaged over the GGX lobe of the level's alpha around the texel's direction, seen
// along that direction (the split sum's view = normal = reflection), each sample weighed by its
// cosine and read from the capture's box chain at the level its share of the lobe covers
// (core/ggx.h's prefilterSourceLod), so that few samples do not alias. The lobe is the same for
// every texel, turned into its frame: the C++ computes it once a level (prefilterLobe).
#include "ggx.glsl"

uniform samplerCube u_source;
uniform int u_face;          // 0..5, GL order (+X, -X, +Y, -Y, +Z, -Z)
uniform float u_targetSize;  // this level's face size
uniform int u_samples;       // the lobe's samples (those above the surface)
// core/ggx.h's prefilterLobe: each sample's direction around the normal, its length its weight,
// and its source level.
uniform vec4 u_lobe[PREFILTER_MAX_SAMPLES];

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
  mat3 frame = frameAround(normalize(faceDirection(u_face, st.x, st.y)));
  vec3 sum = vec3(0.0);
  for (int k = 0; k < u_samples; ++k) {
    vec4 s = u_lobe[k];
    vec3 l = frame * s.xyz;
    sum += textureLod(u_source, l, s.w).rgb * length(s.xyz);
  }
  fragColour = vec4(sum, 1.0);
}
