// The hierarchical search: where does the ray x + tau d (x relative to the probe centre, both in
// near-plane units, d of unit length) first meet the surroundings a probe captured?
//
// Seen from the probe centre, the ray is a great-circle arc, and on each cube face a straight
// line (the face's perspective projection keeps lines straight). Along it the ray's depth z
// (along the face's look direction) is linear in tau. So on one face this is screen-space ray
// marching against a depth buffer, and the search walks the face's min/max depth chain
// (depth_reduce.frag) as hierarchical-Z tracing does (Uludag, GPU Pro 5; McGuire and Mara, JCGT
// 2014):
//  - the ray's depths over the current cell are [zIn, zOut], exact at the cell's borders;
//  - in front of the cell's nearest surface: nothing in the cell can be hit, so the search jumps
//    to the cell's border and goes up a level;
//  - behind the back of every object stored in the cell and in front of whatever the second
//    layer stores behind them: jump likewise;
//  - otherwise a finer level, down to one texel, where the ray either crosses the stored surface
//    (a hit, refined exactly: z is linear in tau) or passes behind it.
// Every texel the ray's projection passes through is tested before the search moves past it, so
// an object one texel thin cannot be stepped over. A face border is a cell border at every
// level; the search then continues on the face the ray enters.
//
// A single layer cannot see behind what it stores, nor how deep it is: an object is taken to be
// kThickness of its depth deep, and a ray that passes behind it goes on; if it never comes out in
// front of a surface to cross it, the best guess is the last point where it was known to be free,
// beside the occluder. Two layers (capture_output.glsl) also store each first object's back and
// the nearest surface behind it that faces the probe: a ray behind an object meets what is
// really there.
precision highp float;
precision highp int;
#include "depth_encoding.glsl"

// The depth pyramid (faces side by side, a mip per level: src/gfx/cube_capture_target.h): the
// first layer's codes in R and G, the second's in B and A (u_layers == 2).
uniform highp usampler2D u_pyramid;
uniform int u_layers;       // 1 or 2
uniform int u_faceSize;     // texels along a face edge at level 0
uniform int u_topLevel;     // the last level: one cell a face
uniform int u_pyramidTile;  // a face's tile at level 0 (the face size rounded up to a power of 2)
uniform vec3 u_faceRight[6];              // per face: the view's right, up and look directions
uniform vec3 u_faceUp[6];
uniform vec3 u_faceAxis[6];

const int kMaxSteps = 128;
// A ray nearly parallel to a cell border can stall against it: just past the border in exact
// arithmetic, its rounded position falls back into the cell it left, and each step advances it by
// the minimum. (Nearly horizontal rays on a side face's middle row, a cell border at every level,
// at the mirror's rim.) Almost all such rays never get past, and end out of steps with the lookup
// along d; after this many minimum steps in a row the search gives that answer at once. Measured
// at 256 x 256 over the eight held-out times, against letting them run: no pixel changed in seven
// shipped scenes, and skybox-grid's frame fell from 23.6 to 16.8 ms in llvmpipe, its pixels off by
// more than 32 levels 13.6 -> 13.8 a frame (a ray that got free after more than 64 steps had found
// the right colour). 16 and 8 cost skybox-grid 0.5 and 1.4 dB.
const int kStallSteps = 64;
const float kNever = 1e30;

int faceOf(vec3 p) {
  vec3 a = abs(p);
  if (a.x >= a.y && a.x >= a.z) return p.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return p.y >= 0.0 ? 2 : 3;
  return p.z >= 0.0 ? 4 : 5;
}

// The (near, far) codes of a cell of face f at `level`: the first layer's, then the second's.
uvec4 cellCodes(ivec2 cell, int f, int level) {
  return texelFetch(u_pyramid, ivec2(f * (u_pyramidTile >> level) + cell.x, cell.y), level);
}

struct SearchResult {
  vec3 point;  // where to look up (relative to the probe centre); the direction is what counts
  int layer;   // 1 or 2: which layer's colour; 0: nothing met (infinitely far, along d)
  int steps;   // iterations used (for measuring the search)
};

// The ray's depth z as the fraction depth codes are of 65535 (1 - 1/z: depth_encoding.glsl), so
// it compares with stored codes without decoding them; 1/z also projects the ray onto the face.
float depthFraction(float inverseZ) { return 1.0 - clamp(inverseZ, 0.0, 1.0); }

// The ray seen on one face: its depth along the face's axis is xz + tau dz, its face coordinates
// (xst + tau dst) / depth.
struct FaceRay {
  float xz;
  float dz;
  vec2 xst;
  vec2 dst;
  vec2 motion;
  vec2 towards;
};

FaceRay rayOnFace(vec3 x, vec3 d, int f) {
  FaceRay ray;
  vec3 right = u_faceRight[f], up = u_faceUp[f], axis = u_faceAxis[f];
  ray.xz = dot(x, axis);
  ray.dz = dot(d, axis);
  ray.xst = vec2(dot(x, right), dot(x, up));
  ray.dst = vec2(dot(d, right), dot(d, up));
  // s (and t) move monotonically along the ray, towards the border on the side of motion.
  ray.motion = ray.dst * ray.xz - ray.xst * ray.dz;
  ray.towards = step(0.0, ray.motion);
  return ray;
}

// The level-`level` cell the ray is in at tau (at face coordinates st), and where it leaves it:
// through the border at level-0 texel edgeTexel.x (leavesAcross) or edgeTexel.y, at tauExit
// (kNever: it never leaves).
struct Cell {
  ivec2 index;
  ivec2 edgeTexel;
  bool leavesAcross;
  float tauExit;
};

// The level-`level` cell holding face coordinates st (-1..1). A level-L cell spans 2^L level-0
// texels (the last one in a row may be cut by the face's edge).
ivec2 cellIndexAt(vec2 st, int level) {
  int n = (u_faceSize + (1 << level) - 1) >> level;
  return clamp(ivec2(floor((st * 0.5 + 0.5) * float(u_faceSize))) >> level, ivec2(0),
               ivec2(n - 1));
}

Cell cellAt(FaceRay ray, vec2 st, float tau, int level) {
  Cell cell;
  float toFace = 2.0 / float(u_faceSize);  // level-0 texels to face coordinates
  int span = 1 << level;
  cell.index = cellIndexAt(st, level);
  // Where the ray leaves the cell: s = b where xs + tau ds = b (xz + tau dz).
  cell.edgeTexel = min((cell.index + ivec2(ray.towards)) * span, ivec2(u_faceSize));
  vec2 border = vec2(cell.edgeTexel) * toFace - 1.0;
  vec2 crossing = (border * ray.xz - ray.xst) / (ray.dst - border * ray.dz);
  // A crossing behind the ray's origin is never reached; one just behind tau is rounding.
  bvec2 reached = bvec2(ray.motion.x != 0.0 && crossing.x >= 0.0,
                        ray.motion.y != 0.0 && crossing.y >= 0.0);
  crossing = max(crossing, vec2(tau));
  cell.leavesAcross = reached.x && (!reached.y || crossing.x <= crossing.y);
  cell.tauExit = cell.leavesAcross ? crossing.x : reached.y ? crossing.y : kNever;
  return cell;
}

// One texel the ray does not pass freely (its depths over it are (eIn, eNear, eFar)): the ray
// meets its object if its depths here reach into [front, back]: where it crosses the front, else
// inside (it entered through a side the probe cannot see); likewise what lies behind. False:
// it is behind what the texel stores.
bool meetsTexel(vec3 x, vec3 d, FaceRay ray, float tau, float tauExit, vec3 depths, float eFront,
                float eBack, vec2 behind, int i, out SearchResult met) {
  float eIn = depths.x, eNear = depths.y, eFar = depths.z;
  float mid = tauExit >= kNever ? tau : 0.5 * (tau + tauExit);
  if (eNear <= eBack && eFar >= eFront) {
    if (eIn > eFront) {
      met = SearchResult(x + mid * d, 1, i);
      return true;
    }
    float zFront = 1.0 / (1.0 - eFront);
    met = SearchResult(x + clamp((zFront - ray.xz) / ray.dz, tau, tauExit) * d, 1, i);
    return true;
  }
  if (u_layers == 2 && eNear <= behind.y && eFar >= behind.x) {
    if (eIn > behind.x) {
      met = SearchResult(x + mid * d, 2, i);
      return true;
    }
    float zBehind = 1.0 / (1.0 - behind.x);
    met = SearchResult(x + clamp((zBehind - ray.xz) / ray.dz, tau, tauExit) * d, 2, i);
    return true;
  }
  return false;
}

// `finest`: the finest level the search descends to (0: one texel); at a coarser one, a cell the
// ray does not pass freely is met as its texel would be, at its nearest surface (a blurred lookup
// needs no more). After `maxSteps` steps, or stalled: layer -1.
SearchResult searchDepthsTo(vec3 x, vec3 d, int finest, int maxSteps) {
  float tau = 0.0;
  float tauFree = 0.0;  // the farthest point known to be in front of every stored surface
  int level = max(u_topLevel - 3, finest);
  const float kCode = 1.0 / 65535.0;
  // The ray seen on face f, recomputed only when it moves to another face.
  int f = -1;
  FaceRay ray = FaceRay(0.0, 0.0, vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
  bool faceEdge = true;  // the ray is on a face's edge: which face it is on is to be found
  int stalled = 0;       // minimum steps in a row
  for (int i = 0; i < maxSteps; ++i) {
    int face = faceEdge ? faceOf(x + tau * d) : f;
    if (face != f) {
      f = face;
      ray = rayOnFace(x, d, f);
    }
    float zIn = ray.xz + tau * ray.dz;
    float inverseIn = 1.0 / zIn;
    vec2 st = (ray.xst + tau * ray.dst) * inverseIn;
    Cell cell = cellAt(ray, st, tau, level);
    float tauExit = cell.tauExit;
    // The ray's depths over the cell, as code fractions (an endless ray: 1, infinitely far).
    float eIn = depthFraction(inverseIn);
    float eOut = tauExit >= kNever ? 1.0 : depthFraction(1.0 / (ray.xz + tauExit * ray.dz));
    float eNear = min(eIn, eOut), eFar = max(eIn, eOut);

    // The first chain: the nearest surfaces' codes (min over the cell) and how far back their
    // objects reach (max). The second (two layers): what lies behind them, from its nearest to
    // its far end. (The capture wrote each far end with the thickness its pass cannot see.)
    // Each stored range is widened by a code either side: a surface square to the face (the
    // floor below the probe) spans no depth across a texel, and its codes round to one value
    // or the next from texel to texel; a ray crossing it where the code steps down would be in
    // front of one texel's surface and behind the next's, and slip through (single wrong
    // pixels in the mirror's image of the floor, 2-3 a frame in the default scene).
    uvec4 codes = cellCodes(cell.index, f, level);
    vec2 first = vec2(codes.xy) * kCode;
    float eFront = first.x - kCode, eBack = first.y + kCode;
    vec2 behind = u_layers == 2 ? vec2(codes.zw) * kCode : vec2(1.0);
    // In front of every surface in the cell, or behind every object there and in front of
    // everything behind them: nothing in the cell can be met.
    bool free = eFar < eFront;
    bool passes = free || (eNear > eBack && eFar < behind.x);
    if (!passes && level == finest) {
      SearchResult met;
      vec3 depths = vec3(eIn, eNear, eFar);
      if (meetsTexel(x, d, ray, tau, tauExit, depths, eFront, eBack, behind, i, met)) return met;
      passes = true;  // behind what the texel stores: past it, unseen
    }
    if (!passes) {
      level -= 1;
      continue;
    }
    if (free) tauFree = tauExit;
    if (tauExit >= kNever) {
      // Nothing ahead: free, the ray runs to infinity (the sky); hidden, it passed behind the
      // last surface it saw, and the last free point is the guess. (No ?: on structures: WebGL
      // refuses it.)
      if (free) return SearchResult(d, 0, i);
      return SearchResult(x + tauFree * d, 1, i);
    }
    // Just past the border, into the next cell (or face); one level coarser if that border is
    // also the coarser cell's (else the next cell is this one's sibling, at this level), so a
    // ray grazing a surface walks along it instead of going up and down at every texel.
    int exitTexel = cell.leavesAcross ? cell.edgeTexel.x : cell.edgeTexel.y;
    int span = 1 << level;
    faceEdge = exitTexel == 0 || exitTexel >= u_faceSize;
    if ((exitTexel & (2 * span - 1)) == 0 || faceEdge) level = min(level + 1, u_topLevel);
    stalled = tauExit - tau < 1e-4 * max(tau, 1.0) ? stalled + 1 : 0;
    if (stalled > kStallSteps) break;
    tau = tauExit + max(tauExit * 1e-5, 1e-5);
  }
  // Out of steps or stalled (a long walk of a ray grazing the reflector's rim, behind the sky's
  // texels or a figure's): taken as a miss, looked up along d. (The farthest point reached, the
  // guess this replaced, painted the rim of skybox-grid's mirror grey: its PSNR 29.4 -> 46.0 dB.)
  return SearchResult(d, -1, maxSteps);
}

// How far the point x (relative to the probe centre, near-plane units) lies outside the depths
// the probe stored in its cell at `level`, relative to its own depth: 0 where it lies within a
// stored object's depth range (either layer's), as a point the probe could have captured there.
float storedDepthMismatch(vec3 x, int level) {
  int f = faceOf(x);
  float z = dot(x, u_faceAxis[f]);
  vec2 st = vec2(dot(x, u_faceRight[f]), dot(x, u_faceUp[f])) / z;
  uvec4 codes = cellCodes(cellIndexAt(st, level), f, level);
  vec4 stored = vec4(decodeDepth(codes.x), decodeDepth(codes.y), decodeDepth(codes.z),
                     decodeDepth(codes.w));
  float first = max(stored.x - z, 0.0) + max(z - stored.y, 0.0);
  float second = max(stored.z - z, 0.0) + max(z - stored.w, 0.0);
  return (u_layers == 2 ? min(first, second) : first) / z;
}

SearchResult searchDepths(vec3 x, vec3 d) {
  SearchResult found = searchDepthsTo(x, d, 0, kMaxSteps);
  found.layer = max(found.layer, 0);
  return found;
}

#ifdef REFLECT_MEDIUMP
precision mediump float;
#endif
