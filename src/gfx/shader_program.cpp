#include "gfx/shader_program.h"

#include <cstdio>
#include <set>
#include <sstream>
#include <vector>

#include "gfx/shader_library.h"

namespace reflect {
namespace {

// Integers are highp in both: the fragment language's default is mediump int, which may hold only
// 16 signed bits, and depth codes use all 16 unsigned ones.
constexpr const char* kHighp = "#version 300 es\nprecision highp float;\nprecision highp int;\n";
constexpr const char* kMediump =
    "#version 300 es\nprecision mediump float;\nprecision highp int;\n";

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::vector<char> log(static_cast<size_t>(length > 1 ? length : 1), '\0');
  if (isProgram) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  return log.data();
}

Result<ShaderHandle> compile(GLenum stage, const std::string& file, const char* body, bool mediump,
                             const std::string& defines) {
  const char* stageName = stage == GL_VERTEX_SHADER ? "vertex" : "fragment";
  if (!body)
    return Result<ShaderHandle>::failure("shader " + file + ": not embedded in this build");
  ShaderHandle shader(glCreateShader(stage));
  // Vertex shaders stay highp (positions); fragments may trade precision for speed.
  const char* sources[3] = {stage == GL_FRAGMENT_SHADER && mediump ? kMediump : kHighp,
                            defines.c_str(), body};
  glShaderSource(shader.id(), 3, sources, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    return Result<ShaderHandle>::failure(std::string(stageName) + " shader " + file +
                                         " failed to compile:\n" + infoLog(shader.id(), false));
  }
  return shader;
}

// GLSL ES has no #include: a line `#include "name.glsl"` is replaced by that embedded file (once
// per program, so two files may include the same library).
Result<std::string> expandIncludes(const std::string& file, std::set<std::string>& included) {
  const char* text = embeddedShader(file);
  if (!text) return Result<std::string>::failure("shader " + file + ": not embedded in this build");
  std::string out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const size_t open = line.find("#include \"");
    if (open != 0) {
      out += line + "\n";
      continue;
    }
    const size_t start = open + 10;
    const size_t end = line.find('"', start);
    const std::string name = line.substr(start, end == std::string::npos ? end : end - start);
    if (!included.insert(name).second) continue;
    Result<std::string> library = expandIncludes(name, included);
    if (!library) {
      return Result<std::string>::failure("shader " + file + " includes " + library.error());
    }
    out += library.value();
  }
  return out;
}

}  // namespace

Result<ShaderProgram> ShaderProgram::build(const std::string& vertexFile,
                                           const std::string& fragmentFile, bool mediump,
                                           const std::string& defines,
                                           const std::vector<std::string>& feedback) {
  std::set<std::string> vertexIncludes, fragmentIncludes;
  Result<std::string> vertex = expandIncludes(vertexFile, vertexIncludes);
  if (!vertex) return Result<ShaderProgram>::failure(vertex.error());
  Result<std::string> fragment = expandIncludes(fragmentFile, fragmentIncludes);
  if (!fragment) return Result<ShaderProgram>::failure(fragment.error());
  return buildFromSource(vertexFile, vertex.value().c_str(), fragmentFile, fragment.value().c_str(),
                         mediump, defines, feedback);
}

Result<ShaderProgram> ShaderProgram::buildFromSource(const std::string& vertexFile,
                                                     const char* vertexSource,
                                                     const std::string& fragmentFile,
                                                     const char* fragmentSource, bool mediump,
                                                     const std::string& defines,
                                                     const std::vector<std::string>& feedback) {
  Result<ShaderHandle> vs = compile(GL_VERTEX_SHADER, vertexFile, vertexSource, false, defines);
  if (!vs) return Result<ShaderProgram>::failure(vs.error());
  Result<ShaderHandle> fs =
      compile(GL_FRAGMENT_SHADER, fragmentFile, fragmentSource, mediump, defines);
  if (!fs) return Result<ShaderProgram>::failure(fs.error());

  ShaderProgram result;
  result.label_ = vertexFile + " + " + fragmentFile;
  result.program_ = ProgramHandle(glCreateProgram());
  glAttachShader(result.program_.id(), vs.value().id());
  glAttachShader(result.program_.id(), fs.value().id());
  // Outputs transform feedback captures (named before the link), one buffer, interleaved.
  if (!feedback.empty()) {
    std::vector<const char*> names;
    for (const std::string& name : feedback) names.push_back(name.c_str());
    glTransformFeedbackVaryings(result.program_.id(), static_cast<GLsizei>(names.size()),
                                names.data(), GL_INTERLEAVED_ATTRIBS);
  }
  glLinkProgram(result.program_.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(result.program_.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    return Result<ShaderProgram>::failure("program " + result.label_ + " failed to link:\n" +
                                          infoLog(result.program_.id(), true));
  }
  // The shader objects can go now; the linked program keeps what it needs.
  glDetachShader(result.program_.id(), vs.value().id());
  glDetachShader(result.program_.id(), fs.value().id());
  return result;
}

GLint ShaderProgram::uniform(const char* name) const {
  GLint location = glGetUniformLocation(program_.id(), name);
  if (location < 0) std::fprintf(stderr, "program %s has no uniform %s\n", label_.c_str(), name);
  return location;
}

}  // namespace reflect
