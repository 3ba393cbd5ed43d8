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
// Distance-corrected lookup: the capture's alpha holds each texel's distance from u_probeCentre.
uniform int u_distanceIterations;  // 0 = plain lookup along the ray direction (the course)
uniform vec3 u_probeCentre;
uniform int u_outputDirection;     // 1: write the looked-up direction instead (for measuring)

out vec4 fragColour;

// The direction from the probe centre to where the ray from the surface point x along d meets
// the captured surroundings: Newton steps on f(t) = dist(x + t d) - |x + t d| = 0, starting from
// the distance seen along d itself. With no iterations it is d, the course's plain lookup.
vec3 lookupDirection(vec3 d) {
  if (u_distanceIterations == 0) return d;
  vec3 x = v_worldPosition - u_probeCentre;
  float t = texture(u_environment, d).a;
  for (int i = 0; i < u_distanceIterations; ++i) {
    vec3 p = x + t * d;
    float len = max(length(p), 1e-4);
    // d|p|/dt = dot(p/|p|, d); keep the step sane where the ray runs across the view.
    t += (texture(u_environment, p).a - len) / max(dot(p / len, d), 0.2);
    t = max(t, 0.0);
  }
  return x + t * d;
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
