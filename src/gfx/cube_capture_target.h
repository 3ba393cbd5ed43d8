// The live environment of one probe: per stored layer, a cube texture of colours and, for the
// hierarchical search, the faces' depth codes and their min/max pyramid; one framebuffer and one
// depth renderbuffer shared by the six faces (they are drawn in turn).
//
// Depths (shaders/depth_encoding.glsl) live in integer textures read with texelFetch only (GLSL
// ES 3.00 has no texelFetch on cube samplers):
//  - the faces, per layer: a 2D array (RG16UI), one layer per cube face in GL face order, N x N:
//    each texel's (near, far) codes as the capture wrote them (a capture renders into it beside
//    the colour face);
//  - the pyramid, for both layers: one 2D texture with the six faces side by side and a mip per
//    level, level 0 a copy of the faces: RG16UI, or with two layers RGBA16UI, the second layer's
//    codes in B and A (one chain of draws builds both, one fetch reads both). With P the face
//    size rounded up to a power of two, level L's tile is P / 2^L texels square, so every tile
//    halves exactly and one draw builds a level for any run of neighbouring faces: one draw per
//    level when all six were captured, not six. Only the faces captured in a frame are rebuilt.
//    The search reads this texture alone.
// A level-L cell covers the 2^L x 2^L level-0 texels at its index times 2^L (clipped to N); each
// holds the min of their near codes and the max of their far codes (and of the backs found).
#pragma once

#include <array>
#include <string>

#include "core/result.h"
#include "gfx/depth_pyramid_programs.h"
#include "gfx/gl_handle.h"

namespace reflect {

struct CaptureFormat {
  int faceSize = 256;
  bool halfFloat = false;
  int depthBits = 24;
  bool mipmaps = false;
  // The first layer's colour mip chain is rebuilt after each capture (buildBoxChain) for the
  // irradiance projection (probe_irradiance.h) and lobe taps, which read it through samplers of
  // their own, while lookups still read level 0 alone (LINEAR), unless `mipmaps`.
  bool boxChain = false;
  bool depthChain = false;  // the hierarchical search's depths and pyramids
  int layers = 1;           // 1 or 2 (a second layer needs the depths)
  bool operator==(const CaptureFormat&) const = default;
};

class CubeCaptureTarget {
 public:
  // faceSize is clamped to [1, GL_MAX_CUBE_MAP_TEXTURE_SIZE]; the framebuffer is checked complete
  // (an RGBA16F face needs EXT_color_buffer_half_float or _float: the error says so).
  static Result<CubeCaptureTarget> create(const CaptureFormat& format);

  // Binds the framebuffer with `face` (0..5, GL order) of `layer` (0 or 1) as colour (and that
  // face's level-0 depths as the second colour attachment) and sets the viewport.
  void bindFace(int face, int layer) const;
  // Clears the bound face: colour to `colour` with alpha `alpha`, the depths' two channels to
  // `codes`, the depth buffer to the far plane.
  void clearFace(const float colour[3], float alpha, const unsigned codes[2]) const;
  // Binds `face` of the backs texture alone (shaders/capture_output.glsl, pass 3: the farthest
  // back of each object in front), clears it and the depth buffer, and keeps the farthest
  // fragment; endBackPass() restores the depth test.
  void bindBackPass(int face) const;
  static void endBackPass();
  // After the faces are drawn: rebuilds the pyramid's tiles of the faces in `faces` (bit f for
  // face f: the faces drawn this frame; the others' tiles still bound their unchanged depths)
  // from the layers' faces (and, for the first layer, the backs), then every layer's colour mip
  // chain when the format asks for `mipmaps`. Leaves the depth test off.
  void finish(const DepthPyramidPrograms& programs, unsigned faces) const;
  // The first layer's box chain (CaptureFormat::boxChain, where `mipmaps` has not built it).
  void buildBoxChain() const;

  GLuint texture(int layer = 0) const { return colour_[static_cast<size_t>(layer)].id(); }
  GLuint faceDepths(int layer = 0) const { return faceDepths_[static_cast<size_t>(layer)].id(); }
  GLuint pyramid() const { return pyramid_.id(); }
  GLuint backs() const { return backs_.id(); }
  int faceSize() const { return format_.faceSize; }
  // The last level: one cell a face (log2 of the face size rounded up to a power of two).
  int topLevel() const { return topLevel_; }
  const CaptureFormat& format() const { return format_; }

 private:
  std::array<TextureHandle, 2> colour_;
  std::array<TextureHandle, 2> faceDepths_;
  TextureHandle pyramid_;
  TextureHandle backs_;  // R16UI 2D array, level 0 only (two layers only)
  RenderbufferHandle depth_;
  FramebufferHandle framebuffer_;
  FramebufferHandle pyramidFramebuffer_;
  CaptureFormat format_;
  int topLevel_ = 0;
};

}  // namespace reflect
