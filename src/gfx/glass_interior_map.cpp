#include "gfx/glass_interior_map.h"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/cube_faces.h"

namespace reflect {
namespace {

TextureHandle createCube(GLenum internalFormat, GLenum filter) {
  TextureHandle texture(genTexture());
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture.id());
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, internalFormat, GlassInteriorMap::kFaceSize,
                 GlassInteriorMap::kFaceSize);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  return texture;
}

}  // namespace

Result<GlassInteriorMap> GlassInteriorMap::create(const MeshBuffer& mesh,
                                                  const GlassInteriorProgram& program) {
  GlassInteriorMap map;
  map.centre_ = mesh.bounds().centre();
  map.radius_ = mesh.boundingRadius();
  if (!(map.radius_ > 0.0f)) return Result<GlassInteriorMap>::failure("glass mesh has no extent");
  // Depth along a face's axis never exceeds the radius; the near plane only has to stay inside
  // any surface a star-shaped mesh has around its centre.
  map.near_ = 1e-3f * map.radius_;
  map.far_ = 1.01f * map.radius_;
  // A depth texture is not filterable in GL ES 3.0 (a sampler reads it NEAREST). The normals are
  // read NEAREST too: blended across a cube's edge they bent rays at random (speckles; on
  // tests/data/glass-cube.json at t = 2.5 s, 400 x 400: 36.0 dB and 13 pixels off by more than
  // 32 levels with LINEAR, 41.0 dB and 2 with NEAREST), and a texel's normal then belongs to
  // the same surface as its depth.
  map.depths_ = createCube(GL_DEPTH_COMPONENT24, GL_NEAREST);
  map.normals_ = createCube(GL_RGBA8, GL_NEAREST);

  FramebufferHandle framebuffer(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, kFaceSize, kFaceSize);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // From inside, every face of the mesh is seen from behind or in front: keep the nearest.
  glDisable(GL_CULL_FACE);
  glUseProgram(program.id());
  const glm::mat4 model = glm::translate(glm::mat4(1.0f), -map.centre_);
  program.u().model.set(model);
  program.u().normalMatrix.set(glm::mat3(1.0f));
  const glm::mat4 projection = cubeFaceProjection(map.near_, map.far_);
  std::string error;
  for (int face = 0; face < 6 && error.empty(); ++face) {
    const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, map.normals_.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, target, map.depths_.id(), 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      error = "glass interior map: framebuffer incomplete";
      break;
    }
    // Where the mesh leaves a gap, the far plane: a search ends at the bounding sphere there.
    glClearColor(0.5f, 0.5f, 0.5f, 0.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const glm::mat4 vp = projection * cubeFaceView(glm::vec3(0.0f), face);
    program.u().viewProjection.set(vp);
    mesh.draw();
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGlError("glass interior map");
  if (!error.empty()) return Result<GlassInteriorMap>::failure(error);
  return map;
}

const GlassInteriorMap* GlassInteriorMaps::mapFor(const std::string& name, const MeshBuffer& mesh) {
  auto it = maps_.find(name);
  if (it != maps_.end()) return it->second.get();
  if (!program_) {
    Result<GlassInteriorProgram> built =
        GlassInteriorProgram::build("mesh.vert", "glass_interior.frag");
    if (!built) {
      error_ = built.error();
      maps_[name] = nullptr;
      return nullptr;
    }
    program_ = std::make_unique<GlassInteriorProgram>(built.take());
  }
  Result<GlassInteriorMap> made = GlassInteriorMap::create(mesh, *program_);
  if (!made) error_ = made.error();
  auto& slot = maps_[name];
  if (made) slot = std::make_unique<GlassInteriorMap>(made.take());
  return slot.get();
}

void GlassExitUniforms::setUnits() const {
  depths.set(kGlassDepthUnit);
  normals.set(kGlassNormalsUnit);
}

void GlassExitUniforms::set(const GlassInteriorMap& interior, const glm::mat4& model) const {
  // The map's space is the mesh's own, moved so that the map's centre is the origin.
  const glm::mat4 placed = model * glm::translate(glm::mat4(1.0f), interior.centre());
  const glm::mat4 unplaced = glm::inverse(placed);
  toMap.set(unplaced);
  fromMap.set(placed);
  normalFromMap.set(glm::transpose(glm::inverse(glm::mat3(placed))));
  map.set(glm::vec3(interior.near(), interior.far(), interior.radius()));
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(kGlassDepthUnit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, interior.depths());
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(kGlassNormalsUnit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, interior.normals());
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace reflect
