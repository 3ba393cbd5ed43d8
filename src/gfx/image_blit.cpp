#include "gfx/image_blit.h"

namespace reflect {

Result<ImageBlit> ImageBlit::create() {
  return withBuiltProgram<decltype(program_)>(
      "fullscreen.vert", "image_blit.frag", [](auto program) {
        ImageBlit blit;
        blit.program_ = std::move(program);
        blit.vertexArray_ = VertexArrayHandle(genVertexArray());
        return blit;
      });
}

void ImageBlit::draw(const RgbaImage& image, int width, int height,
                     const std::array<uint8_t, 4>& background) {
  // The view is drawn every frame while it is on: the texture is kept and only refilled, and made
  // again only when the image's size changes (another face size, another canvas fit).
  glActiveTexture(GL_TEXTURE0);
  if (!texture_ || image.width != textureWidth_ || image.height != textureHeight_) {
    texture_ = TextureHandle(genTexture());
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, image.width, image.height);
    textureWidth_ = image.width;
    textureHeight_ = image.height;
  }
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                  image.pixels.data());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glUseProgram(program_.id());
  const Uniforms& u = program_.u();
  u.image.set(0);
  // Centred; a negative origin cuts the image equally on both sides.
  u.origin.set(glm::ivec2((width - image.width) / 2, (height - image.height) / 2));
  u.background.set(glm::vec3(background[0], background[1], background[2]) / 255.0f);
  glBindVertexArray(vertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace reflect
