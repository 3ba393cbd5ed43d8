// One level of the depth pyramid from the level below (the texture's base level while this pass
// runs): each texel holds the min and max code of the 2x2 texels it covers. The pyramid tiles
// the six faces side by side at every level, and each face's tile halves exactly, so the 2x2
// below a texel always lie in the same face.
uniform highp usampler2D u_source;

out uvec2 result;

void main() {
  ivec2 first = ivec2(gl_FragCoord.xy) * 2;
  uvec2 a = texelFetch(u_source, first, 0).rg, b = texelFetch(u_source, first + ivec2(1, 0), 0).rg;
  uvec2 c = texelFetch(u_source, first + ivec2(0, 1), 0).rg;
  uvec2 d = texelFetch(u_source, first + ivec2(1, 1), 0).rg;
  result = uvec2(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)));
}
