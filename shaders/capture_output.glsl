// What every fragment shader writes. In the main pass (CAPTURE_OUTPUT 0, a program of its own):
// the colour alone. In a capture (CAPTURE_OUTPUT 1), also:
//  - alpha: the Euclidean distance d from the probe centre as d / (d + 1), in near-plane units
//    (the linear search reads it);
//  - location 1: depth codes (depth_encoding.glsl) as the first level of the chains the
//    hierarchical search walks.
// A capture draws one pass a face, or three (u_captureLayer):
//  1. the nearest surface: colour, and the range of its depth z1 over the texel, from the depth's
//     screen-space derivatives (a slanted floor spans many depths in one texel);
//  3. the farthest surface that faces away from the probe, behind the first pass's and within
//     its own object's size of it (depth test GREATER): where the objects in front end, so the
//     search knows how deep they are (into a texture of its own, the backs);
//  2. the nearest surface behind that back which faces the probe (peeled: fragments at or in
//     front of the back, or facing away, are discarded): what the objects hide, its colour and
//     depth range in the second layer.
#include "depth_encoding.glsl"

layout(location = 0) out vec4 fragColour;
#if CAPTURE_OUTPUT == 0
void writeOutputs(vec3 colour, vec3 worldPosition, vec3 normal, bool infinite) {
  fragColour = vec4(colour, 1.0);
}
#else
uniform int u_captureLayer;        // 0: main pass; 1, 2, 3: a capture's passes (above)
uniform vec3 u_captureCentre;      // the probe centre being captured
uniform vec3 u_captureAxis;        // the captured face's look direction
uniform float u_captureUnit;       // the capture's near plane
uniform int u_captureFace;         // 0..5, for the peel's look-up of the first layer
uniform float u_captureExtent;     // the drawn object's size (bounding box diagonal), near units
uniform highp usampler2DArray u_peelDepths;  // the first layer's codes (passes 2 and 3)
uniform highp usampler2DArray u_peelBacks;   // the backs pass 3 found (pass 2 peels behind)

layout(location = 1) out uvec2 fragDepth;

// Codes at most this far behind the first layer's count as the same surface when peeling (two
// draws of one surface can round to neighbouring codes).
const uint kPeelSlack = 2u;
// The depth range a texel stores reaches at most this fraction of the drawn object's size either
// side: an edge-on triangle at a figure's silhouette would otherwise claim a long wall of depths,
// which rays passing beside the figure would meet, while a floor seen at a grazing angle (its
// size is the scene's) keeps the wide range it really spans across a texel, so no ray slips
// under it. (Measured on the default scene over t = 0..7.5 s at 400 x 400: 0.01, 0.02 and 0.05
// lost 0.7, 0.1 and 0.2 dB against 0.03; a cap of 10% of the depth itself, 0.2 dB.)
const float kMaxSpread = 0.03;

// `normal` (world space) only matters when peeling; `infinite`: the sky.
void writeOutputs(vec3 colour, vec3 worldPosition, vec3 normal, bool infinite) {
  if (u_captureLayer == 0) {
    fragColour = vec4(colour, 1.0);
    fragDepth = uvec2(0u);
    return;
  }
  highp vec3 offset = worldPosition - u_captureCentre;
  highp float z = dot(offset, u_captureAxis) / u_captureUnit;
  // Half the depth the surface spans across this texel.
  highp float spread = min(0.5 * (abs(dFdx(z)) + abs(dFdy(z))), kMaxSpread * u_captureExtent);
  uint code = infinite ? kInfiniteDepthCode : encodeDepth(z);
  uint nearCode = infinite ? kInfiniteDepthCode : encodeDepth(z - spread);
  uint farCode = infinite ? kInfiniteDepthCode : encodeDepth(z + spread);
  bool facesAway = !infinite && dot(normal, offset) > 0.0;
  if (u_captureLayer == 2) {
    ivec3 texel = ivec3(ivec2(gl_FragCoord.xy), u_captureFace);
    uint back = max(texelFetch(u_peelDepths, texel, 0).g, texelFetch(u_peelBacks, texel, 0).r);
    if (code <= back + kPeelSlack || facesAway) discard;
  } else if (u_captureLayer == 3) {
    uint front = texelFetch(u_peelDepths, ivec3(ivec2(gl_FragCoord.xy), u_captureFace), 0).r;
    // The back of something far behind the front is not the front object's back.
    if (!facesAway || code <= front || z > decodeDepth(front) + u_captureExtent) discard;
  }
  highp float d = length(offset) / u_captureUnit;
  fragColour = vec4(colour, infinite ? 1.0 : d / (d + 1.0));
  fragDepth = u_captureLayer == 3 ? uvec2(farCode) : uvec2(nearCode, farCode);
}
#endif
