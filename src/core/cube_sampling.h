// GL ES 3.0's texture(samplerCube, d) on the CPU, texel for texel, for an RGBA8 cube map with
// LINEAR filtering and no mipmaps (how src/gfx/skybox_pass.cpp sets up the skybox): the truth the
// reference's sky and, later, the raster's environment lookups are checked against.
//
// 1. Face selection (GL ES 3.0 section 3.8.10, "Cube Map Texture Selection"): the major axis is
//    the coordinate of largest magnitude, and
//        face  sc   tc   ma
//        +X   -rz  -ry   rx
//        -X   +rz  -ry   rx
//        +Y   +rx  +rz   ry
//        -Y   +rx  -rz   ry
//        +Z   +rx  -ry   rz
//        -Z   -rx  -ry   rz
//    s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2 (computed as sc * (0.5 / |ma|) + 0.5, the
//    order Mesa's llvmpipe uses). The spec leaves ties open; here, as in llvmpipe and as Direct3D
//    10 requires, Z wins over Y and X, and Y over X. The zero vector (undefined in GL) reads +Z's
//    centre, as in llvmpipe.
// 2. Texel addressing: face images are stored top row first (core/skybox_faces.h) and uploaded as
//    they are, so row j of the image is t in [j / N, (j + 1) / N); nothing is flipped.
// 3. LINEAR: u = s N - 1/2, v = t N - 1/2; the four texels around (u, v) weighted by the
//    fractions, lerp along u first, then along v (each lerp a + w (b - a)); texels are c / 255.
// 4. The edges. GL ES 3.0 filters cube maps seamlessly (its Appendix F.2: "OpenGL ES 3.0 requires
//    that all cube map filtering be seamless"; WebGL 2 inherits it), and the wrap modes are then
//    ignored: a texel past a face's edge is the adjacent face's texel across that edge. At a
//    corner, where a texel would be off two edges, it is the mean of the other three (what the GL
//    spec suggests and llvmpipe does). CubeEdges::ClampToEdge is the per-face alternative
//    (GL ES 2.0, WebGL 1, desktop GL without TEXTURE_CUBE_MAP_SEAMLESS): CLAMP_TO_EDGE within the
//    chosen face.
#pragma once

#include <glm/glm.hpp>

#include "core/skybox_faces.h"

namespace reflect {

// Where a direction lands: face index in GL order (+X, -X, +Y, -Y, +Z, -Z) and s, t in [0, 1].
struct CubeFaceCoord {
  int face = 4;
  float s = 0.5f;
  float t = 0.5f;
};

CubeFaceCoord cubeFaceCoord(const glm::vec3& direction);
// The inverse: the direction (major axis of length 1) that lands on (s, t) of `face`.
glm::vec3 faceDirection(int face, float s, float t);

enum class CubeEdges {
  Seamless,     // GL ES 3.0 and WebGL 2: every cube map
  ClampToEdge,  // per face
};

// The filtered RGBA (0..1) of level 0 of `faces` (six equal squares, 4 bytes a texel) along
// `direction` (any length).
glm::vec4 sampleCubeLinear(const CubeFaces& faces, const glm::vec3& direction,
                           CubeEdges edges = CubeEdges::Seamless);

// The texel (face, column i, row j from the top) that a texel position one step past a face edge
// stands for under seamless filtering: the adjacent face's texel across that edge. i and j may be
// -1 or N (not both); inside the face the texel is itself.
struct CubeTexel {
  int face = 0;
  int i = 0;
  int j = 0;
  bool operator==(const CubeTexel&) const = default;
};
CubeTexel seamlessTexel(int face, int i, int j, int size);

}  // namespace reflect
