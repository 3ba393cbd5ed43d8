// Mirror and glass: the environment (live probe or static skybox) looked up along the reflected
// or refracted view ray, mixed with the base colour. The course's mirror is the fixed mix
// 0.78 x environment + 0.3 x base (the weights sum past 1, so bright reflections clip to white);
// with Fresnel on, Schlick's approximation weighs reflection against the base (mirror) or against
// refraction (glass) instead.
in vec3 v_worldPosition;
in vec3 v_worldNormal;

uniform vec3 u_colour;
uniform vec3 u_viewPosition;
uniform float u_reflectionWeight;
uniform float u_baseWeight;
uniform int u_refracts;      // 0 mirror, 1 glass
uniform float u_eta;         // n1 / n2 for refract(): air to the material
uniform float u_fresnelF0;   // ((n - 1) / (n + 1))^2
uniform int u_fresnel;       // 0 fixed mix, 1 Schlick
uniform samplerCube u_environment;
// Distance-corrected lookup (DISTANCE_ITERATIONS > 0, defined when the program is built: a
// runtime switch would not do, as software rasterisers run both sides of a branch): the
// capture's alpha holds each texel's distance d from u_probeCentre, encoded as d / (d + 1).
uniform vec3 u_probeCentre;
uniform float u_distanceUnit;      // the capture's near plane (distances are stored in its units)
uniform int u_outputDirection;     // 1: write the looked-up direction instead (for measuring)

out vec4 fragColour;

// The direction from the probe centre to where the ray from the surface point x along d meets
// the captured surroundings (the capture's alpha holds each texel's distance from the centre).
// As in the distance-impostor method: a linear search along the ray, parametrised so that a in
// [0, 1) covers the whole ray (t = a / (1 - a) units), finds the first sample behind the stored
// surface (so thin, near objects are not skipped), then DISTANCE_ITERATIONS secant steps refine
// the crossing. With no iterations it is d, the course's plain lookup.
const int kLinearSteps = 12;

float storedDistance(vec3 direction) {
  float a = min(texture(u_environment, direction).a, 0.9999);
  return a / (1.0 - a);
}

// Positions here are in units of the capture's near plane, as the stored distances are.
float behind(vec3 x, vec3 d, float a) {  // > 0 in front of the stored surface, < 0 behind it
  vec3 p = x + (a / (1.0 - a)) * d;
  return storedDistance(p) - length(p);
}

vec3 lookupDirection(vec3 d) {
#if DISTANCE_ITERATIONS == 0
  return d;
#else
  vec3 x = (v_worldPosition - u_probeCentre) / u_distanceUnit;
  float previousA = 0.0;
  float previousF = behind(x, d, 0.0);
  float a = 0.0;
  float f = previousF;
  bool crossed = false;
  for (int i = 1; i <= kLinearSteps; ++i) {
    a = float(i) / float(kLinearSteps + 1);
    f = behind(x, d, a);
    if (f < 0.0) {
      crossed = true;
      break;
    }
    previousA = a;
    previousF = f;
  }
  if (!crossed) return d;  // nothing stored along the ray: the far background, seen along d
  for (int i = 0; i < DISTANCE_ITERATIONS; ++i) {
    float middle = previousA + (a - previousA) * previousF / max(previousF - f, 1e-6);
    float fm = behind(x, d, middle);
    if (fm < 0.0) {
      a = middle;
      f = fm;
    } else {
      previousA = middle;
      previousF = fm;
    }
  }
  float hit = previousA + (a - previousA) * previousF / max(previousF - f, 1e-6);
  return x + (hit / (1.0 - hit)) * d;
#endif
}

void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_viewPosition);
  vec3 reflectedDirection = lookupDirection(reflect(I, N));
  if (u_outputDirection == 1) {
    fragColour = vec4(normalize(reflectedDirection), 1.0);
    return;
  }
  vec3 reflected = texture(u_environment, reflectedDirection).rgb;
  float schlick = u_fresnelF0 + (1.0 - u_fresnelF0) * pow(1.0 - clamp(dot(-I, N), 0.0, 1.0), 5.0);
  vec3 colour;
  if (u_refracts == 1) {
    vec3 T = refract(I, N, u_eta);
    // Past the critical angle refract() returns a zero vector, and sampling a cube map with it is
    // undefined: all the light is reflected there.
    bool total = dot(T, T) == 0.0;
    vec3 refracted = total ? reflected : texture(u_environment, lookupDirection(T)).rgb;
    colour = u_fresnel == 1 ? mix(refracted, reflected, total ? 1.0 : schlick)
                            : u_reflectionWeight * refracted + u_baseWeight * u_colour;
  } else {
    colour = u_fresnel == 1 ? mix(u_colour, reflected, schlick)
                            : u_reflectionWeight * reflected + u_baseWeight * u_colour;
  }
  fragColour = vec4(colour, 1.0);
}
