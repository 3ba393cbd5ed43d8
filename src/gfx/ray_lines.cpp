#include "gfx/ray_lines.h"

#include <glm/gtc/type_ptr.hpp>

namespace reflect {

Result<RayLines> RayLines::create() {
  return withBuiltProgram<decltype(program_)>("ray_lines.vert", "ray_lines.frag", [](auto program) {
    RayLines lines;
    lines.program_ = std::move(program);
    lines.buffer_ = BufferHandle(genBuffer());
    lines.vertexArray_ = VertexArrayHandle(genVertexArray());
    glBindVertexArray(lines.vertexArray_.id());
    glBindBuffer(GL_ARRAY_BUFFER, lines.buffer_.id());
    // Each vertex: position then colour, three floats each.
    constexpr GLsizei kStride = 6 * sizeof(float);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, kStride,
                          reinterpret_cast<const void*>(3 * sizeof(float)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return lines;
  });
}

void RayLines::set(const std::vector<RaySegment>& segments) {
  std::vector<float> data;
  data.reserve(segments.size() * 12);
  for (const RaySegment& s : segments) {
    for (const glm::vec3& p : {s.from, s.to}) {
      data.insert(data.end(), {p.x, p.y, p.z, s.colour.r, s.colour.g, s.colour.b});
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)),
               data.empty() ? nullptr : data.data(), GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  vertices_ = static_cast<GLsizei>(segments.size() * 2);
}

void RayLines::draw(const glm::mat4& viewProjection, int width, int height) const {
  if (vertices_ == 0) return;
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glUseProgram(program_.id());
  program_.u().viewProjection.set(viewProjection);
  glBindVertexArray(vertexArray_.id());
  glDrawArrays(GL_LINES, 0, vertices_);
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace reflect
