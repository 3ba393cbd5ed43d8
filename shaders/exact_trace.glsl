// The exact mode (SEARCH 3, search: exact): a mirror or glass pixel's ray is traced against the
// scene's triangles instead of looked up in a cube map, and what it meets is shaded as a capture
// would shade it: Phong lit as seen from the main camera's eye, a mirror reflecting again, glass
// crossed through both surfaces, a cube-textured object traced from its probe centre, the sky
// (or the clear colour) where nothing is met. src/reference/reference_renderer.h says what the
// exact answer is; this follows it term by term, with one limit: glass met by a ray that has
// already left a surface sees, for its Fresnel-reflected share, the sky along the reflected ray
// (one ray a bounce: no tree of rays in a fragment shader).
//
// The scene is two levels of BVH (core/bvh.h) in float textures, kBvhTextureWidth texels a row:
//  u_exactNodes      every mesh's nodes, 2 texels each: (min, first), (max, count); first is the
//                    left child (the right one follows it) or, in a leaf, the first triangle
//  u_exactPositions  3 texels a triangle (object space), in leaf order
//  u_exactNormals    3 texels a triangle: the vertices' normals
//  u_exactScene      kInstanceTexels per object (its inverse model's rows, normal matrix columns,
//                    colour and material, mix weights, probe centre and root node, self epsilon),
//                    then the top level's nodes (from u_exactTopNodes) and items (u_exactTopOrder)
// Rays go into each object's space unnormalised, so t is the same parameter in both.
#if SEARCH == 3
// Tracing needs full precision whatever the shader's default (mediump would lose the triangles).
precision highp float;
precision highp int;
const int kExactWidth = 1024;       // kBvhTextureWidth
const int kExactInstance = 10;      // kInstanceTexels
const int kExactStack = 33;         // kBvhMaxDepth + 1
const int kExactMaxBounces = 4;     // reference_renderer.h's kMaxBounces
const int kExactMaxInternal = 8;    // and kMaxInternalReflections
const float kExactFar = 3.0e38;     // no hit

uniform highp sampler2D u_exactNodes;
uniform highp sampler2D u_exactPositions;
uniform highp sampler2D u_exactNormals;
uniform highp sampler2D u_exactScene;
uniform samplerCube u_exactSky;
uniform int u_exactHasSky;    // 0: the clear colour where nothing is met
uniform vec3 u_exactClear;
uniform int u_exactSelf;      // the object being drawn
uniform int u_exactTopNodes;
uniform int u_exactTopOrder;
uniform int u_exactEmpty;     // 1: nothing to trace
uniform vec3 u_exactLight;
uniform vec4 u_exactPhong;    // ambient, diffuse, specular, shininess
uniform vec3 u_exactEye;      // the main camera's eye: captures are lit as seen from it
uniform int u_exactMark;      // 1: alpha 0 on this pass's pixels (the error view's reflector mask)

highp vec4 exactFetch(highp sampler2D s, int i) {
  return texelFetch(s, ivec2(i % kExactWidth, i / kExactWidth), 0);
}

struct ExactHit {
  float t;
  int instance;  // -1: nothing met
  int slot;      // the triangle, in leaf order
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
// when >= 0): the top level, then each object's own tree, both walked nearer child first.
ExactHit exactTrace(vec3 origin, vec3 direction, float tMin, int skip, int only) {
  ExactHit best;
  best.t = kExactFar;
  best.instance = -1;
  best.slot = -1;
  best.u = 0.0;
  best.v = 0.0;
  if (u_exactEmpty == 1) return best;
  vec3 invD = exactInverse(direction);
  int topNode[kExactStack];
  float topEntry[kExactStack];
  int top = 0;
  int node = 0;
  vec4 r0 = exactFetch(u_exactScene, u_exactTopNodes);
  vec4 r1 = exactFetch(u_exactScene, u_exactTopNodes + 1);
  if (exactBoxEntry(r0.xyz, r1.xyz, origin, invD, tMin, best.t) >= kExactFar) return best;
  for (;;) {
    vec4 a = exactFetch(u_exactScene, u_exactTopNodes + 2 * node);
    vec4 b = exactFetch(u_exactScene, u_exactTopNodes + 2 * node + 1);
    int first = int(a.w);
    int count = int(b.w);
    bool descended = false;
    if (count > 0) {
      for (int k = 0; k < count; ++k) {
        int instance = int(exactFetch(u_exactScene, u_exactTopOrder + first + k).x);
        if (instance == skip || (only >= 0 && instance != only)) continue;
        int base = instance * kExactInstance;
        int root = int(exactFetch(u_exactScene, base + 8).w);
        if (root < 0) continue;
        vec4 m0 = exactFetch(u_exactScene, base);
        vec4 m1 = exactFetch(u_exactScene, base + 1);
        vec4 m2 = exactFetch(u_exactScene, base + 2);
        vec3 o = vec3(dot(m0, vec4(origin, 1.0)), dot(m1, vec4(origin, 1.0)),
                      dot(m2, vec4(origin, 1.0)));
        vec3 d = vec3(dot(m0.xyz, direction), dot(m1.xyz, direction), dot(m2.xyz, direction));
        vec3 inv = exactInverse(d);
        // The object's own tree.
        int meshNode[kExactStack];
        float meshEntry[kExactStack];
        int sp = 0;
        int n = root;
        vec4 q0 = exactFetch(u_exactNodes, 2 * root);
        vec4 q1 = exactFetch(u_exactNodes, 2 * root + 1);
        if (exactBoxEntry(q0.xyz, q1.xyz, o, inv, tMin, best.t) >= kExactFar) continue;
        for (;;) {
          vec4 na = exactFetch(u_exactNodes, 2 * n);
          vec4 nb = exactFetch(u_exactNodes, 2 * n + 1);
          int nFirst = int(na.w);
          int nCount = int(nb.w);
          bool down = false;
          if (nCount > 0) {
            for (int s = nFirst; s < nFirst + nCount; ++s) {
              vec3 v0 = exactFetch(u_exactPositions, 3 * s).xyz;
              vec3 e1 = exactFetch(u_exactPositions, 3 * s + 1).xyz - v0;
              vec3 e2 = exactFetch(u_exactPositions, 3 * s + 2).xyz - v0;
              vec3 p = cross(d, e2);
              float det = dot(e1, p);
              if (det == 0.0) continue;
              float invDet = 1.0 / det;
              vec3 sv = o - v0;
              float u = dot(sv, p) * invDet;
              if (u < 0.0 || u > 1.0) continue;
              vec3 q = cross(sv, e1);
              float v = dot(d, q) * invDet;
              if (v < 0.0 || u + v > 1.0) continue;
              float t = dot(e2, q) * invDet;
              if (t > tMin && t < best.t) {
                best.t = t;
                best.instance = instance;
                best.slot = s;
                best.u = u;
                best.v = v;
              }
            }
          } else {
            vec4 l0 = exactFetch(u_exactNodes, 2 * nFirst);
            vec4 l1 = exactFetch(u_exactNodes, 2 * nFirst + 1);
            vec4 g0 = exactFetch(u_exactNodes, 2 * nFirst + 2);
            vec4 g1 = exactFetch(u_exactNodes, 2 * nFirst + 3);
            float tl = exactBoxEntry(l0.xyz, l1.xyz, o, inv, tMin, best.t);
            float tr = exactBoxEntry(g0.xyz, g1.xyz, o, inv, tMin, best.t);
            if (tl < kExactFar || tr < kExactFar) {
              bool leftFirst = tl <= tr;
              n = leftFirst ? nFirst : nFirst + 1;
              float farEntry = leftFirst ? tr : tl;
              if (farEntry < kExactFar) {
                meshNode[sp] = leftFirst ? nFirst + 1 : nFirst;
                meshEntry[sp] = farEntry;
                ++sp;
              }
              down = true;
            }
          }
          if (down) continue;
          bool found = false;
          while (sp > 0) {
            --sp;
            if (meshEntry[sp] <= best.t) {
              n = meshNode[sp];
              found = true;
              break;
            }
          }
          if (!found) break;
        }
      }
    } else {
      vec4 l0 = exactFetch(u_exactScene, u_exactTopNodes + 2 * first);
      vec4 l1 = exactFetch(u_exactScene, u_exactTopNodes + 2 * first + 1);
      vec4 g0 = exactFetch(u_exactScene, u_exactTopNodes + 2 * first + 2);
      vec4 g1 = exactFetch(u_exactScene, u_exactTopNodes + 2 * first + 3);
      float tl = exactBoxEntry(l0.xyz, l1.xyz, origin, invD, tMin, best.t);
      float tr = exactBoxEntry(g0.xyz, g1.xyz, origin, invD, tMin, best.t);
      if (tl < kExactFar || tr < kExactFar) {
        bool leftFirst = tl <= tr;
        node = leftFirst ? first : first + 1;
        float farEntry = leftFirst ? tr : tl;
        if (farEntry < kExactFar) {
          topNode[top] = leftFirst ? first + 1 : first;
          topEntry[top] = farEntry;
          ++top;
        }
        descended = true;
      }
    }
    if (descended) continue;
    bool found = false;
    while (top > 0) {
      --top;
      if (topEntry[top] <= best.t) {
        node = topNode[top];
        found = true;
        break;
      }
    }
    if (!found) break;
  }
  return best;
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
  mat3 normalMatrix = mat3(exactFetch(u_exactScene, base + 3).xyz,
                           exactFetch(u_exactScene, base + 4).xyz,
                           exactFetch(u_exactScene, base + 5).xyz);
  return normalize(normalMatrix * n);
}

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
    if (glass >= 0) tMin = exactFetch(u_exactScene, glass * kExactInstance + 9).x;
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
      float n = exactFetch(u_exactScene, g * kExactInstance + 7).z;
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
    if (first) {
      first = false;
      truth = h.instance >= 0 ? normalize(p - u_probeCentre) : dir;
    }
    if (h.instance < 0) {
      result = exactBackground(dir);
      break;
    }
    int base = h.instance * kExactInstance;
    vec4 look = exactFetch(u_exactScene, base + 6);
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
    vec4 weightsOf = exactFetch(u_exactScene, base + 7);  // reflection, base, ior, fresnel
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
      vec4 m0 = exactFetch(u_exactScene, base);
      vec4 m1 = exactFetch(u_exactScene, base + 1);
      vec4 m2 = exactFetch(u_exactScene, base + 2);
      vec3 objectPosition = vec3(dot(m0, vec4(p, 1.0)), dot(m1, vec4(p, 1.0)), dot(m2, vec4(p, 1.0)));
      if (dot(objectPosition, objectPosition) == 0.0) {
        result = exactBackground(vec3(0.0, 0.0, 1.0));
        break;
      }
      nextOrigin = exactFetch(u_exactScene, base + 8).xyz;
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

// environment.frag's main() with every environment traced: the reflected ray (a mirror; glass
// with Fresnel or at total internal reflection), and glass's refracted ray from inside the object.
void exactMain() {
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_viewPosition);
  float schlick = u_fresnelF0 + (1.0 - u_fresnelF0) * pow(1.0 - clamp(dot(-I, N), 0.0, 1.0), 5.0);
  vec3 T = u_refracts == 1 ? refract(I, N, u_eta) : vec3(0.0);
  bool total = dot(T, T) == 0.0;
  vec3 reflected = vec3(0.0);
  vec3 refracted = vec3(0.0);
  vec3 measured = reflect(I, N);
  for (int ray = 0; ray < 2; ++ray) {
    bool wanted = ray == 0 ? (u_refracts == 0 || u_fresnel == 1 || total)
                           : (u_refracts == 1 && !total);
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
  vec3 colour;
  if (u_refracts == 1) {
    if (total) refracted = reflected;
    colour = u_fresnel == 1 ? mix(refracted, reflected, total ? 1.0 : schlick)
                            : u_reflectionWeight * refracted + u_baseWeight * u_colour;
  } else {
    colour = u_fresnel == 1 ? mix(u_colour, reflected, schlick)
                            : u_reflectionWeight * reflected + u_baseWeight * u_colour;
  }
  if (u_outputDirection == 1) colour = normalize(measured);
  writeOutputs(colour, v_worldPosition, N, false);
  if (u_exactMark == 1 && u_captureLayer == 0) fragColour.a = 0.0;
}
#endif
