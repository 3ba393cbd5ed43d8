// The skybox: the static cube map along the view direction. In a capture it is infinitely far.
in vec3 v_direction;
uniform samplerCube u_skybox;

#include "capture_output.glsl"

void main() {
  writeOutputs(texture(u_skybox, v_direction).rgb, vec3(0.0), vec3(0.0), true);
}
