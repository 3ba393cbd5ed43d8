// One level of a face's depth chain from the level below: each texel holds the min and max code
// of the 2x2 texels it covers (3 wide or high at the last column or row of an odd-sized level),
// so a cell of any level bounds every surface stored inside it.
uniform highp usampler2DArray u_source;  // the level below, as the texture's base level
uniform int u_layer;                     // the face
uniform ivec2 u_sourceSize;

out uvec2 result;

void main() {
  ivec2 target = ivec2(gl_FragCoord.xy);
  ivec2 targetSize = max(u_sourceSize / 2, ivec2(1));
  ivec2 first = target * 2;
  // An odd source leaves one column (row) over: the last target texel takes it too.
  ivec2 last = min(first + 1 + ivec2(equal(target, targetSize - 1)) * (u_sourceSize & 1),
                   u_sourceSize - 1);
  uvec2 bounds = uvec2(65535u, 0u);
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) {
      uvec2 cell = texelFetch(u_source, ivec3(x, y, u_layer), 0).rg;
      bounds = uvec2(min(bounds.x, cell.x), max(bounds.y, cell.y));
    }
  }
  result = bounds;
}
