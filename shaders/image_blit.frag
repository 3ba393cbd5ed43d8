// Shows an image made on the CPU (the faces view's cross) on the framebuffer, texel for pixel:
// u_origin is where the image's bottom-left pixel lands (the image is centred, never scaled, so a
// teacher's screenshot holds exactly the read-back's pixels). Outside it: the background.
uniform highp sampler2D u_image;
uniform ivec2 u_origin;
uniform vec3 u_background;

out vec4 fragColour;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
  ivec2 size = textureSize(u_image, 0);
  bool inside = p.x >= 0 && p.y >= 0 && p.x < size.x && p.y < size.y;
  // The image is uploaded top row first; the framebuffer's row 0 is its bottom.
  fragColour = inside ? texelFetch(u_image, ivec2(p.x, size.y - 1 - p.y), 0)
                      : vec4(u_background, 1.0);
}
