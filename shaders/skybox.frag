// The skybox: the static cube map along the view direction.
in vec3 v_direction;

uniform samplerCube u_skybox;

out vec4 fragColour;

// Alpha 1: in a distance-storing capture, infinitely far.
void main() { fragColour = vec4(texture(u_skybox, v_direction).rgb, 1.0); }
