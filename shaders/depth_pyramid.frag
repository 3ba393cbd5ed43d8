// The first level of the depth pyramid, for all six faces in one pass: each texel holds the min
// and max code of the 2x2 level-0 texels it covers in its face's tile (faces side by side, each
// tile u_tile texels wide). Level 0 is the capture's own per-face layer; where the capture found
// the backs of the objects in front (two layers), the far end takes the back. Texels past an odd
// or non-power-of-two face's edge hold nothing (min 65535, max 0), so they never count.
uniform highp usampler2DArray u_faces;  // level 0: (near, far) codes, one layer a face
uniform highp usampler2DArray u_backs;  // the third capture pass's backs (u_useBacks == 1)
uniform int u_useBacks;
uniform int u_faceSize;
uniform int u_tile;

out uvec2 result;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int face = p.x / u_tile;
  ivec2 first = ivec2(p.x - face * u_tile, p.y) * 2;
  uvec2 bounds = uvec2(65535u, 0u);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      ivec2 t = first + ivec2(i, j);
      if (t.x >= u_faceSize || t.y >= u_faceSize) continue;
      uvec2 codes = texelFetch(u_faces, ivec3(t, face), 0).rg;
      if (u_useBacks == 1) codes.y = max(codes.y, texelFetch(u_backs, ivec3(t, face), 0).r);
      bounds = uvec2(min(bounds.x, codes.x), max(bounds.y, codes.y));
    }
  }
  result = bounds;
}
