// The course's shading, written once: Phong with the scene light's constants, Schlick's Fresnel,
// and how a mirror or glass mixes what it sees with its base colour. phong.frag, environment.frag
// and the exact tracer (exact_shade.glsl) all shade with these; src/reference/reference_shading.h
// mirrors each function here term by term, with the same names in the same order, and
// tests/reference/shading_equivalence_test.cpp holds the two equal on sample inputs.

// Per-fragment Phong: ambient and diffuse take the object colour, white specular only where the
// light reaches the front of the surface. `terms` = (ambient, diffuse, specular, shininess).
// Unclamped: a capture texel or the frame's byte clamps it.
// phongLit: the same with the ambient light given per channel (a probe-lit object's irradiance,
// irradiance.glsl); phongShade's is the constant terms.x.
vec3 phongLit(vec3 colour, vec3 p, vec3 n, vec3 light, vec3 eye, vec3 ambient, vec4 terms) {
  vec3 L = normalize(light - p);
  vec3 V = normalize(eye - p);
  float nDotL = max(dot(n, L), 0.0);
  vec3 c = colour * (ambient + terms.y * nDotL);
  if (nDotL > 0.0) {
    vec3 R = reflect(-L, n);
    c += vec3(terms.z * pow(clamp(dot(R, V), 0.0, 1.0), terms.w));
  }
  return c;
}

vec3 phongShade(vec3 colour, vec3 p, vec3 n, vec3 light, vec3 eye, vec4 terms) {
  return phongLit(colour, p, n, light, eye, vec3(terms.x), terms);
}

// ((n - 1) / (n + 1))^2, the share reflected at normal incidence (core/fresnel.h's fresnelF0,
// which the C++ hands environment.frag as u_fresnelF0; the tracer reads indices, so it needs
// this).
float fresnelF0(float ior) {
  float n = max(ior, 1e-3);
  return ((n - 1.0) / (n + 1.0)) * ((n - 1.0) / (n + 1.0));
}

// Schlick: F0 + (1 - F0) (1 - clamp(V.N, 0, 1))^5, the share reflected towards the viewer.
float schlickWeight(float f0, vec3 toViewer, vec3 normal) {
  return f0 + (1.0 - f0) * pow(1.0 - clamp(dot(toViewer, normal), 0.0, 1.0), 5.0);
}

// A reflector's colour as a function of what its ray sees: add + weight * seen. One form for
// the direct draw and for the tracer's bounces, which unwind a chain of them.
struct Blend {
  vec3 add;
  float weight;
};

vec3 blended(Blend b, vec3 seen) { return b.add + b.weight * seen; }

// The course's fixed mix: reflectionWeight x what is seen + baseWeight x the base colour (0.78
// and 0.3 in the course: they sum past 1, so bright reflections clip to white).
Blend courseMix(vec3 colour, float reflectionWeight, float baseWeight) {
  return Blend(baseWeight * colour, reflectionWeight);
}

// A mirror, applied to what the reflected ray sees: with Fresnel mix(colour, seen, schlick),
// else the course's mix.
Blend mirrorBlend(vec3 colour, float reflectionWeight, float baseWeight, bool fresnel,
                  float schlick) {
  if (fresnel) return Blend((1.0 - schlick) * colour, schlick);
  return courseMix(colour, reflectionWeight, baseWeight);
}

// Glass, applied to what the refracted ray sees, or at total internal reflection (`total`) to
// what the reflected ray sees: with Fresnel mix(refracted, reflected, schlick), all of the
// reflection where it is total; else the course's mix.
Blend glassBlend(vec3 colour, vec3 reflected, bool total, float reflectionWeight,
                 float baseWeight, bool fresnel, float schlick) {
  if (!fresnel) return courseMix(colour, reflectionWeight, baseWeight);
  if (total) return Blend(vec3(0.0), 1.0);
  return Blend(schlick * reflected, 1.0 - schlick);
}
