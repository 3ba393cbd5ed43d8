// Pick a pixel's rays (gfx/ray_lines.h): world-space line ends, each with its colour.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_colour;

uniform mat4 u_viewProjection;

out vec3 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = u_viewProjection * vec4(a_position, 1.0);
}
