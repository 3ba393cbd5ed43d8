#include "gfx/shader_program.h"

#include <cstdio>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>
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

// The text of each stage, as compiled: a prelude (the version, precisions and defines), then the
// file. They stay two source strings, so the driver's line numbers in the file's string are the
// file's own.
struct StageText {
  std::string prelude;
  std::string body;
  bool operator==(const StageText& o) const { return prelude == o.prelude && body == o.body; }
};
struct StageTexts {
  StageText vertex;
  StageText fragment;
  bool operator==(const StageTexts& o) const {
    return vertex == o.vertex && fragment == o.fragment;
  }
};

// Vertex shaders stay highp (positions); fragments may trade precision for speed.
StageTexts stageTexts(const char* vertexSource, const char* fragmentSource, bool mediump,
                      const std::string& defines) {
  return {{kHighp, vertexSource},
          {std::string(mediump ? kMediump : kHighp) + defines, fragmentSource}};
}

ShaderHandle startCompile(GLenum stage, const StageText& text) {
  ShaderHandle shader(glCreateShader(stage));
  const char* sources[2] = {text.prelude.c_str(), text.body.c_str()};
  glShaderSource(shader.id(), 2, sources, nullptr);
  glCompileShader(shader.id());
  return shader;
}

// A program whose stages are compiling and which is linking; nothing has been asked of it yet.
struct StartedProgram {
  StageTexts texts;
  ShaderHandle vertex;
  ShaderHandle fragment;
  ProgramHandle program;
};

StartedProgram startProgram(StageTexts texts) {
  StartedProgram started{std::move(texts), {}, {}, {}};
  started.vertex = startCompile(GL_VERTEX_SHADER, started.texts.vertex);
  started.fragment = startCompile(GL_FRAGMENT_SHADER, started.texts.fragment);
  started.program = ProgramHandle(glCreateProgram());
  glAttachShader(started.program.id(), started.vertex.id());
  glAttachShader(started.program.id(), started.fragment.id());
  glLinkProgram(started.program.id());
  return started;
}

// Programs start() began, waiting for the build() that takes them over. A scene asks for a handful.
std::vector<StartedProgram>& startedPrograms() {
  static std::vector<StartedProgram> started;
  return started;
}

StartedProgram takeOrStart(StageTexts texts) {
  std::vector<StartedProgram>& started = startedPrograms();
  for (auto it = started.begin(); it != started.end(); ++it) {
    if (it->texts == texts) {
      StartedProgram taken = std::move(*it);
      started.erase(it);
      return taken;
    }
  }
  return startProgram(std::move(texts));
}

std::string compileError(GLuint shader, GLenum stage, const std::string& file) {
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return {};
  const char* stageName = stage == GL_VERTEX_SHADER ? "vertex" : "fragment";
  return std::string(stageName) + " shader " + file + " failed to compile:\n" +
         infoLog(shader, false);
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
                                           const std::string& defines) {
  std::set<std::string> vertexIncludes, fragmentIncludes;
  Result<std::string> vertex = expandIncludes(vertexFile, vertexIncludes);
  if (!vertex) return Result<ShaderProgram>::failure(vertex.error());
  Result<std::string> fragment = expandIncludes(fragmentFile, fragmentIncludes);
  if (!fragment) return Result<ShaderProgram>::failure(fragment.error());
  return buildFromSource(vertexFile, vertex.value().c_str(), fragmentFile, fragment.value().c_str(),
                         mediump, defines);
}

Result<ShaderProgram> ShaderProgram::buildFromSource(const std::string& vertexFile,
                                                     const char* vertexSource,
                                                     const std::string& fragmentFile,
                                                     const char* fragmentSource, bool mediump,
                                                     const std::string& defines) {
  for (const auto& [file, source] :
       {std::pair{&vertexFile, vertexSource}, std::pair{&fragmentFile, fragmentSource}}) {
    if (!source) {
      return Result<ShaderProgram>::failure("shader " + *file + ": not embedded in this build");
    }
  }
  StartedProgram started = takeOrStart(stageTexts(vertexSource, fragmentSource, mediump, defines));
  for (const auto& [shader, stage, file] :
       {std::tuple{started.vertex.id(), GL_VERTEX_SHADER, &vertexFile},
        std::tuple{started.fragment.id(), GL_FRAGMENT_SHADER, &fragmentFile}}) {
    std::string error = compileError(shader, stage, *file);
    if (!error.empty()) return Result<ShaderProgram>::failure(error);
  }

  ShaderProgram result;
  result.label_ = vertexFile + " + " + fragmentFile;
  result.program_ = std::move(started.program);
  GLint ok = GL_FALSE;
  glGetProgramiv(result.program_.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    return Result<ShaderProgram>::failure("program " + result.label_ + " failed to link:\n" +
                                          infoLog(result.program_.id(), true));
  }
  // The shader objects can go now; the linked program keeps what it needs.
  glDetachShader(result.program_.id(), started.vertex.id());
  glDetachShader(result.program_.id(), started.fragment.id());
  return result;
}

void ShaderProgram::start(const ProgramSource& source) {
  std::set<std::string> vertexIncludes, fragmentIncludes;
  Result<std::string> vertex = expandIncludes(source.vertexFile, vertexIncludes);
  Result<std::string> fragment = expandIncludes(source.fragmentFile, fragmentIncludes);
  if (!vertex || !fragment) return;  // build() reports it
  StageTexts texts =
      stageTexts(vertex.value().c_str(), fragment.value().c_str(), source.mediump, source.defines);
  for (const StartedProgram& s : startedPrograms()) {
    if (s.texts == texts) return;
  }
  startedPrograms().push_back(startProgram(std::move(texts)));
}

void ShaderProgram::dropStarted(bool contextLost) {
  if (contextLost) {
    for (StartedProgram& s : startedPrograms()) {
      s.vertex.abandon();
      s.fragment.abandon();
      s.program.abandon();
    }
  }
  startedPrograms().clear();
}

size_t ShaderProgram::startedCount() {
  return startedPrograms().size();
}

GLint ShaderProgram::uniform(const char* name) const {
  GLint location = glGetUniformLocation(program_.id(), name);
  if (location < 0) std::fprintf(stderr, "program %s has no uniform %s\n", label_.c_str(), name);
  return location;
}

}  // namespace reflect
