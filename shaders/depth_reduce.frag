// One level of the depth pyramid from the level below (the texture's base level while this pass
// runs): each texel holds the min and max code of the 2x2 texels it covers, for each layer
// (R, G the first; B, A the second, where there are two: depth_pyramid.frag). The pyramid tiles
// the six faces side by side at every level, and each face's tile halves exactly, so the 2x2
// below a texel always lie in the same face.
uniform highp usampler2D u_source;

out uvec4 result;

void main() {
  ivec2 first = ivec2(gl_FragCoord.xy) * 2;
  uvec4 a = texelFetch(u_source, first, 0), b = texelFetch(u_source, first + ivec2(1, 0), 0);
  uvec4 c = texelFetch(u_source, first + ivec2(0, 1), 0);
  uvec4 d = texelFetch(u_source, first + ivec2(1, 1), 0);
  uvec4 low = min(min(a, b), min(c, d)), high = max(max(a, b), max(c, d));
  result = uvec4(low.x, high.y, low.z, high.w);
}
