// The skybox: the static cube map along the view direction.
in vec3 v_direction;

uniform samplerCube u_skybox;
uniform float u_alpha;  // 1, or in a distance-storing capture the far distance (the sky is far)

out vec4 fragColour;

void main() { fragColour = vec4(texture(u_skybox, v_direction).rgb, u_alpha); }
