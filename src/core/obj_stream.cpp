// The driver of the streaming OBJ parser: cuts the pieces into lines, reads each line's keyword
// and hands its parts to the files with one job each (core/obj_tokens.h: tokens and numbers;
// core/obj_corners.h: face corners and undefined references; core/obj_faces.h: triangulation;
// core/obj_vertices.h: vertices and normals), then checks the limits and makes the mesh.
#include "core/obj_stream.h"

#include <utility>
#include <vector>

#include "core/block_array.h"
#include "core/obj_corners.h"
#include "core/obj_faces.h"
#include "core/obj_tokens.h"
#include "core/obj_vertices.h"

namespace reflect {
namespace {

std::string lineError(size_t lineNumber, const std::string& what) {
  return "line " + std::to_string(lineNumber) + ": " + what;
}

// Empties a container and frees its storage (`c = {}` would keep a vector's capacity).
template <class Container>
void freeStorage(Container& c) {
  c = Container();
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
  ObjVertices vertices;  // what each vertex is made of (finish() makes them)
  BlockArray<uint32_t> indices;
  std::vector<std::string_view> cornerTokens;  // the face being read, as text
  std::vector<ObjCorner> face;                 // and its corners
  ObjFaceTriangulator triangulator;

  bool failed() const { return !failure.empty(); }

  // "v" or "vn" and its three numbers.
  std::string parseVector(std::string_view keyword, ObjTokens& tokens) {
    float xyz[3];
    for (float& value : xyz) {
      const std::string_view token = tokens.next();
      if (token.empty()) return "'" + std::string(keyword) + "' needs three numbers";
      if (!parseObjFloat(token, &value))
        return "'" + std::string(token) + "' is not a finite number";
    }
    if (keyword == "v") {
      positions.push_back(glm::vec3(xyz[0], xyz[1], xyz[2]));
      vertices.addPosition();
    } else {
      normals.push_back(glm::vec3(xyz[0], xyz[1], xyz[2]));
      undefinedNormals.defined(normals.size());
    }
    return {};
  }

  // An "f" line's corners, then its triangles.
  std::string parseFace(ObjTokens& tokens) {
    cornerTokens.clear();
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
      cornerTokens.push_back(token);
    }
    if (cornerTokens.size() < 3) {
      return "a face needs at least 3 vertices, this one has " +
             std::to_string(cornerTokens.size());
    }
    face.clear();
    CornerReferences refs;
    const ObjCounts defined{positions.size(), texcoords, normals.size()};
    for (std::string_view token : cornerTokens) {
      ObjCorner corner;
      std::string problem = readObjCorner(token, defined, &corner, &refs);
      if (!problem.empty()) return problem;
      face.push_back(corner);
    }
    forwardNormals |= refs.forwardNormal;
    triangleBudget += face.size() - 2;
    if (triangleBudget > limits.maxTriangles) {
      return "more than " + std::to_string(limits.maxTriangles) + " triangles";
    }
    undefinedTexcoords.noteLine(lines, refs.largest[0], refs.before[0], texcoords);
    undefinedNormals.noteLine(lines, refs.largest[1], refs.before[1], normals.size());
    triangulator.triangulate(face, positions, vertices, indices);
    return {};
  }

  // One line, trailing white space and CRs removed. Returns the problem, or "".
  std::string parseLine(std::string_view line) {
    // A lone CR ends a line for some readers: what follows it would be a line never checked.
    if (line.find('\r') != std::string_view::npos) {
      return "a carriage return inside a line (old Mac line ends are not supported)";
    }
    ObjTokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword.empty() || keyword[0] == '#') return {};
    if (keyword == "v" || keyword == "vn") return parseVector(keyword, tokens);
    if (keyword == "vw") return "'vw' (skin weights) is not supported";
    if (keyword == "vt") {
      ++texcoords;
      undefinedTexcoords.defined(texcoords);
    } else if (keyword == "f") {
      return parseFace(tokens);
    }
    return {};
  }

  void parse(std::string_view text) {
    ++lines;
    while (!text.empty() && (text.back() == '\r' || isObjBlank(text.back()))) {
      text.remove_suffix(1);
    }
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
           vertices.heldBytes() + indices.capacityBytes() + face.capacity() * sizeof(ObjCorner) +
           triangulator.heldBytes() + cornerTokens.capacity() * sizeof(std::string_view);
  }

  // The warnings about references the file never defines.
  std::vector<std::string> warnings() const {
    std::vector<std::string> out;
    const size_t normalLine = undefinedNormals.firstLine(normals.size());
    const size_t texcoordLine = undefinedTexcoords.firstLine(texcoords);
    if (normalLine != 0) {
      out.push_back(name + ": faces name normals the file does not define (first on line " +
                    std::to_string(normalLine) + "); using computed normals");
    }
    if (texcoordLine != 0) {
      out.push_back(
          name + ": faces name texture coordinates the file does not define (first on line " +
          std::to_string(texcoordLine) + "); ignored, as texture coordinates are not used");
    }
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
    loaded.warnings = warnings();
    // The chains found vertices while the faces were read, and the face buffers held them: not
    // needed any more.
    vertices.releaseChains();
    freeStorage(cornerTokens);
    freeStorage(face);
    triangulator.release();
    if (forwardNormals && vertices.anyNormalPast(normals.size())) {
      vertices.mergeUndefinedNormals(normals.size(), indices);
    }

    MeshData& mesh = loaded.mesh;
    mesh.name = name;
    // The vertices first: they set the parse's peak (core/obj_vertices.cpp).
    mesh.vertices = vertices.makeVertices(positions, normals, indices);
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
