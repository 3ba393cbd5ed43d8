#include "gfx/cube_readback.h"

#include <cmath>
#include <vector>

#include "core/irradiance.h"
#include "gfx/gl_handle.h"

namespace reflect {
namespace {

RgbaImage emptyFace(int size) {
  RgbaImage face;
  face.width = face.height = size;
  face.pixels.resize(static_cast<size_t>(size) * static_cast<size_t>(size) * 4);
  return face;
}

uint8_t toByte(float c) {
  return static_cast<uint8_t>(std::lround(std::fmin(std::fmax(c, 0.0f), 1.0f) * 255.0f));
}

// The colour attachment bound for reading, as RGBA8.
RgbaImage readColour(int size, bool halfFloat) {
  RgbaImage face = emptyFace(size);
  if (!halfFloat) {
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, face.pixels.data());
    return face;
  }
  std::vector<float> rgba(face.pixels.size());
  glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, rgba.data());
  for (size_t k = 0; k < rgba.size(); ++k) face.pixels[k] = toByte(rgba[k]);
  return face;
}

// The RG16UI depth codes bound for reading, as grey (near bright); with `zeroIsEmpty` (the backs,
// cleared to 0 where none was stored), code 0 as black.
RgbaImage readDistance(int size, bool zeroIsEmpty = false) {
  RgbaImage face = emptyFace(size);
  // RGBA_INTEGER / UNSIGNED_INT is the pair every GL ES 3.0 implementation reads an unsigned
  // integer colour buffer with.
  std::vector<GLuint> codes(face.pixels.size());
  glReadPixels(0, 0, size, size, GL_RGBA_INTEGER, GL_UNSIGNED_INT, codes.data());
  for (size_t texel = 0; texel < codes.size() / 4; ++texel) {
    const GLuint code = codes[texel * 4];
    const uint8_t grey =
        zeroIsEmpty && code == 0 ? 0 : static_cast<uint8_t>(255 - (code * 255 + 32767) / 65535);
    face.pixels[texel * 4 + 0] = face.pixels[texel * 4 + 1] = face.pixels[texel * 4 + 2] = grey;
    face.pixels[texel * 4 + 3] = 255;
  }
  return face;
}

std::string missingChannel(const CubeCaptureTarget& target, FacesChannel channel) {
  if (channel == FacesChannel::Distance && !target.format().depthChain) {
    return "the distance channel needs stored depths: set search to hierarchical";
  }
  if (channel == FacesChannel::SecondLayer && target.format().layers < 2) {
    return "the second-layer channel needs a second layer: set search to hierarchical and layers "
           "to 2";
  }
  return {};
}

}  // namespace

Result<CubeFaces> readCubeFaces(const CubeCaptureTarget& target, FacesChannel channel) {
  if (const std::string missing = missingChannel(target, channel); !missing.empty()) {
    return Result<CubeFaces>::failure(missing);
  }
  const int size = target.faceSize();
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  FramebufferHandle framebuffer(generateOne<glGenFramebuffers>());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
  CubeFaces faces;
  for (int face = 0; face < 6; ++face) {
    if (channel == FacesChannel::Distance) {
      glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target.faceDepths(0), 0,
                                face);
      faces[static_cast<size_t>(face)] = readDistance(size);
    } else {
      const int layer = channel == FacesChannel::SecondLayer ? 1 : 0;  // irradiance: the colours'
      glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                             static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face),
                             target.texture(layer), 0);
      faces[static_cast<size_t>(face)] = readColour(size, target.format().halfFloat);
    }
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
  // Projected on the CPU from the colours just read, as irradiance_project.vert projects the box
  // chain on the GPU (both weigh each texel by its solid angle): the GPU's coefficients stay in
  // their uniform buffer, which WebGL2 cannot read back.
  if (channel == FacesChannel::Irradiance) return irradianceCube(projectIrradiance(faces), size);
  return faces;
}

Result<RgbaImage> readBacksFace(const CubeCaptureTarget& target, int face) {
  if (target.format().layers < 2) {
    return Result<RgbaImage>::failure("the backs are stored only with a second layer");
  }
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  FramebufferHandle framebuffer(generateOne<glGenFramebuffers>());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
  glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target.backs(), 0, face);
  // The same read as the distances' (R16UI reads back through RGBA_INTEGER too).
  RgbaImage image = readDistance(target.faceSize(), true);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
  return image;
}

}  // namespace reflect
