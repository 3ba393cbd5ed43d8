// The exact mode's walk (SEARCH_EXACT: search exact, or planned where the planner traces): the
// nearest triangle a ray meets in the scene's two-level BVH. What the ray's pixel shows, shaded
// from what it meets, is exact_shade.glsl's, which includes this.
//
// The scene is two levels of BVH (core/bvh.h) in float textures, kBvhTextureWidth texels a row:
//  u_exactAtlas    every mesh's tree: interior nodes (kNodeTexels: each child's (min, ref) and
//                  (max, count)) and triangles (kTriangleTexels: v0, v1 - v0, v2 - v0, v0.w its
//                  slot); after them, rewritten each frame, the header (the top level's box and
//                  root, then the box and slot of the object tested before the walk), each
//                  object's slot (its inverse model's rows, then (root, count, object)) and the
//                  top level's interior nodes
//  u_exactNormals  3 texels a triangle slot: its vertices' normals
//  u_exactScene    kInstanceTexels per object, for shading what the walk found (normal matrix
//                  columns, colour and material, mix weights, probe centre, self epsilon,
//                  inverse model's rows)
// A reference (ref, count) is an interior node (count 0), a leaf of `count` triangles, or in the
// top level an object's slot (count -1). Rays go into each object's space unnormalised, so t is
// the same parameter in both levels.
#if SEARCH == SEARCH_EXACT
// From the C++ that writes the atlas and holds the rays' limits (gfx/program_key.cpp). The
// program is built highp whatever the precision setting (ProgramKey::allowsMediump(): mediump
// would lose the triangles).
const int kExactWidthShift = EXACT_WIDTH_SHIFT;     // kBvhTextureWidthShift
const int kExactInstance = EXACT_INSTANCE_TEXELS;   // kInstanceTexels
const int kExactTriangle = EXACT_TRIANGLE_TEXELS;   // kTriangleTexels
const int kExactTested = EXACT_TESTED_TRIANGLES;    // kTestedTriangles
const int kExactStack = EXACT_STACK;                // two levels of kBvhMaxDepth, and some
const int kExactMaxBounces = EXACT_MAX_BOUNCES;     // core/trace_limits.h's kMaxBounces
const int kExactMaxInternal = EXACT_MAX_INTERNAL;   // and kMaxInternalReflections
const int kExactSteps = 4096;       // a bound on one walk's turns (a walk takes tens)
const float kExactFar = 3.0e38;     // no hit

uniform highp sampler2D u_exactAtlas;
uniform highp sampler2D u_exactNormals;
uniform highp sampler2D u_exactScene;
uniform int u_exactHeader;    // the texel of the top level's header in u_exactAtlas
uniform int u_exactEmpty;     // 1: nothing to trace

highp vec4 exactFetch(highp sampler2D s, int i) {
  return texelFetch(s, ivec2(i & ((1 << kExactWidthShift) - 1), i >> kExactWidthShift), 0);
}

struct ExactHit {
  float t;
  int instance;  // -1: nothing met
  int slot;      // the triangle's slot (u_exactNormals)
  float u;
  float v;
};

// Where the ray enters the box within [tMin, tMax], or kExactFar.
float exactBoxEntry(vec3 lo, vec3 hi, vec3 o, vec3 invD, float tMin, float tMax) {
  vec3 t0 = (lo - o) * invD;
  vec3 t1 = (hi - o) * invD;
  vec3 a = min(t0, t1);
  vec3 b = max(t0, t1);
  float enter = max(max(a.x, a.y), max(a.z, tMin));
  float leave = min(min(b.x, b.y), min(b.z, tMax));
  return enter <= leave ? enter : kExactFar;
}

vec3 exactInverse(vec3 d) {
  vec3 s = vec3(d.x < 0.0 ? -1e-20 : 1e-20, d.y < 0.0 ? -1e-20 : 1e-20, d.z < 0.0 ? -1e-20 : 1e-20);
  return 1.0 / mix(d, s, lessThan(abs(d), vec3(1e-20)));
}

// The ray o + t d against the triangle at v0 = a.xyz with edges e1 and e2 (a.w its slot): the
// best hit becomes it where the ray meets it at t in (tMin, best.t).
void exactTriangle(vec4 a, vec3 e1, vec3 e2, vec3 o, vec3 d, float tMin, int instance,
                   inout ExactHit best) {
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  float invDet = 1.0 / det;
  vec3 sv = o - a.xyz;
  float u = dot(sv, p) * invDet;
  vec3 q = cross(sv, e1);
  float v = dot(d, q) * invDet;
  float t = dot(e2, q) * invDet;
  if (det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > tMin && t < best.t) {
    best.t = t;
    best.instance = instance;
    best.slot = int(a.w);
    best.u = u;
    best.v = v;
  }
}

// The nearest hit along o + t d, t in (tMin, best.t), among the objects but `skip` (only `only`
// when >= 0). One loop walks both levels, nearer child first: each turn reads the four texels
// at `ref` and, by `count`, tests an interior node's two children, one triangle of a leaf, or
// enters an object (the ray moves into its space; its nodes are pushed above `base`, and the
// ray moves back when the walk pops below it). Every turn reads the same texture the same way:
// a software rasteriser runs the union of its pixels' branches each turn.
ExactHit exactTrace(vec3 origin, vec3 direction, float tMin, int skip, int only) {
  ExactHit best = ExactHit(kExactFar, -1, -1, 0.0, 0.0);
  if (u_exactEmpty == 1) return best;
  vec3 worldInv = exactInverse(direction);
  vec4 h0 = exactFetch(u_exactAtlas, u_exactHeader);
  vec4 h1 = exactFetch(u_exactAtlas, u_exactHeader + 1);
  // The object tested before the walk (h3.w 1; core/bvh.h packScene: the ground, left out of the
  // tree): its few triangles, in its space as the walk would test them, so the walk starts with
  // the nearest hit it gives and the tree's boxes beyond it are never entered.
  vec4 h2 = exactFetch(u_exactAtlas, u_exactHeader + 2);
  vec4 h3 = exactFetch(u_exactAtlas, u_exactHeader + 3);
  if (h3.w > 0.5 && exactBoxEntry(h2.xyz, h3.xyz, origin, worldInv, tMin, best.t) < kExactFar) {
    int slot = int(h2.w);
    vec4 r0 = exactFetch(u_exactAtlas, slot);
    vec4 r1 = exactFetch(u_exactAtlas, slot + 1);
    vec4 r2 = exactFetch(u_exactAtlas, slot + 2);
    vec4 r3 = exactFetch(u_exactAtlas, slot + 3);
    int object = int(r3.z);
    if (object != skip && (only < 0 || object == only)) {
      vec3 o = vec3(dot(r0, vec4(origin, 1.0)), dot(r1, vec4(origin, 1.0)), dot(r2, vec4(origin, 1.0)));
      vec3 d = vec3(dot(r0.xyz, direction), dot(r1.xyz, direction), dot(r2.xyz, direction));
      int tri = int(r3.x);
      int triangles = int(r3.y);
      for (int k = 0; k < kExactTested; ++k) {
        if (k >= triangles) break;
        exactTriangle(exactFetch(u_exactAtlas, tri), exactFetch(u_exactAtlas, tri + 1).xyz,
                      exactFetch(u_exactAtlas, tri + 2).xyz, o, d, tMin, object, best);
        tri += kExactTriangle;
      }
    }
  }
  // An empty tree (the tested object alone) has root -1.
  if (h0.w < 0.0 || exactBoxEntry(h0.xyz, h1.xyz, origin, worldInv, tMin, best.t) >= kExactFar) {
    return best;
  }
  int ref = int(h0.w);
  int count = int(h1.w);
  vec3 o = origin;
  vec3 d = direction;
  vec3 inv = worldInv;
  int instance = -1;
  int base = -1;  // the stack's height when the walk entered `instance` (-1: the top level)
  int stackRef[kExactStack];
  int stackCount[kExactStack];
  float stackEntry[kExactStack];
  int sp = 0;
  for (int step = 0; step < kExactSteps; ++step) {
    vec4 a = exactFetch(u_exactAtlas, ref);
    vec4 b = exactFetch(u_exactAtlas, ref + 1);
    vec4 c = exactFetch(u_exactAtlas, ref + 2);
    vec4 e = exactFetch(u_exactAtlas, ref + 3);
    bool done = false;  // this reference is finished: take the next from the stack
    if (count == 0) {  // an interior node: a = (left min, ref), b = (left max, count), c, e right
      float tl = exactBoxEntry(a.xyz, b.xyz, o, inv, tMin, best.t);
      float tr = exactBoxEntry(c.xyz, e.xyz, o, inv, tMin, best.t);
      bool leftFirst = tl <= tr;
      float nearEntry = min(tl, tr);
      float farEntry = max(tl, tr);
      if (farEntry < kExactFar) {
        stackRef[sp] = int(leftFirst ? c.w : a.w);
        stackCount[sp] = int(leftFirst ? e.w : b.w);
        stackEntry[sp] = farEntry;
        ++sp;
      }
      ref = int(leftFirst ? a.w : c.w);
      count = int(leftFirst ? b.w : e.w);
      done = nearEntry >= kExactFar;
    } else if (count > 0) {  // a leaf's next triangle: a = v0, b = v1 - v0, c = v2 - v0
      exactTriangle(a, b.xyz, c.xyz, o, d, tMin, instance, best);
      ref += kExactTriangle;
      --count;
      done = count == 0;
    } else {  // an object: a, b, c = its inverse model's rows, e = (root, count, object)
      int object = int(e.z);
      if (object == skip || (only >= 0 && object != only) || e.x < 0.0) {
        done = true;
      } else {
        o = vec3(dot(a, vec4(origin, 1.0)), dot(b, vec4(origin, 1.0)), dot(c, vec4(origin, 1.0)));
        d = vec3(dot(a.xyz, direction), dot(b.xyz, direction), dot(c.xyz, direction));
        inv = exactInverse(d);
        instance = object;
        base = sp;
        ref = int(e.x);
        count = int(e.y);
      }
    }
    if (done) {
      // The nearest pushed reference the best hit so far has not ruled out.
      while (sp > 0 && stackEntry[sp - 1] > best.t) --sp;
      if (sp == 0) break;
      --sp;
      ref = stackRef[sp];
      count = stackCount[sp];
      if (sp < base) {  // back at the top level
        o = origin;
        d = direction;
        inv = worldInv;
        instance = -1;
        base = -1;
      }
    }
  }
  return best;
}
#endif
