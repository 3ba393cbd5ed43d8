#include "gfx/uniform_table.h"

#include <algorithm>

namespace reflect {

void UniformTable::locate(const ShaderProgram& program) {
  for (UniformSlot* entry : entries_) entry->location_ = program.optionalUniform(entry->name_);
}

std::vector<std::string> UniformTable::unlisted(GLuint program) const {
  GLint count = 0, longest = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::vector<std::string> out;
  std::vector<char> buffer(static_cast<size_t>(std::max(longest, 1)));
  for (GLint i = 0; i < count; ++i) {
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, static_cast<GLuint>(i), static_cast<GLsizei>(buffer.size()),
                       &length, &size, &type, buffer.data());
    // A uniform block's members are set by the buffer bound to it, not by the table.
    const GLuint index = static_cast<GLuint>(i);
    GLint block = -1;
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_BLOCK_INDEX, &block);
    if (block >= 0) continue;
    std::string name(buffer.data(), static_cast<size_t>(length));
    const size_t bracket = name.find('[');  // arrays are listed as "name[0]"
    if (bracket != std::string::npos) name.resize(bracket);
    const auto named = [&name](const UniformSlot* e) { return name == e->name(); };
    if (std::none_of(entries_.begin(), entries_.end(), named)) out.push_back(name);
  }
  return out;
}

}  // namespace reflect
