// After a capture's third pass (capture_output.glsl): where it found the back of the object in
// front, that back becomes the far end of the first layer's depth range at level 0 (the pass
// masks the other channels).
uniform highp usampler2DArray u_backs;  // the third pass's codes (0: no back found)
uniform int u_layer;                    // the face

out uvec2 result;

void main() {
  uint back = texelFetch(u_backs, ivec3(ivec2(gl_FragCoord.xy), u_layer), 0).r;
  if (back == 0u) discard;
  result = uvec2(0u, back);
}
