// The live environment of one probe: per stored layer, a cube texture of colours and, for the
// hierarchical search, a depth chain; one framebuffer and one depth renderbuffer shared by the six
// faces (they are drawn in turn).
//
// The depth chain is a 2D array texture, one layer per cube face in GL face order, RG16UI: at
// level 0 each texel holds the depth code of what the face saw there (shaders/depth_encoding.glsl)
// twice, and each level above holds the min and max of the 2x2 texels below it. A 2D array, not a
// cube, because GLSL ES 3.00 has no texelFetch on cube samplers, and the search addresses texels
// of a face and level exactly.
#pragma once

#include <array>
#include <string>

#include "core/result.h"
#include "gfx/gl_handle.h"

namespace reflect {

struct CaptureFormat {
  int faceSize = 256;
  bool halfFloat = false;
  int depthBits = 24;
  bool mipmaps = false;
  bool depthChain = false;  // the hierarchical search's min/max chains
  int layers = 1;           // 1 or 2 (a second layer needs the depth chain)
  bool operator==(const CaptureFormat&) const = default;
};

class CubeCaptureTarget {
 public:
  // faceSize is clamped to [1, GL_MAX_CUBE_MAP_TEXTURE_SIZE]; the framebuffer is checked complete
  // (an RGBA16F face needs EXT_color_buffer_half_float or _float: the error says so).
  static Result<CubeCaptureTarget> create(const CaptureFormat& format);

  // Binds the framebuffer with `face` (0..5, GL order) of `layer` (0 or 1) as colour (and its
  // depth chain's level 0 as the second colour attachment) and sets the viewport.
  void bindFace(int face, int layer) const;
  // Clears the bound face: colour to `colour` with alpha `alpha`, the depth chain's two channels
  // to `codes`, the depth buffer to the far plane.
  void clearFace(const float colour[3], float alpha, const unsigned codes[2]) const;
  // Binds `face` of the backs texture alone (shaders/capture_output.glsl, pass 3: the farthest
  // back of each object in front), clears it and the depth buffer, and keeps the farthest
  // fragment. endBackPass() writes the backs found into the first layer's depth chain (level 0,
  // the far end of each texel's range) with `merge` (fullscreen.vert + depth_merge.frag, its
  // face uniform at `mergeLayer`) and restores the depth test.
  void bindBackPass(int face) const;
  void endBackPass(int face, GLuint merge, GLint mergeLayer) const;
  // Rebuilds levels 1.. of `layer`'s depth chain for `face` from its level 0 with `reduce`, a
  // program of fullscreen.vert + depth_reduce.frag whose uniforms are at the given locations.
  void reduceDepths(int face, int layer, GLuint reduce, GLint sourceSize, GLint sourceLayer) const;
  // After the faces are drawn: rebuilds the colour mip chain when the format asks for one.
  void finish() const;

  GLuint texture(int layer = 0) const { return colour_[static_cast<size_t>(layer)].id(); }
  GLuint depthChain(int layer = 0) const { return depths_[static_cast<size_t>(layer)].id(); }
  int faceSize() const { return format_.faceSize; }
  // The chain's last level: 1 x 1 texel a face.
  int topLevel() const { return topLevel_; }
  const CaptureFormat& format() const { return format_; }
  void abandon();

 private:
  std::array<TextureHandle, 2> colour_;
  std::array<TextureHandle, 2> depths_;
  TextureHandle backs_;  // R16UI, one level (two layers only)
  RenderbufferHandle depth_;
  FramebufferHandle framebuffer_;
  FramebufferHandle reduceFramebuffer_;
  CaptureFormat format_;
  int topLevel_ = 0;
};

}  // namespace reflect
