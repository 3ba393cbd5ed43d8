// Pick a pixel's rays: flat colour, drawn over the finished frame.
in vec3 v_colour;

out vec4 fragColour;

void main() {
  fragColour = vec4(v_colour, 1.0);
}
