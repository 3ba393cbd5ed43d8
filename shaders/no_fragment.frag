// The fragment stage a program that only transforms vertices still needs (irradiance_project.vert
// runs with the rasteriser off, so this never runs).
out vec4 o_colour;

void main() { o_colour = vec4(0.0); }
