// Glass seen through both surfaces, for a mesh that is not a sphere (a sphere has its closed form
// in environment.frag): where the refracted ray leaves is searched for in the object's own
// interior map (gfx/glass_interior_map; GPU Gems 3, ch. 17). The map stores, for each direction
// from the object's centre, the depth of its surface along the face's axis and the surface's
// outward normal, in the mesh's coordinates; the ray is moved into them, searched, and the exit
// point and its normal moved back. Only the program built with GLASS_EXIT 1 has any of this: a
// software rasteriser would pay for the search on every reflector if a uniform switched it.
#if GLASS_EXIT == 1
uniform highp samplerCube u_glassDepths;    // window depths of the nearest surface (NEAREST)
uniform mediump samplerCube u_glassNormals;  // its outward normal * 0.5 + 0.5
uniform highp mat4 u_glassToMap;             // world to the map's space (mesh, centre at 0)
uniform highp mat4 u_glassFromMap;           // and back
uniform highp mat3 u_glassNormalFromMap;     // normals from the map's space to world
uniform highp vec3 u_glassMap;               // the map's near and far planes, the mesh's radius

// Linear steps along the chord of the bounding sphere, then refinements of the crossing found.
// An exit closer than a step to the entry (a corner cut short) is still found: the first step's
// bracket starts at the entry.
const int kGlassSteps = 16;
const int kGlassBisections = 2;
const int kGlassSecants = 3;
// As the reference (kMaxInternalReflections): after them the ray goes on from the last wall.
const int kGlassBounces = 8;

// How far inside the object x (map space) lies, measured along the axis of x's cube face: the
// stored surface's depth minus x's own. Positive inside, negative outside; across a face edge
// the sign stays continuous because both depths change axis together.
highp float insideBy(highp vec3 x) {
  highp vec3 a = abs(x);
  highp float z = max(a.x, max(a.y, a.z));
  highp float n = u_glassMap.x, f = u_glassMap.y;
  highp float stored = n * f / (f - texture(u_glassDepths, x).r * (f - n));
  return stored - z;
}

// The ray p + t d (map space; p on the surface, d pointing inwards) where it leaves the object.
highp float exitAlong(highp vec3 p, highp vec3 d) {
  highp float r = u_glassMap.z;
  highp float a = dot(d, d), b = dot(p, d), c = dot(p, p) - r * r;
  highp float tEnd = (-b + sqrt(max(b * b - a * c, 0.0))) / a;  // the bounding sphere's far side
  // The crossing lies in [t0, t1]: inside at t0 (the entry counts as inside), outside at t1.
  highp float t0 = 0.0, g0 = 0.0, t1 = tEnd, g1 = -1.0;
  for (int i = 1; i <= kGlassSteps; ++i) {
    highp float t = tEnd * float(i) / float(kGlassSteps);
    highp float g = insideBy(p + t * d);
    if (g < 0.0) {
      t1 = t;
      g1 = g;
      break;
    }
    t0 = t;
    g0 = g;
  }
  // The entry's own value is 0 up to the map's rounding, useless to a secant: halve first.
  for (int k = 0; k < kGlassBisections + kGlassSecants; ++k) {
    highp float t = k < kGlassBisections || g0 <= 0.0 ? 0.5 * (t0 + t1)
                                                      : t0 + (t1 - t0) * g0 / (g0 - g1);
    highp float g = insideBy(p + t * d);
    if (g < 0.0) {
      t1 = t;
      g1 = g;
    } else {
      t0 = t;
      g0 = g;
    }
  }
  // The secant's last guess, then the tangent plane there: exact on a flat face, where the
  // depths between texel centres are no plane (the map is read NEAREST).
  highp float t = g0 > 0.0 ? t0 + (t1 - t0) * g0 / (g0 - g1) : 0.5 * (t0 + t1);
  highp vec3 x = p + t * d;
  highp vec3 normal = texture(u_glassNormals, x).rgb * 2.0 - 1.0;
  highp float along = dot(normal, d);
  if (along > 0.0) {
    highp vec3 ax = abs(x);
    highp float z = max(ax.x, max(ax.y, ax.z));
    highp vec3 surface = x * ((insideBy(x) + z) / z);
    t = clamp(t + dot(normal, surface - x) / along, t0, t1);
  }
  return t;
}

// From world point `origin` on the object along `d` (refracted in): the last surface point and
// the ray that goes on from it, refracted out (n to air), reflected inside on total internal
// reflection.
void leaveGlassMesh(inout vec3 origin, inout vec3 d) {
  for (int bounce = 0; bounce < kGlassBounces; ++bounce) {
    highp vec3 p = (u_glassToMap * vec4(origin, 1.0)).xyz;
    highp vec3 dm = mat3(u_glassToMap) * d;
    highp vec3 x = p + exitAlong(p, dm) * dm;
    origin = (u_glassFromMap * vec4(x, 1.0)).xyz;
    vec3 normal = u_glassNormalFromMap * (texture(u_glassNormals, x).rgb * 2.0 - 1.0);
    vec3 inward = dot(normal, d) > 0.0 ? -normalize(normal) : normalize(normal);
    vec3 out_ = refract(d, inward, 1.0 / u_eta);
    if (dot(out_, out_) > 0.0) {
      d = normalize(out_);
      return;
    }
    d = reflect(d, inward);
  }
}
#endif
