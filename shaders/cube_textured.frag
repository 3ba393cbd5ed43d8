// Ex12-1: the live cube map painted on an object, looked up along its object-space position
// (so a cube shows the six faces of its own capture), unlit.
in vec3 v_objectPosition;

uniform samplerCube u_environment;

out vec4 fragColour;

void main() { fragColour = vec4(texture(u_environment, v_objectPosition).rgb, 1.0); }
