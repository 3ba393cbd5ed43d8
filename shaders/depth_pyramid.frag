// Level 0 of the depth pyramid, for all six faces in one pass: the capture's per-face (near, far)
// codes copied into the faces' tiles side by side (each tile u_tile texels square, the face size
// rounded up to a power of two). With two layers the first layer's codes go to R and G, the
// second's to B and A, so one chain of draws reduces both and the search reads both in one
// fetch; the first layer's far end then takes the back the capture found. Texels past a face's
// edge in its tile hold nothing (min 65535, max 0), so they never count.
uniform highp usampler2DArray u_faces;   // (near, far) codes, one layer a face
uniform highp usampler2DArray u_backs;   // the third capture pass's backs (u_layers == 2)
uniform highp usampler2DArray u_faces2;  // the second layer's codes (u_layers == 2)
uniform int u_layers;
uniform int u_faceSize;
uniform int u_tile;

out uvec4 result;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int face = p.x / u_tile;
  ivec2 t = ivec2(p.x - face * u_tile, p.y);
  if (t.x >= u_faceSize || t.y >= u_faceSize) {
    result = uvec4(65535u, 0u, 65535u, 0u);
    return;
  }
  uvec2 codes = texelFetch(u_faces, ivec3(t, face), 0).rg;
  uvec2 second = uvec2(65535u, 0u);
  if (u_layers == 2) {
    codes.y = max(codes.y, texelFetch(u_backs, ivec3(t, face), 0).r);
    second = texelFetch(u_faces2, ivec3(t, face), 0).rg;
  }
  result = uvec4(codes, second);
}
