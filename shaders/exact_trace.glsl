// The exact mode (SEARCH_EXACT: search exact, or planned where the planner traces): a mirror or glass pixel's ray is traced against the
// scene's triangles instead of looked up in a cube map, and what it meets is shaded as a capture
// would shade it: Phong lit as seen from the main camera's eye, a mirror reflecting again, glass
// crossed through both surfaces, a cube-textured object traced from its probe centre, the sky
// (or the clear colour) where nothing is met. src/reference/reference_renderer.h says what the
// exact answer is; this follows it term by term, with one limit: glass met by a ray that has
// already left a surface sees, for its Fresnel-reflected share, the sky along the reflected ray
// (one ray a bounce: no tree of rays in a fragment shader).
//
// The scene is two levels of BVH (core/bvh.h) in float textures, kBvhTextureWidth texels a row:
//  u_exactAtlas    every mesh's tree: interior nodes (kNodeTexels: each child's (min, ref) and
//                  (max, count)) and triangles (kTriangleTexels: v0, v1 - v0, v2 - v0, v0.w its
//                  slot); after them, rewritten each frame, the header (the top level's box and
//                  root), each object's slot (its inverse model's rows, then (root, count,
//                  object)) and the top level's interior nodes
//  u_exactNormals  3 texels a triangle slot: its vertices' normals
//  u_exactScene    kInstanceTexels per object, for shading what the walk found (normal matrix
//                  columns, colour and material, mix weights, probe centre, self epsilon,
//                  inverse model's rows)
// A reference (ref, count) is an interior node (count 0), a leaf of `count` triangles, or in the
// top level an object's slot (count -1). Rays go into each object's space unnormalised, so t is
// the same parameter in both levels.
#if SEARCH == SEARCH_EXACT
// Tracing needs full precision whatever the shader's default (mediump would lose the triangles).
precision highp float;
precision highp int;
// From the C++ that writes the atlas and holds the rays' limits (gfx/program_key.cpp).
const int kExactWidthShift = EXACT_WIDTH_SHIFT;     // kBvhTextureWidthShift
const int kExactInstance = EXACT_INSTANCE_TEXELS;   // kInstanceTexels
const int kExactTriangle = EXACT_TRIANGLE_TEXELS;   // kTriangleTexels
const int kExactStack = EXACT_STACK;                // two levels of kBvhMaxDepth, and some
const int kExactMaxBounces = EXACT_MAX_BOUNCES;     // core/trace_limits.h's kMaxBounces
const int kExactMaxInternal = EXACT_MAX_INTERNAL;   // and kMaxInternalReflections
const int kExactSteps = 4096;       // a bound on one walk's turns (a walk takes tens)
const float kExactFar = 3.0e38;     // no hit

uniform highp sampler2D u_exactAtlas;
uniform highp sampler2D u_exactNormals;
uniform highp sampler2D u_exactScene;
uniform samplerCube u_exactSky;
uniform int u_exactHasSky;    // 0: the clear colour where nothing is met
uniform vec3 u_exactClear;
uniform int u_exactSelf;      // the object being drawn
uniform int u_exactHeader;    // the texel of the top level's header in u_exactAtlas
uniform int u_exactEmpty;     // 1: nothing to trace
uniform vec3 u_exactLight;
uniform vec4 u_exactPhong;    // ambient, diffuse, specular, shininess
uniform vec3 u_exactEye;      // the main camera's eye: captures are lit as seen from it
uniform float u_exactFar;     // the capture's far distance: the world a reflector sees ends there
uniform int u_exactMark;      // 1: alpha 0 on this pass's pixels (the error view's reflector mask)

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

// The nearest hit along o + t d, t in (tMin, best.t), among the objects but `skip` (only `only`
// when >= 0). One loop walks both levels, nearer child first: each turn reads the four texels
// at `ref` and, by `count`, tests an interior node's two children, one triangle of a leaf, or
// enters an object (the ray moves into its space; its nodes are pushed above `base`, and the
// ray moves back when the walk pops below it). Every turn reads the same texture the same way:
// a software rasteriser runs each turn's whole body for every pixel.
ExactHit exactTrace(vec3 origin, vec3 direction, float tMin, int skip, int only) {
  ExactHit best;
  best.t = kExactFar;
  best.instance = -1;
  best.slot = -1;
  best.u = 0.0;
  best.v = 0.0;
  if (u_exactEmpty == 1) return best;
  vec3 worldInv = exactInverse(direction);
  vec4 h0 = exactFetch(u_exactAtlas, u_exactHeader);
  vec4 h1 = exactFetch(u_exactAtlas, u_exactHeader + 1);
  if (exactBoxEntry(h0.xyz, h1.xyz, origin, worldInv, tMin, best.t) >= kExactFar) return best;
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
      vec3 p = cross(d, c.xyz);
      float det = dot(b.xyz, p);
      float invDet = 1.0 / det;
      vec3 sv = o - a.xyz;
      float u = dot(sv, p) * invDet;
      vec3 q = cross(sv, b.xyz);
      float v = dot(d, q) * invDet;
      float t = dot(c.xyz, q) * invDet;
      if (det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > tMin && t < best.t) {
        best.t = t;
        best.instance = instance;
        best.slot = int(a.w);
        best.u = u;
        best.v = v;
      }
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

// The world a reflector sees ends at its probe's far planes, as the main camera's ends at its
// own: a surface farther than the capture's far distance along any axis from `centre` is not
// there (reference_renderer.cpp's radiance()).
bool exactBeyondFar(vec3 p, vec3 centre) {
  vec3 away = abs(p - centre);
  return max(away.x, max(away.y, away.z)) > u_exactFar;
}

vec3 exactBackground(vec3 d) {
  if (u_exactHasSky == 1) return texture(u_exactSky, d).rgb;
  return u_exactClear;
}

// shaders/phong.frag, lit from the main camera's eye.
vec3 exactPhong(vec3 colour, vec3 p, vec3 n) {
  vec3 L = normalize(u_exactLight - p);
  vec3 V = normalize(u_exactEye - p);
  float nDotL = max(dot(n, L), 0.0);
  vec3 c = colour * (u_exactPhong.x + u_exactPhong.y * nDotL);
  if (nDotL > 0.0) {
    vec3 R = reflect(-L, n);
    c += vec3(u_exactPhong.z * pow(clamp(dot(R, V), 0.0, 1.0), u_exactPhong.w));
  }
  return c;
}

float exactSchlick(float ior, vec3 toViewer, vec3 n) {
  float f0 = ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  return f0 + (1.0 - f0) * pow(1.0 - clamp(dot(toViewer, n), 0.0, 1.0), 5.0);
}

// The world normal (interpolated, normalised) of a hit.
vec3 exactNormal(ExactHit h) {
  int base = h.instance * kExactInstance;
  vec3 n0 = exactFetch(u_exactNormals, 3 * h.slot).xyz;
  vec3 n1 = exactFetch(u_exactNormals, 3 * h.slot + 1).xyz;
  vec3 n2 = exactFetch(u_exactNormals, 3 * h.slot + 2).xyz;
  vec3 n = (1.0 - h.u - h.v) * n0 + h.u * n1 + h.v * n2;
  mat3 normalMatrix = mat3(exactFetch(u_exactScene, base).xyz,
                           exactFetch(u_exactScene, base + 1).xyz,
                           exactFetch(u_exactScene, base + 2).xyz);
  return normalize(normalMatrix * n);
}

#if EXACT_GENERAL == 0
// What the ray origin + t dir sees when nothing it can meet is a mirror, glass or cube-textured
// object (the program's variant: src/gfx/program_key.h): one trace, and the Phong surface it
// meets or the sky. `truth`: the direction from the probe centre to what it meets, or its own
// direction when it meets nothing.
vec3 exactRadiance(vec3 origin, vec3 dir, int self, out vec3 truth) {
  ExactHit h = exactTrace(origin, dir, 0.0, self, -1);
  truth = dir;
  vec3 p = origin + h.t * dir;
  if (h.instance < 0 || exactBeyondFar(p, u_probeCentre)) return exactBackground(dir);
  truth = normalize(p - u_probeCentre);
  vec4 look = exactFetch(u_exactScene, h.instance * kExactInstance + 3);
  return clamp(exactPhong(look.rgb, p, exactNormal(h)), 0.0, 1.0);
}
#else
// What the ray origin + t dir (t > 0) sees, clamped as a capture texel is (the reference's
// radiance): among the objects but `self`, or, with `inside`, first across glass object `self`
// to where it leaves. `truth`: the direction from the probe centre to what the ray (once out of
// the glass) meets, or its own direction when it meets nothing.
vec3 exactRadiance(vec3 origin, vec3 dir, int self, bool inside, out vec3 truth) {
  // A bounce at a mirror or glass gives colour = add + weight * (what it sees), clamped; those
  // are kept and unwound at the end.
  vec3 adds[kExactMaxBounces];
  float weights[kExactMaxBounces];
  int links = 0;
  int leaving = self;
  int glass = inside ? self : -1;
  int reflections = 0;
  int depth = 1;
  bool first = true;
  truth = dir;
  vec3 result = exactBackground(dir);
  for (int step = 0; step < 64; ++step) {
    float tMin = 0.0;
    if (glass >= 0) tMin = exactFetch(u_exactScene, glass * kExactInstance + 6).x;
    ExactHit h = exactTrace(origin, dir, tMin, glass >= 0 ? -1 : leaving, glass);
    if (glass >= 0) {
      // Inside glass: leave through the far surface, or reflect inside it.
      int g = glass;
      if (h.instance < 0) {  // no far surface (along a silhouette): on from here
        leaving = g;
        glass = -1;
        continue;
      }
      vec3 N = exactNormal(h);
      vec3 facing = dot(dir, N) > 0.0 ? -N : N;
      float n = exactFetch(u_exactScene, g * kExactInstance + 4).z;
      vec3 out_ = refract(dir, facing, n);
      origin = origin + h.t * dir;
      if (dot(out_, out_) > 0.0) {
        dir = normalize(out_);
        leaving = g;
        glass = -1;
      } else {
        dir = reflect(dir, facing);
        if (++reflections == kExactMaxInternal) {
          leaving = g;
          glass = -1;
        }
      }
      continue;
    }
    vec3 p = origin + h.t * dir;
    if (h.instance >= 0 && leaving >= 0 &&
        exactBeyondFar(p, exactFetch(u_exactScene, leaving * kExactInstance + 5).xyz)) {
      h.instance = -1;
    }
    if (first) {
      first = false;
      truth = h.instance >= 0 ? normalize(p - u_probeCentre) : dir;
    }
    if (h.instance < 0) {
      result = exactBackground(dir);
      break;
    }
    int base = h.instance * kExactInstance;
    vec4 look = exactFetch(u_exactScene, base + 3);
    int material = int(look.w + 0.5);
    if (material != 0 && depth > kExactMaxBounces) {
      result = exactBackground(dir);
      break;
    }
    vec3 N = exactNormal(h);
    if (material == 0) {
      result = clamp(exactPhong(look.rgb, p, N), 0.0, 1.0);
      break;
    }
    vec4 weightsOf = exactFetch(u_exactScene, base + 4);  // reflection, base, ior, fresnel
    vec3 toViewer = normalize(-dir);
    vec3 add = vec3(0.0);
    float weight = 1.0;
    vec3 nextOrigin = p;
    vec3 nextDir;
    bool enterGlass = false;
    if (material == 1) {  // mirror
      nextDir = reflect(-toViewer, N);
      if (weightsOf.w > 0.5) {
        float s = exactSchlick(weightsOf.z, toViewer, N);
        add = (1.0 - s) * look.rgb;
        weight = s;
      } else {
        add = weightsOf.y * look.rgb;
        weight = weightsOf.x;
      }
    } else if (material == 2) {  // glass
      vec3 R = reflect(-toViewer, N);
      vec3 T = refract(-toViewer, N, 1.0 / weightsOf.z);
      bool total = dot(T, T) == 0.0;
      bool fresnel = weightsOf.w > 0.5;
      if (total) {
        nextDir = R;
        add = fresnel ? vec3(0.0) : weightsOf.y * look.rgb;
        weight = fresnel ? 1.0 : weightsOf.x;
      } else {
        nextDir = normalize(T);
        enterGlass = true;
        if (fresnel) {
          float s = exactSchlick(weightsOf.z, toViewer, N);
          add = s * clamp(exactBackground(R), 0.0, 1.0);
          weight = 1.0 - s;
        } else {
          add = weightsOf.y * look.rgb;
          weight = weightsOf.x;
        }
      }
    } else {  // cube-textured: from its probe centre along its object-space position
      vec4 m0 = exactFetch(u_exactScene, base + 7);
      vec4 m1 = exactFetch(u_exactScene, base + 8);
      vec4 m2 = exactFetch(u_exactScene, base + 9);
      vec3 objectPosition = vec3(dot(m0, vec4(p, 1.0)), dot(m1, vec4(p, 1.0)), dot(m2, vec4(p, 1.0)));
      if (dot(objectPosition, objectPosition) == 0.0) {
        result = exactBackground(vec3(0.0, 0.0, 1.0));
        break;
      }
      nextOrigin = exactFetch(u_exactScene, base + 5).xyz;
      nextDir = normalize(objectPosition);
    }
    adds[links] = add;
    weights[links] = weight;
    ++links;
    origin = nextOrigin;
    dir = nextDir;
    leaving = h.instance;
    ++depth;
    if (enterGlass) {
      glass = h.instance;
      reflections = 0;
    }
  }
  for (int k = kExactMaxBounces - 1; k >= 0; --k) {
    if (k < links) result = clamp(adds[k] + weights[k] * result, 0.0, 1.0);
  }
  return result;
}
#endif


// environment.frag's main() with every environment traced: the reflected ray (a mirror; glass
// with Fresnel or at total internal reflection), and glass's refracted ray from inside the object.
void exactMain() {
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_viewPosition);
  float schlick = u_fresnelF0 + (1.0 - u_fresnelF0) * pow(1.0 - clamp(dot(-I, N), 0.0, 1.0), 5.0);
  vec3 measured;
  vec3 colour;
#if REFRACTS == 0
  // A mirror: the reflected ray alone.
#if EXACT_GENERAL == 0
  vec3 reflected = exactRadiance(v_worldPosition, reflect(I, N), u_exactSelf, measured);
#else
  vec3 reflected = exactRadiance(v_worldPosition, reflect(I, N), u_exactSelf, false, measured);
#endif
  colour = u_fresnel == 1 ? mix(u_colour, reflected, schlick)
                          : u_reflectionWeight * reflected + u_baseWeight * u_colour;
#else
  // Glass: the refracted ray through the object, and the reflected one where Fresnel weighs it in
  // or the refraction is total.
  vec3 T = refract(I, N, u_eta);
  bool total = dot(T, T) == 0.0;
  vec3 reflected = vec3(0.0);
  vec3 refracted = vec3(0.0);
  measured = reflect(I, N);
  for (int ray = 0; ray < 2; ++ray) {
    bool wanted = ray == 0 ? (u_fresnel == 1 || total) : !total;
    if (!wanted) continue;
    vec3 truth;
    vec3 c = exactRadiance(v_worldPosition, ray == 0 ? reflect(I, N) : normalize(T), u_exactSelf,
                           ray == 1, truth);
    if (ray == 0) {
      reflected = c;
    } else {
      refracted = c;
    }
    measured = truth;
  }
  if (total) refracted = reflected;
  colour = u_fresnel == 1 ? mix(refracted, reflected, total ? 1.0 : schlick)
                          : u_reflectionWeight * refracted + u_baseWeight * u_colour;
#endif
  if (u_outputDirection == 1) colour = normalize(measured);
  writeOutputs(colour, v_worldPosition, N, false);
#if CAPTURE_OUTPUT == 0
  if (u_exactMark == 1) fragColour.a = 0.0;
#endif
}
#endif
