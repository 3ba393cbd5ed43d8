// A glass object's own distance map (GPU Gems 3, ch. 17): its mesh seen from its bounds' centre
// into a cube map, in object space, so that a ray refracted into the object can find where it
// leaves (shaders/glass_exit.glsl). Each texel holds the nearest surface's depth along the face's
// axis (a depth texture: nothing else stores 24 bits in both WebGL2 and GL ES 3 without an
// extension) and its outward normal (RGBA8, n * 0.5 + 0.5). The object is rigid, so a map is made
// once per mesh, when a scene first needs it, and never per frame.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gfx/capture_state.h"
#include "gfx/gl_handle.h"
#include "gfx/mesh_buffer.h"
#include "gfx/shader_program.h"
#include "gfx/uniform_table.h"

namespace reflect {

// Past the exact mode's units (exact_tracer.h): the exact mode never binds an interior map.
inline constexpr GLint kGlassDepthUnit = 11;    // samplerCube: an interior map's depths
inline constexpr GLint kGlassNormalsUnit = 12;  // samplerCube: its normals

// The uniforms of the program that draws a map (mesh.vert + glass_interior.frag).
struct GlassInteriorUniforms : UniformTable {
  Uniform<glm::mat4> model{*this, "u_model"};
  Uniform<glm::mat3> normalMatrix{*this, "u_normalMatrix"};
  Uniform<glm::mat4> viewProjection{*this, "u_viewProjection"};
};
using GlassInteriorProgram = TabledProgram<GlassInteriorUniforms>;

class GlassInteriorMap {
 public:
  // Texels per face edge. Measured at 400 x 400 (docs/accuracy.md): the glass cube is exact at
  // any size (each face is a plane square to one of the map's axes, so its depth is one value,
  // and the tangent-plane step puts the exit on it: 16 measured the same as 256), and a glass
  // figure moved by at most 0.03 dB between 64 and 256. 256 (3 MB a mesh) leaves room for
  // curved meshes.
  static constexpr int kFaceSize = 256;

  // Draws `mesh` into a new map with `program` (mesh.vert + glass_interior.frag). Leaves
  // framebuffer 0 bound and the depth test on.
  static Result<GlassInteriorMap> create(const MeshBuffer& mesh,
                                         const GlassInteriorProgram& program);

  GLuint depths() const { return depths_.id(); }
  GLuint normals() const { return normals_.id(); }
  // Where the map looks from, in the mesh's own coordinates.
  const glm::vec3& centre() const { return centre_; }
  float near() const { return near_; }
  float far() const { return far_; }
  // The mesh's farthest vertex from centre(): every exit lies within it.
  float radius() const { return radius_; }

 private:
  GlassInteriorMap() = default;
  TextureHandle depths_;
  TextureHandle normals_;
  glm::vec3 centre_{0.0f};
  float near_ = 0.0f, far_ = 0.0f, radius_ = 0.0f;
};

// The maps a scene needs, by mesh name, each made on first use, and the program that draws them
// (built with the first map: a scene without glass meshes never compiles it).
class GlassInteriorMaps {
 public:
  // `mesh`'s map, made now if it is not yet (nullptr, and the error in lastError(), if that
  // failed; it is not tried again for the same mesh).
  const GlassInteriorMap* mapFor(const std::string& name, const MeshBuffer& mesh);
  // The map made for `name`, without making one.
  const GlassInteriorMap* find(const std::string& name) const {
    auto it = maps_.find(name);
    return it == maps_.end() ? nullptr : it->second.get();
  }
  // The mesh `name` was replaced: its map no longer fits it.
  void forget(const std::string& name) { maps_.erase(name); }
  const std::string& lastError() const { return error_; }
  // Maps made (for tests: a scene makes only those it needs).
  size_t count() const {
    size_t made = 0;
    for (const auto& [name, map] : maps_) made += map ? 1 : 0;
    return made;
  }

 private:
  std::unique_ptr<GlassInteriorProgram> program_;
  std::map<std::string, std::unique_ptr<GlassInteriorMap>> maps_;  // null: making it failed
  std::string error_;
};

// The uniforms of glass_exit.glsl in an environment program built with GLASS_EXIT 1.
// Entries of their program's table (uniform_table.h); -1 in the variants without it.
struct GlassExitUniforms {
  UniformTable& table;
  Uniform<glm::mat4> toMap{table, "u_glassToMap"};
  Uniform<glm::mat4> fromMap{table, "u_glassFromMap"};
  Uniform<glm::mat3> normalFromMap{table, "u_glassNormalFromMap"};
  Uniform<glm::vec3> map{table, "u_glassMap"};
  Uniform<int> depths{table, "u_glassDepths"};
  Uniform<int> normals{table, "u_glassNormals"};

  // The maps' texture units, once, into the program in use (after the table is located).
  void setUnits() const;
  // Binds `interior` for an object placed by `model`, and its textures to their units.
  void set(const GlassInteriorMap& interior, const glm::mat4& model) const;
};

}  // namespace reflect
