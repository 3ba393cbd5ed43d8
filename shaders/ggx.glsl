// The GGX lobe of a rough mirror: src/core/ggx.h's functions, term by term and with the same
// names (that header says what a rough mirror sees), for the exact mode's lobe rays
// (exact_shade.glsl) and, frameAround, for the prefilter pass (prefilter.frag), whose lobe the C++
// computes (prefilterLobe).

const float kGgxPi = 3.14159265358979;

vec2 hammersley(uint i, uint n) {
  uint bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return vec2(float(i) / float(n), float(bits) * 2.3283064365386963e-10);
}

mat3 frameAround(vec3 n) {
  vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 tangent = normalize(cross(up, n));
  vec3 bitangent = cross(n, tangent);
  return mat3(tangent, bitangent, n);
}

// ggxHalfVector in a frame made once for many samples (the lobe taps); `nDotH` its cos(theta).
vec3 ggxHalfVectorInFrame(vec2 u, float alpha, mat3 frame, out float nDotH) {
  float phi = 2.0 * kGgxPi * u.x;
  float a2 = alpha * alpha;
  nDotH = sqrt((1.0 - u.y) / (1.0 + (a2 - 1.0) * u.y));
  float sinTheta = sqrt(max(1.0 - nDotH * nDotH, 0.0));
  return frame * vec3(sinTheta * cos(phi), sinTheta * sin(phi), nDotH);
}

vec3 ggxHalfVector(vec2 u, float alpha, vec3 n) {
  float nDotH;
  return normalize(ggxHalfVectorInFrame(u, alpha, frameAround(n), nDotH));
}

float ggxDistribution(float nDotH, float alpha) {
  float a2 = alpha * alpha;
  float d = nDotH * nDotH * (a2 - 1.0) + 1.0;
  return a2 / (kGgxPi * d * d);
}

float smithG1(float cosine, float alpha) {
  float a2 = alpha * alpha;
  return 2.0 * cosine / (cosine + sqrt(a2 + (1.0 - a2) * cosine * cosine));
}

vec3 specularDominantDirection(vec3 n, vec3 r, float alpha) {
  float s = 1.0 - alpha;
  return normalize(mix(n, r, s * (sqrt(s) + alpha)));
}

float lobeSampleWeight(float nDotV, float nDotL, float nDotH, float vDotH, float alpha) {
  if (nDotL <= 0.0 || nDotV <= 0.0 || nDotH <= 0.0) return 0.0;
  return smithG1(nDotV, alpha) * smithG1(nDotL, alpha) * vDotH / (nDotV * nDotH);
}
