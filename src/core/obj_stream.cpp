#include "core/obj_stream.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/block_array.h"

namespace reflect {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
// A position's vertices (one per distinct normal) are found by walking a chain; past this many
// the rest go to a hash map, so a file that gives one position thousands of normals stays linear.
constexpr int kChainLimit = 32;

std::string lineError(size_t lineNumber, const std::string& what) {
  return "line " + std::to_string(lineNumber) + ": " + what;
}

bool isBlank(char c) {
  return c == ' ' || c == '\t';
}

// The white-space separated tokens of a line, one at a time.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : line_(line) {}
  // The next token, or an empty view at the end.
  std::string_view next() {
    while (pos_ < line_.size() && isBlank(line_[pos_])) ++pos_;
    const size_t start = pos_;
    while (pos_ < line_.size() && !isBlank(line_[pos_])) ++pos_;
    return line_.substr(start, pos_ - start);
  }

 private:
  std::string_view line_;
  size_t pos_ = 0;
};

// strtof on a token (which is not terminated): the whole token must be the number.
bool strtofWhole(std::string_view token, float* out) {
  char buffer[64];
  std::string copy;
  const char* text = buffer;
  if (token.size() < sizeof buffer) {
    std::copy(token.begin(), token.end(), buffer);
    buffer[token.size()] = '\0';
  } else {
    copy.assign(token);
    text = copy.c_str();
  }
  char* end = nullptr;
  const float value = std::strtof(text, &end);
  if (end != text + token.size()) return false;
  *out = value;
  return true;
}

// A finite number, exactly as strtof reads it. Plain decimals of up to 7 significant digits and
// small exponents (almost every number in an OBJ file) are read directly: the digits and the
// power of ten are both exact floats there, so one division or multiplication is correctly
// rounded, as strtof is. Everything else goes to strtof.
bool parseFiniteFloat(std::string_view token, float* out) {
  static constexpr float kPowers[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                      1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
  size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '-' || token[i] == '+')) negative = token[i++] == '-';
  uint32_t mantissa = 0;
  int digits = 0;  // significant digits (leading zeros do not count)
  int scale = 0;   // digits after the point
  bool any = false;
  bool fast = true;
  for (; i < token.size() && token[i] >= '0' && token[i] <= '9'; ++i) {
    any = true;
    if (mantissa != 0 || token[i] != '0') ++digits;
    if (digits > 7) {
      fast = false;
      break;
    }
    mantissa = mantissa * 10 + static_cast<uint32_t>(token[i] - '0');
  }
  if (fast && i < token.size() && token[i] == '.') {
    for (++i; i < token.size() && token[i] >= '0' && token[i] <= '9'; ++i) {
      any = true;
      if (mantissa != 0 || token[i] != '0') ++digits;
      if (digits > 7) {
        fast = false;
        break;
      }
      mantissa = mantissa * 10 + static_cast<uint32_t>(token[i] - '0');
      ++scale;
    }
  }
  int exponent = 0;
  if (fast && any && i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    size_t j = i + 1;
    bool negativeExponent = false;
    if (j < token.size() && (token[j] == '-' || token[j] == '+'))
      negativeExponent = token[j++] == '-';
    const size_t first = j;
    for (; j < token.size() && token[j] >= '0' && token[j] <= '9' && j - first < 3; ++j) {
      exponent = exponent * 10 + (token[j] - '0');
    }
    if (j == first || j != token.size()) {
      fast = false;
    } else {
      i = j;
      if (negativeExponent) exponent = -exponent;
    }
  }
  if (fast && any && i == token.size()) {
    const int power = exponent - scale;
    if (power >= -10 && power <= 10) {
      float value = static_cast<float>(mantissa);  // exact: under 2^24
      value = power < 0 ? value / kPowers[-power] : value * kPowers[power];
      *out = negative ? -value : value;
      return true;
    }
  }
  float value = 0.0f;
  if (!strtofWhole(token, &value) || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

// strtol on a whole token (an optional sign, then digits), saturating as strtol does.
bool parseIndex(std::string_view token, long* out) {
  size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '-' || token[i] == '+')) negative = token[i++] == '-';
  if (i == token.size()) return false;
  unsigned long magnitude = 0;
  bool saturated = false;
  for (; i < token.size(); ++i) {
    if (token[i] < '0' || token[i] > '9') return false;
    const unsigned long digit = static_cast<unsigned long>(token[i] - '0');
    if (magnitude > (static_cast<unsigned long>(LONG_MAX) + 1 - digit) / 10) saturated = true;
    if (!saturated) magnitude = magnitude * 10 + digit;
  }
  if (negative) {
    *out = saturated || magnitude > static_cast<unsigned long>(LONG_MAX) + 1
               ? LONG_MIN
               : static_cast<long>(0 - magnitude);
  } else {
    *out = saturated || magnitude > static_cast<unsigned long>(LONG_MAX)
               ? LONG_MAX
               : static_cast<long>(magnitude);
  }
  return true;
}

// Which face lines name a normal (texture coordinate) that the file never defines: a negative
// index that reaches back before the first definition is known at once; a positive one past the
// definitions so far is undefined only if the file never gets that far, known at the end.
struct UndefinedReferences {
  size_t firstBefore = 0;  // the first line with a negative index before the first definition
  // Lines with a positive index past what was defined then, each with its largest index; kept
  // only while that index rises, since a later line with a smaller index cannot be the first
  // undefined one. Entries that definitions have since covered are dropped from the front.
  std::vector<std::pair<size_t, long>> pending;
  size_t pendingStart = 0;

  void noteLine(size_t line, long largest, bool before, size_t defined) {
    if (before && firstBefore == 0) firstBefore = line;
    if (largest <= static_cast<long>(defined)) return;
    if (pendingStart < pending.size() && largest <= pending.back().second) return;
    pending.emplace_back(line, largest);
  }
  void defined(size_t count) {
    while (pendingStart < pending.size() &&
           pending[pendingStart].second <= static_cast<long>(count)) {
      ++pendingStart;
    }
    if (pendingStart == pending.size()) {
      pending.clear();
      pendingStart = 0;
    }
  }
  // The first line naming one past `total`, or before the first; 0 if none.
  size_t firstLine(size_t total) const {
    size_t after = 0;
    for (size_t i = pendingStart; i < pending.size(); ++i) {
      if (pending[i].second > static_cast<long>(total)) {
        after = pending[i].first;
        break;
      }
    }
    if (firstBefore == 0) return after;
    if (after == 0) return firstBefore;
    return std::min(firstBefore, after);
  }
};

// One face corner, resolved as tinyobjloader resolves it: 0-based position; normal 0-based, or
// -1 for none (absent, or a negative index before the first normal). A positive normal index may
// be past the normals read so far: the file may define it further down.
struct Corner {
  uint32_t position = 0;
  int32_t normal = -1;
};

// A vertex while the file is read: its position and normal (Corner's numbers) and the next vertex
// of the same position (the chain vertexOf walks). 12 bytes where the Vertex it becomes is 24:
// finish() makes the vertices, once, in the mesh's own array.
struct VertexKey {
  uint32_t position = 0;
  int32_t normal = -1;
  uint32_t nextSamePosition = 0;
};

// pnpoly (W. Randolph Franklin), as tinyobjloader's ear clipping uses it.
bool insideTriangle(const float* x, const float* y, float tx, float ty) {
  bool inside = false;
  for (int i = 0, j = 2; i < 3; j = i++) {
    if (((y[i] > ty) != (y[j] > ty)) && (tx < (x[j] - x[i]) * (ty - y[i]) / (y[j] - y[i]) + x[i])) {
      inside = !inside;
    }
  }
  return inside;
}

// Empties a container and frees its storage (`c = {}` would keep a vector's or a map's).
template <class Container>
void freeStorage(Container& c) {
  c = Container();
}

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return (length > 1e-20f && std::isfinite(length)) ? v / length : fallback;
}

}  // namespace

struct ObjStreamParser::State {
  std::string name;
  ObjLimits limits;
  std::string partial;  // a line begun in an earlier piece
  size_t bytes = 0;
  size_t lines = 0;
  std::string failure;  // "line N: ..." or another message, without the name

  size_t texcoords = 0;
  size_t triangleBudget = 0;  // triangles counted as the faces' fans, for the limit
  UndefinedReferences undefinedNormals, undefinedTexcoords;
  bool forwardNormals = false;  // some vertex names a normal past those read at the time

  BlockArray<glm::vec3> positions;
  BlockArray<glm::vec3> normals;
  BlockArray<VertexKey> vertices;        // what each vertex is made of (finish() makes it)
  BlockArray<uint32_t> firstOfPosition;  // per position: its chain's first vertex
  std::unordered_map<uint64_t, uint32_t> overflow;  // (position, normal) past a chain's limit
  BlockArray<uint32_t> indices;
  std::vector<std::string_view> cornerTokens;  // the face being read, as text
  std::vector<Corner> face;                    // and its corners
  std::vector<Corner> remaining;               // the ear clipper's polygon

  bool failed() const { return !failure.empty(); }

  uint32_t vertexOf(const Corner& c) {
    uint32_t id = firstOfPosition[c.position];
    int steps = 0;
    for (; id != kNone; id = vertices[id].nextSamePosition, ++steps) {
      if (vertices[id].normal == c.normal) return id;
    }
    const uint64_t key =
        (static_cast<uint64_t>(c.position) << 32) | static_cast<uint32_t>(c.normal);
    if (steps >= kChainLimit) {
      auto it = overflow.find(key);
      if (it != overflow.end()) return it->second;
    }
    const uint32_t created = static_cast<uint32_t>(vertices.size());
    if (steps < kChainLimit) {
      vertices.push_back(VertexKey{c.position, c.normal, firstOfPosition[c.position]});
      firstOfPosition[c.position] = created;
    } else {
      vertices.push_back(VertexKey{c.position, c.normal, kNone});
      overflow.emplace(key, created);
    }
    return created;
  }

  void emit(const Corner& a, const Corner& b, const Corner& c) {
    for (const Corner* corner : {&a, &b, &c}) indices.push_back(vertexOf(*corner));
  }

  // A quad along its shorter diagonal; larger polygons by tinyobjloader's ear clipping (which may
  // give up on a polygon it cannot clip and emit fewer triangles).
  void triangulate() {
    const size_t n = face.size();
    if (n == 3) {
      emit(face[0], face[1], face[2]);
      return;
    }
    if (n == 4) {
      const glm::vec3 v0 = positions[face[0].position], v1 = positions[face[1].position];
      const glm::vec3 v2 = positions[face[2].position], v3 = positions[face[3].position];
      const float e02x = v2.x - v0.x, e02y = v2.y - v0.y, e02z = v2.z - v0.z;
      const float e13x = v3.x - v1.x, e13y = v3.y - v1.y, e13z = v3.z - v1.z;
      const float sqr02 = e02x * e02x + e02y * e02y + e02z * e02z;
      const float sqr13 = e13x * e13x + e13y * e13y + e13z * e13z;
      if (sqr02 < sqr13) {
        emit(face[0], face[1], face[2]);
        emit(face[0], face[2], face[3]);
      } else {
        emit(face[0], face[1], face[3]);
        emit(face[1], face[2], face[3]);
      }
      return;
    }
    clipEars();
  }

  void clipEars() {
    const size_t n = face.size();
    // The two axes to work in: the plane of the first corner that is not straight.
    size_t axes[2] = {1, 2};
    for (size_t k = 0; k < n; ++k) {
      const glm::vec3 v0 = positions[face[k % n].position];
      const glm::vec3 v1 = positions[face[(k + 1) % n].position];
      const glm::vec3 v2 = positions[face[(k + 2) % n].position];
      const float e0x = v1.x - v0.x, e0y = v1.y - v0.y, e0z = v1.z - v0.z;
      const float e1x = v2.x - v1.x, e1y = v2.y - v1.y, e1z = v2.z - v1.z;
      const float cx = std::fabs(e0y * e1z - e0z * e1y);
      const float cy = std::fabs(e0z * e1x - e0x * e1z);
      const float cz = std::fabs(e0x * e1y - e0y * e1x);
      const float epsilon = std::numeric_limits<float>::epsilon();
      if (cx > epsilon || cy > epsilon || cz > epsilon) {
        if (!(cx > cy && cx > cz)) {
          axes[0] = 0;
          if (cz > cx && cz > cy) axes[1] = 1;
        }
        break;
      }
    }
    remaining = face;
    size_t guess = 0;
    size_t iterationsLeft = n;
    size_t previousCount = n;
    Corner ind[3];
    float vx[3], vy[3];
    while (remaining.size() > 3 && iterationsLeft > 0) {
      const size_t count = remaining.size();
      if (guess >= count) guess -= count;
      if (previousCount != count) {
        previousCount = count;
        iterationsLeft = count;
      } else {
        --iterationsLeft;
      }
      for (size_t k = 0; k < 3; ++k) {
        ind[k] = remaining[(guess + k) % count];
        const glm::vec3 p = positions[ind[k].position];
        vx[k] = p[static_cast<int>(axes[0])];
        vy[k] = p[static_cast<int>(axes[1])];
      }
      const float e0x = vx[1] - vx[0], e0y = vy[1] - vy[0];
      const float e1x = vx[2] - vx[1], e1y = vy[2] - vy[1];
      const float cross = e0x * e1y - e0y * e1x;
      const float area = (vx[0] * vy[1] - vy[0] * vx[1]) * 0.5f;
      if (cross * area < 0.0f) {  // an inner angle
        ++guess;
        continue;
      }
      bool overlap = false;
      for (size_t other = 3; other < count; ++other) {
        const glm::vec3 p = positions[remaining[(guess + other) % count].position];
        if (insideTriangle(vx, vy, p[static_cast<int>(axes[0])], p[static_cast<int>(axes[1])])) {
          overlap = true;
          break;
        }
      }
      if (overlap) {
        ++guess;
        continue;
      }
      emit(ind[0], ind[1], ind[2]);
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>((guess + 1) % count));
    }
    if (remaining.size() == 3) emit(remaining[0], remaining[1], remaining[2]);
  }

  // One face corner: "v", "v/t", "v//n" or "v/t/n". Returns the problem, or "" (and the corner).
  std::string readCorner(std::string_view corner, Corner* out, long largest[2], bool before[2]) {
    const size_t available[3] = {positions.size(), texcoords, normals.size()};
    static const char* const kKinds[3] = {"vertex", "texture coordinate", "normal"};
    size_t field = 0;
    size_t start = 0;
    while (start <= corner.size() && field < 3) {
      const size_t slash = corner.find('/', start);
      const std::string_view part = corner.substr(
          start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
      // An empty field is only "v//n"'s texture coordinate: a trailing empty one ("1//", "1/2/")
      // would make tinyobjloader read the next corner's number as the index.
      if (!part.empty() || field == 0 || slash == std::string_view::npos) {
        long index = 0;
        if (!parseIndex(part, &index)) return "'" + std::string(corner) + "' is not a face index";
        const long count = static_cast<long>(available[field]);
        // A vertex must be defined before the face; a normal or texture coordinate the file does
        // not define is only noted. Index 0 is never valid.
        if (index == 0 || (field == 0 && (index > count || index < -count))) {
          return std::string(kKinds[field]) + " index " + std::to_string(index) +
                 " is out of range (" + std::to_string(count) + " defined so far)";
        }
        if (field == 0) {
          out->position = static_cast<uint32_t>(index > 0 ? index - 1 : count + index);
        } else {
          const size_t k = field - 1;  // 0: texture coordinate, 1: normal
          largest[k] = std::max(largest[k], index);
          if (index < -count) before[k] = true;
          if (field == 2) {
            if (index < 0) {
              out->normal = index < -count ? -1 : static_cast<int32_t>(count + index);
            } else {
              // Past INT32_MAX no file can define it: it stays undefined.
              out->normal = static_cast<int32_t>(std::min<long>(index - 1, INT32_MAX));
              if (index > count) forwardNormals = true;
            }
          }
        }
      }
      if (slash == std::string_view::npos) return {};
      start = slash + 1;
      ++field;
    }
    return "'" + std::string(corner) + "' has too many '/' fields";
  }

  // One line, trailing white space and CRs removed. Returns the problem, or "".
  std::string parseLine(std::string_view line) {
    // A lone CR ends a line for some readers: what follows it would be a line never checked.
    if (line.find('\r') != std::string_view::npos) {
      return "a carriage return inside a line (old Mac line ends are not supported)";
    }
    Tokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword.empty() || keyword[0] == '#') return {};
    if (keyword == "v" || keyword == "vn") {
      float xyz[3];
      for (float& value : xyz) {
        const std::string_view token = tokens.next();
        if (token.empty()) return "'" + std::string(keyword) + "' needs three numbers";
        if (!parseFiniteFloat(token, &value)) {
          return "'" + std::string(token) + "' is not a finite number";
        }
      }
      if (keyword == "v") {
        positions.push_back(glm::vec3(xyz[0], xyz[1], xyz[2]));
        firstOfPosition.push_back(kNone);
      } else {
        normals.push_back(glm::vec3(xyz[0], xyz[1], xyz[2]));
        undefinedNormals.defined(normals.size());
      }
    } else if (keyword == "vw") {
      return "'vw' (skin weights) is not supported";
    } else if (keyword == "vt") {
      ++texcoords;
      undefinedTexcoords.defined(texcoords);
    } else if (keyword == "f") {
      cornerTokens.clear();
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        cornerTokens.push_back(token);
      }
      if (cornerTokens.size() < 3) {
        return "a face needs at least 3 vertices, this one has " +
               std::to_string(cornerTokens.size());
      }
      face.clear();
      long largest[2] = {0, 0};
      bool before[2] = {false, false};
      for (std::string_view token : cornerTokens) {
        Corner corner;
        std::string problem = readCorner(token, &corner, largest, before);
        if (!problem.empty()) return problem;
        face.push_back(corner);
      }
      triangleBudget += face.size() - 2;
      if (triangleBudget > limits.maxTriangles) {
        return "more than " + std::to_string(limits.maxTriangles) + " triangles";
      }
      undefinedTexcoords.noteLine(lines, largest[0], before[0], texcoords);
      undefinedNormals.noteLine(lines, largest[1], before[1], normals.size());
      triangulate();
    }
    return {};
  }

  void parse(std::string_view text) {
    ++lines;
    while (!text.empty() && (text.back() == '\r' || isBlank(text.back()))) text.remove_suffix(1);
    std::string problem = parseLine(text);
    if (!problem.empty()) failure = lineError(lines, problem);
  }

  void feed(std::string_view piece) {
    if (failed()) return;
    size_t pos = 0;
    if (!partial.empty()) {
      const size_t end = piece.find('\n');
      if (end == std::string_view::npos) {
        partial.append(piece);
        return;
      }
      partial.append(piece.substr(0, end));
      parse(partial);
      partial.clear();
      partial.shrink_to_fit();
      pos = end + 1;
    }
    while (!failed()) {
      const size_t end = piece.find('\n', pos);
      if (end == std::string_view::npos) {
        partial.assign(piece.substr(pos));
        return;
      }
      parse(piece.substr(pos, end - pos));
      pos = end + 1;
    }
  }

  size_t heldBytes() const {
    return partial.capacity() + positions.capacityBytes() + normals.capacityBytes() +
           vertices.capacityBytes() + firstOfPosition.capacityBytes() + indices.capacityBytes() +
           overflow.size() * (sizeof(uint64_t) + sizeof(uint32_t)) +
           (face.capacity() + remaining.capacity()) * sizeof(Corner) +
           cornerTokens.capacity() * sizeof(std::string_view);
  }

  // Whether a vertex names a normal past the file's last (a forward reference never defined).
  bool anyNormalPastTheEnd() const {
    if (!forwardNormals) return false;
    const int32_t total = static_cast<int32_t>(normals.size());
    for (size_t v = 0; v < vertices.size(); ++v) {
      if (vertices[v].normal >= total) return true;
    }
    return false;
  }

  // Where a positive normal index turned out past the file's last normal, those vertices name no
  // normal: several of them at one position are one vertex, as they would have been had the
  // file's normal count been known when they were read. Renumbers the vertices (still in the
  // order of first use) and rewrites the triangles. The chains are not kept up to date: finish()
  // needs them no more.
  void mergeUndefinedNormals() {
    const int32_t total = static_cast<int32_t>(normals.size());
    std::unordered_map<uint64_t, uint32_t> vertexOfKey;
    std::vector<uint32_t> renumbered(vertices.size());
    uint32_t next = 0;
    for (size_t v = 0; v < vertices.size(); ++v) {
      VertexKey vertex = vertices[v];
      if (vertex.normal >= total) vertex.normal = -1;
      const uint64_t key =
          (static_cast<uint64_t>(vertex.position) << 32) | static_cast<uint32_t>(vertex.normal);
      auto [it, inserted] = vertexOfKey.try_emplace(key, next);
      // The new number is never above the old: moving down is safe in place.
      if (inserted) vertices[next++] = vertex;
      renumbered[v] = it->second;
    }
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = renumbered[indices[i]];
    vertices.truncate(next);
  }

  // The mesh's vertices, made from the positions, the file's normals (normalized) and, for
  // vertices without a usable one, the area-weighted normal of their position's triangles. Frees
  // everything the parse held but the triangles: this array is the one allocation made while the
  // parse's arrays are all held, so it sets the peak. The index array, made after, fits in the
  // space the positions and normals leave when the file lists them before its faces (they lie
  // side by side then: core/block_array.h).
  std::vector<Vertex> makeVertices() {
    std::vector<Vertex> out;
    out.reserve(vertices.size());
    const int32_t total = static_cast<int32_t>(normals.size());
    bool needComputed = false;
    for (size_t v = 0; v < vertices.size(); ++v) {
      const VertexKey& key = vertices[v];
      glm::vec3 normal(0.0f);
      if (key.normal >= 0 && key.normal < total) {
        normal = normalizedOr(normals[static_cast<size_t>(key.normal)], glm::vec3(0.0f));
      }
      needComputed |= normal == glm::vec3(0.0f);
      out.push_back(Vertex{positions[key.position], normal});
    }
    normals.clear();
    if (needComputed) {
      // Per position: the sum of its triangles' area-weighted normals. The positions are in `out`
      // now, so their storage holds the sums.
      BlockArray<glm::vec3> sums;
      std::swap(sums, positions);
      for (size_t p = 0; p < sums.size(); ++p) sums[p] = glm::vec3(0.0f);
      for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3& a = out[indices[t]].position;
        const glm::vec3& b = out[indices[t + 1]].position;
        const glm::vec3& c = out[indices[t + 2]].position;
        const glm::vec3 areaNormal = glm::cross(b - a, c - a);  // length = 2 x area
        for (size_t k = 0; k < 3; ++k) sums[vertices[indices[t + k]].position] += areaNormal;
      }
      for (size_t v = 0; v < vertices.size(); ++v) {
        if (out[v].normal == glm::vec3(0.0f)) {
          out[v].normal = normalizedOr(sums[vertices[v].position], {0.0f, 1.0f, 0.0f});
        }
      }
    }
    positions.clear();
    vertices.clear();
    return out;
  }

  Result<LoadedMesh> finish() {
    using Out = Result<LoadedMesh>;
    if (!failed() && !partial.empty()) {
      std::string last = std::move(partial);
      partial.clear();
      parse(last);
    }
    if (failed()) return Out::failure(name + ": " + failure);
    if (triangleBudget == 0) {
      return Out::failure(name + ": no faces found: not an OBJ model, or an empty one");
    }
    if (indices.empty()) return Out::failure(name + ": no triangles after parsing");

    LoadedMesh loaded;
    const size_t normalLine = undefinedNormals.firstLine(normals.size());
    const size_t texcoordLine = undefinedTexcoords.firstLine(texcoords);
    if (normalLine != 0) {
      loaded.warnings.push_back(name +
                                ": faces name normals the file does not define (first on line " +
                                std::to_string(normalLine) + "); using computed normals");
    }
    if (texcoordLine != 0) {
      loaded.warnings.push_back(
          name + ": faces name texture coordinates the file does not define (first on line " +
          std::to_string(texcoordLine) + "); ignored, as texture coordinates are not used");
    }

    // The chains found vertices while the faces were read, and the face buffers held them: not
    // needed any more.
    firstOfPosition.clear();
    freeStorage(overflow);
    freeStorage(cornerTokens);
    freeStorage(face);
    freeStorage(remaining);
    if (anyNormalPastTheEnd()) mergeUndefinedNormals();

    MeshData& mesh = loaded.mesh;
    mesh.name = name;
    mesh.vertices = makeVertices();
    mesh.indices = indices.release();
    mesh.bounds = computeBounds(mesh.vertices);
    return loaded;
  }
};

ObjStreamParser::ObjStreamParser(std::string name, const ObjLimits& limits)
    : state_(std::make_unique<State>()) {
  state_->name = std::move(name);
  state_->limits = limits;
}

ObjStreamParser::~ObjStreamParser() = default;
ObjStreamParser::ObjStreamParser(ObjStreamParser&&) noexcept = default;
ObjStreamParser& ObjStreamParser::operator=(ObjStreamParser&&) noexcept = default;

bool ObjStreamParser::feed(std::string_view bytes) {
  State& s = *state_;
  s.bytes += bytes.size();
  if (s.failed()) return false;
  if (s.bytes > s.limits.maxBytes) {
    s.failure = "file is at least " + std::to_string(s.bytes) + " bytes, over the limit of " +
                std::to_string(s.limits.maxBytes);
    s.partial.clear();
    return false;
  }
  s.feed(bytes);
  return !s.failed();
}

Result<LoadedMesh> ObjStreamParser::finish() {
  Result<LoadedMesh> result = state_->finish();
  State fresh;
  fresh.name = state_->name;
  fresh.limits = state_->limits;
  *state_ = std::move(fresh);
  return result;
}

bool ObjStreamParser::failed() const {
  return state_->failed();
}

std::string ObjStreamParser::error() const {
  return state_->failed() ? state_->name + ": " + state_->failure : std::string();
}

size_t ObjStreamParser::bytesFed() const {
  return state_->bytes;
}

size_t ObjStreamParser::linesParsed() const {
  return state_->lines;
}

size_t ObjStreamParser::partialLineBytes() const {
  return state_->partial.size();
}

size_t ObjStreamParser::heldBytes() const {
  return state_->heldBytes();
}

}  // namespace reflect
