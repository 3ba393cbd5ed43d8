// Ex12-1: the live cube map painted on an object, looked up along its object-space position
// (so a cube shows the six faces of its own capture), unlit.
in vec3 v_worldPosition;
in vec3 v_worldNormal;
in vec3 v_objectPosition;
uniform samplerCube u_environment;

#include "capture_output.glsl"

void main() {
  writeOutputs(texture(u_environment, v_objectPosition).rgb, v_worldPosition,
               normalize(v_worldNormal), false);
}
