#include "core/obj_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace reflect {
namespace {

std::vector<std::string_view> splitWhitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

bool parseFiniteFloat(std::string_view token, float* out) {
  std::string copy(token);  // strtof needs a terminated string
  char* end = nullptr;
  float value = std::strtof(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

bool parseIndex(std::string_view token, long* out) {
  if (token.empty()) return false;
  std::string copy(token);
  char* end = nullptr;
  long value = std::strtol(copy.c_str(), &end, 10);
  if (end != copy.c_str() + copy.size()) return false;
  *out = value;
  return true;
}

// What the first pass saw of the normal or texture-coordinate indices faces name, enough to tell
// afterwards whether any of them names one the file does not define.
struct References {
  long maxIndex = 0;           // the largest positive index
  bool reachesBefore = false;  // a negative index reached back before the first definition
};

struct ValidationState {
  ObjCounts counts;
  References texcoords, normals;
};

// One face corner: "v", "v/t", "v//n" or "v/t/n". Returns an empty string when valid.
std::string checkCorner(std::string_view corner, ValidationState& state) {
  ObjCounts& counts = state.counts;
  const size_t available[3] = {counts.positions, counts.texcoords, counts.normals};
  References* references[3] = {nullptr, &state.texcoords, &state.normals};
  const char* kinds[3] = {"vertex", "texture coordinate", "normal"};
  size_t field = 0;
  size_t start = 0;
  while (start <= corner.size() && field < 3) {
    size_t slash = corner.find('/', start);
    std::string_view part = corner.substr(
        start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    // An empty field is only "v//n"'s texture coordinate: a trailing empty one ("1//", "1/2/")
    // makes tinyobjloader read the next corner's number as the index.
    if (!part.empty() || field == 0 || slash == std::string_view::npos) {
      long index = 0;
      if (!parseIndex(part, &index)) return "'" + std::string(corner) + "' is not a face index";
      long count = static_cast<long>(available[field]);
      // A vertex must be defined before the face; a normal or texture coordinate the file does
      // not define is only noted (see validateObjText). Index 0 is never valid, and
      // tinyobjloader refuses the whole file for it.
      if (index == 0 || (field == 0 && (index > count || index < -count))) {
        return std::string(kinds[field]) + " index " + std::to_string(index) +
               " is out of range (" + std::to_string(count) + " defined so far)";
      }
      if (References* seen = references[field]) {
        seen->maxIndex = std::max(seen->maxIndex, index);
        if (index < -count) seen->reachesBefore = true;
      }
    }
    if (slash == std::string_view::npos) return {};
    start = slash + 1;
    ++field;
  }
  return "'" + std::string(corner) + "' has too many '/' fields";
}

// Calls visit(lineNumber, line) for each line, with trailing CR, space and tab removed; stops
// early when visit returns false.
template <typename Visit>
void forEachLine(const std::string& text, Visit visit) {
  size_t lineNumber = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNumber;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.remove_suffix(1);  // CR CR LF endings, as in the course's sphere.obj
    if (!visit(lineNumber, line)) return;
  }
}

}  // namespace

std::string lineError(size_t lineNumber, const std::string& what) {
  return "line " + std::to_string(lineNumber) + ": " + what;
}

size_t lineOfAttribute(const std::string& text, std::string_view keyword, size_t ordinal) {
  size_t found = 0;
  size_t seen = 0;
  forEachLine(text, [&](size_t lineNumber, std::string_view line) {
    std::vector<std::string_view> tokens = splitWhitespace(line);
    if (tokens.empty() || tokens[0] != keyword) return true;
    if (seen++ == ordinal) {
      found = lineNumber;
      return false;
    }
    return true;
  });
  return found;
}

namespace {

// Checks one line (trailing white space removed) and adds what it defines to the counts. Returns
// the problem, or an empty string.
std::string checkLine(std::string_view line, const ObjLimits& limits, ValidationState& state) {
  ObjCounts& counts = state.counts;
  // tinyobjloader also ends a line at a lone CR: what follows it would be a line this pass
  // never checked.
  if (line.find('\r') != std::string_view::npos) {
    return "a carriage return inside a line (old Mac line ends are not supported)";
  }
  std::vector<std::string_view> tokens = splitWhitespace(line);
  if (tokens.empty() || tokens[0][0] == '#') return {};
  const std::string_view keyword = tokens[0];

  if (keyword == "v" || keyword == "vn") {
    if (tokens.size() < 4) return "'" + std::string(keyword) + "' needs three numbers";
    for (size_t i = 1; i <= 3; ++i) {
      float value = 0;
      if (!parseFiniteFloat(tokens[i], &value)) {
        return "'" + std::string(tokens[i]) + "' is not a finite number";
      }
    }
    ++(keyword == "v" ? counts.positions : counts.normals);
  } else if (keyword == "vw") {
    // tinyobjloader's skin-weight extension converts its numbers to int unchecked.
    return "'vw' (skin weights) is not supported";
  } else if (keyword == "vt") {
    ++counts.texcoords;
  } else if (keyword == "f") {
    if (tokens.size() < 4) {
      return "a face needs at least 3 vertices, this one has " + std::to_string(tokens.size() - 1);
    }
    for (size_t i = 1; i < tokens.size(); ++i) {
      std::string problem = checkCorner(tokens[i], state);
      if (!problem.empty()) return problem;
    }
    counts.triangles += tokens.size() - 3;
    if (counts.triangles > limits.maxTriangles) {
      return "more than " + std::to_string(limits.maxTriangles) + " triangles";
    }
  }
  return {};
}

// Field `field` (1: texture coordinate, 2: normal) of a corner that checkCorner accepted; empty
// when the corner has none.
std::string_view cornerField(std::string_view corner, size_t field) {
  for (size_t i = 0; i < field; ++i) {
    const size_t slash = corner.find('/');
    if (slash == std::string_view::npos) return {};
    corner.remove_prefix(slash + 1);
  }
  return corner.substr(0, corner.find('/'));
}

// The first line whose face names, in `field`, an index past the file's `total` definitions or
// (negative) before the first one; 0 if none does.
size_t firstUndefinedReference(const std::string& text, size_t field, size_t total) {
  const std::string_view keyword = field == 2 ? "vn" : "vt";
  long definedSoFar = 0;
  size_t found = 0;
  forEachLine(text, [&](size_t lineNumber, std::string_view line) {
    std::vector<std::string_view> tokens = splitWhitespace(line);
    if (tokens.empty()) return true;
    if (tokens[0] == keyword) ++definedSoFar;
    if (tokens[0] != "f") return true;
    for (size_t i = 1; i < tokens.size(); ++i) {
      long index = 0;
      if (!parseIndex(cornerField(tokens[i], field), &index)) continue;
      if (index > static_cast<long>(total) || index < -definedSoFar) {
        found = lineNumber;
        return false;
      }
    }
    return true;
  });
  return found;
}

}  // namespace

Result<ObjCounts> validateObjText(const std::string& text, const ObjLimits& limits) {
  if (text.size() > limits.maxBytes) {
    return Result<ObjCounts>::failure("file is " + std::to_string(text.size()) +
                                      " bytes, over the limit of " +
                                      std::to_string(limits.maxBytes));
  }
  ValidationState state;
  std::string problem;
  forEachLine(text, [&](size_t lineNumber, std::string_view line) {
    problem = checkLine(line, limits, state);
    if (problem.empty()) return true;
    problem = lineError(lineNumber, problem);
    return false;
  });
  if (!problem.empty()) return Result<ObjCounts>::failure(problem);
  ObjCounts& counts = state.counts;
  if (counts.triangles == 0) {
    return Result<ObjCounts>::failure("no faces found: not an OBJ model, or an empty one");
  }
  // A positive index may name a normal defined further down (tinyobjloader resolves it against
  // the whole file), so whether it is undefined is known only now; a second look, only for the
  // rare file that has one, finds its line.
  if (state.normals.reachesBefore || state.normals.maxIndex > static_cast<long>(counts.normals)) {
    counts.undefinedNormalLine = firstUndefinedReference(text, 2, counts.normals);
  }
  if (state.texcoords.reachesBefore ||
      state.texcoords.maxIndex > static_cast<long>(counts.texcoords)) {
    counts.undefinedTexcoordLine = firstUndefinedReference(text, 1, counts.texcoords);
  }
  return counts;
}

}  // namespace reflect
