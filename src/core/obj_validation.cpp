#include "core/obj_validation.h"

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

// One face corner: "v", "v/t", "v//n" or "v/t/n". Returns an empty string when valid.
std::string checkCorner(std::string_view corner, const ObjCounts& counts) {
  const size_t available[3] = {counts.positions, counts.texcoords, counts.normals};
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
      if (index == 0 || index > count || index < -count) {
        return std::string(kinds[field]) + " index " + std::to_string(index) +
               " is out of range (" + std::to_string(count) + " defined so far)";
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

// Checks one line (trailing white space removed) and adds what it defines to counts. Returns the
// problem, or an empty string.
std::string checkLine(std::string_view line, const ObjLimits& limits, ObjCounts& counts) {
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
      std::string problem = checkCorner(tokens[i], counts);
      if (!problem.empty()) return problem;
    }
    counts.triangles += tokens.size() - 3;
    if (counts.triangles > limits.maxTriangles) {
      return "more than " + std::to_string(limits.maxTriangles) + " triangles";
    }
  }
  return {};
}

}  // namespace

Result<ObjCounts> validateObjText(const std::string& text, const ObjLimits& limits) {
  if (text.size() > limits.maxBytes) {
    return Result<ObjCounts>::failure("file is " + std::to_string(text.size()) +
                                      " bytes, over the limit of " +
                                      std::to_string(limits.maxBytes));
  }
  ObjCounts counts;
  std::string problem;
  forEachLine(text, [&](size_t lineNumber, std::string_view line) {
    problem = checkLine(line, limits, counts);
    if (problem.empty()) return true;
    problem = lineError(lineNumber, problem);
    return false;
  });
  if (!problem.empty()) return Result<ObjCounts>::failure(problem);
  if (counts.triangles == 0) {
    return Result<ObjCounts>::failure("no faces found: not an OBJ model, or an empty one");
  }
  return counts;
}

}  // namespace reflect
