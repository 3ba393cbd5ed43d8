// The mirror: the live cube map looked up along the reflected view ray, mixed with the base
// colour as the course does (the weights sum past 1, so bright reflections clip to white).
in vec3 v_worldPosition;
in vec3 v_worldNormal;

uniform vec3 u_colour;
uniform vec3 u_viewPosition;
uniform float u_reflectionWeight;
uniform float u_baseWeight;
uniform samplerCube u_environment;

out vec4 fragColour;

void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 V = normalize(u_viewPosition - v_worldPosition);
  vec3 R = reflect(-V, N);
  vec3 environment = texture(u_environment, R).rgb;
  fragColour = vec4(u_reflectionWeight * environment + u_baseWeight * u_colour, 1.0);
}
