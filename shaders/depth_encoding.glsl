// How captures store depth for the hierarchical search: the depth z along the captured face's
// look direction, in units of the capture's near plane (so z >= 1), as the 16-bit integer
// round((1 - 1/z) * 65535). Near surfaces keep fine steps (0.0015% of z at z = 1, 0.15% at
// z = 100), the encoding is monotonic (min and max of codes are codes of min and max), and 65535
// is infinitely far (the sky). Shared by the capture (capture_output.glsl), the chain's
// reduction (depth_reduce.frag) and the search (depth_search.glsl).
const uint kInfiniteDepthCode = 65535u;

// Where a capture cannot see how deep an object is (one stored layer, or what lies behind the
// first), the object is taken to reach this fraction of its depth behind its front: a ray that
// enters a figure's texel from the side meets its side, which the probe cannot see. The capture
// writes it into the far end of the texel's range. (Measured on the default scene at 400 x 400:
// 0.05 and 0.2 lost 0.2 and 0.1 dB against 0.1.)
const float kThickness = 0.1;

uint encodeDepth(highp float z) {
  highp float e = 1.0 - 1.0 / max(z, 1.0);
  return uint(clamp(floor(e * 65535.0 + 0.5), 0.0, 65534.0));
}

highp float decodeDepth(uint code) {
  return code >= kInfiniteDepthCode ? 1e30 : 1.0 / (1.0 - float(code) / 65535.0);
}
