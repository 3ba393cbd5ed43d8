// Small helpers the renderer's parts share (probe_capture.cpp, environment_binding.cpp,
// glass_exits.cpp). Internal to src/gfx.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>

#include "gfx/gl.h"
#include "gfx/mesh_buffer.h"

namespace reflect::renderer_detail {

inline void bindTexture(GLint unit, GLenum target, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(target, texture);
}

// The uniform scale of `model`, or 0 when it scales the axes differently (a stretched sphere is
// no sphere).
inline float uniformScale(const glm::mat4& model) {
  const float x = glm::length(glm::vec3(model[0])), y = glm::length(glm::vec3(model[1])),
              z = glm::length(glm::vec3(model[2]));
  const float lo = std::min({x, y, z}), hi = std::max({x, y, z});
  return hi <= lo * 1.001f ? hi : 0.0f;
}

// The world radius of a glass object whose mesh is a sphere, placed by `model` (uniformly
// scaled): its far side has a closed form. 0 for any other mesh (or none yet).
inline float sphereRadiusIn(const MeshBuffer* full, const glm::mat4& model) {
  return full ? full->sphereRadius() * uniformScale(model) : 0.0f;
}

}  // namespace reflect::renderer_detail
