// The skybox: a unit cube around the eye, seen through a view without translation. z = w puts it
// at the far plane, so with depth LEQUAL it fills only what nothing else covers.
layout(location = 0) in vec3 a_position;

uniform mat4 u_viewRotationProjection;

out vec3 v_direction;

void main() {
  v_direction = a_position;
  gl_Position = (u_viewRotationProjection * vec4(a_position, 1.0)).xyww;
}
