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

out vec4 fragColour;

void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_viewPosition);
  vec3 reflected = texture(u_environment, reflect(I, N)).rgb;
  float schlick = u_fresnelF0 + (1.0 - u_fresnelF0) * pow(1.0 - clamp(dot(-I, N), 0.0, 1.0), 5.0);
  vec3 colour;
  if (u_refracts == 1) {
    vec3 T = refract(I, N, u_eta);
    // Past the critical angle refract() returns a zero vector, and sampling a cube map with it is
    // undefined: all the light is reflected there.
    bool total = dot(T, T) == 0.0;
    vec3 refracted = total ? reflected : texture(u_environment, T).rgb;
    colour = u_fresnel == 1 ? mix(refracted, reflected, total ? 1.0 : schlick)
                            : u_reflectionWeight * refracted + u_baseWeight * u_colour;
  } else {
    colour = u_fresnel == 1 ? mix(u_colour, reflected, schlick)
                            : u_reflectionWeight * reflected + u_baseWeight * u_colour;
  }
  fragColour = vec4(colour, 1.0);
}
