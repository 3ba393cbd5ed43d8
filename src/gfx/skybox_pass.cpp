#include "gfx/skybox_pass.h"

#include <glm/gtc/type_ptr.hpp>

namespace reflect {
namespace {

// A unit cube as 12 triangles (the inside is what is seen; culling is off anyway).
constexpr float kCube[] = {
    -1, -1, -1, 1,  -1, -1, 1,  1,  -1, -1, -1, -1, 1,  1,  -1, -1, 1,  -1,  // -Z
    -1, -1, 1,  1,  1,  1,  1,  -1, 1,  -1, -1, 1,  -1, 1,  1,  1,  1,  1,   // +Z
    -1, -1, -1, -1, 1,  -1, -1, 1,  1,  -1, -1, -1, -1, 1,  1,  -1, -1, 1,   // -X
    1,  -1, -1, 1,  1,  1,  1,  1,  -1, 1,  -1, -1, 1,  -1, 1,  1,  1,  1,   // +X
    -1, -1, -1, 1,  -1, 1,  1,  -1, -1, -1, -1, -1, -1, -1, 1,  1,  -1, 1,   // -Y
    -1, 1,  -1, 1,  1,  -1, 1,  1,  1,  -1, 1,  -1, 1,  1,  1,  -1, 1,  1,   // +Y
};

}  // namespace

Result<SkyboxPass::Program> SkyboxPass::build(bool capture) {
  Result<Program> built =
      Program::build("skybox.vert", "skybox.frag", false,
                     capture ? "#define CAPTURE_OUTPUT 1\n" : "#define CAPTURE_OUTPUT 0\n");
  if (!built) return built;
  glUseProgram(built.value().id());
  built.value().u().skybox.set(kEnvironmentUnit);
  built.value().u().capture.setUnits();
  glUseProgram(0);
  return built;
}

Result<SkyboxPass> SkyboxPass::create(const CubeFaces& faces) {
  Result<Program> main = build(false);
  if (!main) return Result<SkyboxPass>::failure(main.error());
  Result<Program> capture = build(true);
  if (!capture) return Result<SkyboxPass>::failure(capture.error());
  SkyboxPass pass;
  pass.main_ = main.take();
  pass.capture_ = capture.take();

  pass.faceSize_ = faces[0].width;
  pass.texture_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_CUBE_MAP, pass.texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (GLenum f = 0; f < 6; ++f) {
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, faces[f].width, faces[f].height,
                 0, GL_RGBA, GL_UNSIGNED_BYTE, faces[f].pixels.data());
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);

  pass.vao_ = VertexArrayHandle(genVertexArray());
  pass.vertices_ = BufferHandle(genBuffer());
  glBindVertexArray(pass.vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, pass.vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof kCube, kCube, GL_STATIC_DRAW);
  glEnableVertexAttribArray(kAttribPosition);
  glVertexAttribPointer(kAttribPosition, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindVertexArray(0);
  if (!checkGlError("create skybox"))
    return Result<SkyboxPass>::failure("GL error creating the skybox");
  return pass;
}

std::vector<std::string> SkyboxPass::unlisted() const {
  std::vector<std::string> out = main_.unlisted();
  for (const std::string& name : capture_.unlisted()) out.push_back(name);
  return out;
}

void SkyboxPass::draw(const glm::mat4& projection, const glm::mat4& view,
                      const CaptureState& pass) const {
  const glm::mat4 rotationOnly(glm::mat3{view});
  const glm::mat4 viewRotationProjection = projection * rotationOnly;
  glDepthFunc(GL_LEQUAL);
  const Program& p = pass.layer == 0 ? main_ : capture_;
  glUseProgram(p.program.id());
  p.uniforms->viewRotationProjection.set(viewRotationProjection);
  p.uniforms->capture.set(pass);
  glActiveTexture(GL_TEXTURE0 + kEnvironmentUnit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 36);
  glDepthFunc(GL_LESS);
}

}  // namespace reflect
