// The streaming OBJ parser: the same mesh whether the text comes whole or in pieces of any size
// (split inside a line, a number, a CR LF), the same mesh as the loader it replaced (tinyobjloader
// behind a checking pass, kept here as the oracle), and what it holds while it parses.
#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <unordered_map>

#include "core/obj_loader.h"
#include "core/obj_stream.h"

namespace reflect {
namespace {

const std::string kData = std::string(TEST_DATA_DIR) + "/obj/";
const std::string kModels = std::string(MODEL_DIR) + "/";
const std::string kCorpus = std::string(FUZZ_CORPUS_DIR) + "/obj/";

std::string readFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The mesh the replaced loader made of valid text: tinyobjloader (triangulating), then one vertex
// per (position, normal) pair in the order of first use, file normals normalised, computed
// (area-weighted per position) where a corner has none or a zero one.
MeshData tinyobjMesh(const std::string& text) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  EXPECT_TRUE(reader.ParseFromString(text, std::string(), config)) << reader.Error();
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto read = [](const std::vector<tinyobj::real_t>& data, int index) {
    const size_t i = static_cast<size_t>(index) * 3;
    return glm::vec3(data[i], data[i + 1], data[i + 2]);
  };
  const auto normalizedOr = [](const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return (length > 1e-20f && std::isfinite(length)) ? v / length : fallback;
  };
  std::vector<glm::vec3> sums(attrib.vertices.size() / 3, glm::vec3(0.0f));
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& idx = shape.mesh.indices;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
      const glm::vec3 a = read(attrib.vertices, idx[t].vertex_index);
      const glm::vec3 b = read(attrib.vertices, idx[t + 1].vertex_index);
      const glm::vec3 c = read(attrib.vertices, idx[t + 2].vertex_index);
      const glm::vec3 n = glm::cross(b - a, c - a);
      for (size_t k = 0; k < 3; ++k) sums[static_cast<size_t>(idx[t + k].vertex_index)] += n;
    }
  }
  const size_t normalCount = attrib.normals.size() / 3;
  MeshData mesh;
  std::unordered_map<uint64_t, uint32_t> vertexOfPair;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& corner : shape.mesh.indices) {
      const int normal =
          corner.normal_index >= 0 && static_cast<size_t>(corner.normal_index) < normalCount
              ? corner.normal_index
              : -1;
      const uint64_t key =
          (static_cast<uint64_t>(static_cast<uint32_t>(corner.vertex_index)) << 32) |
          static_cast<uint32_t>(normal);
      auto [it, inserted] =
          vertexOfPair.try_emplace(key, static_cast<uint32_t>(mesh.vertices.size()));
      if (inserted) {
        Vertex v;
        v.position = read(attrib.vertices, corner.vertex_index);
        v.normal = normal >= 0 ? normalizedOr(read(attrib.normals, normal), glm::vec3(0.0f))
                               : glm::vec3(0.0f);
        if (v.normal == glm::vec3(0.0f)) {
          v.normal = normalizedOr(sums[static_cast<size_t>(corner.vertex_index)], {0, 1, 0});
        }
        mesh.vertices.push_back(v);
      }
      mesh.indices.push_back(it->second);
    }
  }
  return mesh;
}

// Positions within one float step (tinyobjloader reads numbers through doubles; strtof rounds
// once), normals within 1e-6, triangles and vertex numbering exactly.
void expectSameMesh(const MeshData& expected, const MeshData& actual, const std::string& what) {
  ASSERT_EQ(expected.indices, actual.indices) << what;
  ASSERT_EQ(expected.vertices.size(), actual.vertices.size()) << what;
  for (size_t i = 0; i < expected.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float e = expected.vertices[i].position[k], a = actual.vertices[i].position[k];
      ASSERT_LE(std::fabs(e - a), std::fabs(e) * 1.2e-7f) << what << " vertex " << i;
      ASSERT_NEAR(expected.vertices[i].normal[k], actual.vertices[i].normal[k], 1e-6f)
          << what << " vertex " << i;
    }
  }
}

// Exactly equal meshes (the streaming parser against itself).
void expectIdentical(const LoadedMesh& expected, const LoadedMesh& actual,
                     const std::string& what) {
  EXPECT_EQ(expected.warnings, actual.warnings) << what;
  ASSERT_EQ(expected.mesh.indices, actual.mesh.indices) << what;
  ASSERT_EQ(expected.mesh.vertices.size(), actual.mesh.vertices.size()) << what;
  for (size_t i = 0; i < expected.mesh.vertices.size(); ++i) {
    ASSERT_EQ(expected.mesh.vertices[i].position, actual.mesh.vertices[i].position) << what << i;
    ASSERT_EQ(expected.mesh.vertices[i].normal, actual.mesh.vertices[i].normal) << what << i;
  }
  EXPECT_EQ(expected.mesh.bounds.min, actual.mesh.bounds.min) << what;
  EXPECT_EQ(expected.mesh.bounds.max, actual.mesh.bounds.max) << what;
}

// `text` fed in pieces of random sizes from 1 to `largest` bytes.
Result<LoadedMesh> parseInPieces(const std::string& text, uint32_t seed, size_t largest,
                                 const std::string& name = "x.obj") {
  std::mt19937 random(seed);
  std::uniform_int_distribution<size_t> size(1, largest);
  ObjStreamParser parser(name);
  for (size_t at = 0; at < text.size();) {
    const size_t n = std::min(size(random), text.size() - at);
    parser.feed(std::string_view(text).substr(at, n));
    at += n;
  }
  return parser.finish();
}

const std::vector<std::string>& validFiles() {
  static const std::vector<std::string> files = {kModels + "mario.obj",
                                                 kModels + "sonic.obj",
                                                 kModels + "sphere.obj",
                                                 kModels + "quad.obj",
                                                 kModels + "cube.obj",
                                                 kData + "crcrlf.obj",
                                                 kData + "multi_object_usemtl.obj",
                                                 kData + "negative_indices.obj",
                                                 kData + "no_normals.obj",
                                                 kData + "pos_only_quads.obj",
                                                 kData + "quads_vtvn.obj",
                                                 kData + "undefined_normals.obj"};
  return files;
}

// Polygons of 5 to 8 corners, convex and not, which tinyobjloader's ear clipper splits.
const char* kPolygons =
    "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1.5 2.5 0\nv -1 1 0\n"
    "v 0 0 1\nv 4 0 1\nv 4 4 1\nv 2 1 1\nv 0 4 1\n"  // a concave dart
    "v 0 0 2\nv 1 0 2.1\nv 2 0.5 2\nv 2 1.5 2.3\nv 1 2 2\nv 0 2 2\nv -0.5 1 2.2\n"  // bent heptagon
    "vn 0 0 1\n"
    "f 1//1 2//1 3//1 4//1 5//1\n"
    "f 6 7 8 9 10\n"
    "f 11 12 13 14 15 16 17\n"
    "f 1 2 3 4 5 6 7 8\n";

TEST(ObjStream, TheSameMeshAsTheTinyobjloaderPath) {
  for (const std::string& path : validFiles()) {
    const std::string text = readFile(path);
    Result<LoadedMesh> streamed = parseObj(text, path);
    ASSERT_TRUE(streamed) << streamed.error();
    expectSameMesh(tinyobjMesh(text), streamed.value().mesh, path);
  }
  Result<LoadedMesh> polygons = parseObj(kPolygons, "polygons.obj");
  ASSERT_TRUE(polygons) << polygons.error();
  EXPECT_GT(polygons.value().mesh.triangleCount(), 10u);
  expectSameMesh(tinyobjMesh(kPolygons), polygons.value().mesh, "polygons");
  // A hexagon the ear clipper gives up on: no triangles, as before.
  const std::string degenerate = readFile(kCorpus + "regress_degenerate_hexagon.obj");
  EXPECT_TRUE(tinyobjMesh(degenerate).indices.empty());
  EXPECT_EQ(parseObj(degenerate, "x.obj").error(), "x.obj: no triangles after parsing");
}

TEST(ObjStream, PiecesOfAnySizeGiveTheSameMesh) {
  std::vector<std::string> texts;
  for (const std::string& path : validFiles()) texts.push_back(readFile(path));
  texts.push_back(kPolygons);
  for (size_t i = 0; i < texts.size(); ++i) {
    Result<LoadedMesh> whole = parseObj(texts[i], "x.obj");
    ASSERT_TRUE(whole) << whole.error();
    for (uint32_t seed = 1; seed <= 6; ++seed) {
      // Pieces of a few bytes split nearly every number and line end; larger ones split some.
      for (size_t largest : {size_t{1}, size_t{3}, size_t{17}, size_t{4096}}) {
        Result<LoadedMesh> pieces = parseInPieces(texts[i], seed, largest);
        ASSERT_TRUE(pieces) << pieces.error();
        expectIdentical(whole.value(), pieces.value(),
                        "text " + std::to_string(i) + " seed " + std::to_string(seed) +
                            " pieces up to " + std::to_string(largest));
      }
    }
  }
}

TEST(ObjStream, SplitsInsideALineANumberAndALineEnd) {
  const std::string lf = "v 0.125 -1.5e1 3\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";
  std::string crlf, crcrlf;
  for (char c : lf) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    crcrlf += c == '\n' ? std::string("\r\r\n") : std::string(1, c);
  }
  Result<LoadedMesh> whole = parseObj(lf, "x.obj");
  ASSERT_TRUE(whole) << whole.error();
  EXPECT_EQ(whole.value().mesh.vertices[0].position, glm::vec3(0.125f, -15.0f, 3.0f));
  for (const std::string* text : std::vector<const std::string*>{&lf, &crlf, &crcrlf}) {
    // Every split point: inside "0.125", inside "-1.5e1" (between mantissa and exponent), inside
    // a keyword, between CR and LF, between the two CRs.
    for (size_t at = 1; at < text->size(); ++at) {
      ObjStreamParser parser("x.obj");
      parser.feed(std::string_view(*text).substr(0, at));
      parser.feed(std::string_view(*text).substr(at));
      Result<LoadedMesh> split = parser.finish();
      ASSERT_TRUE(split) << split.error();
      expectIdentical(whole.value(), split.value(), "split at " + std::to_string(at));
    }
  }
  // A last line without a line end is parsed at finish().
  Result<LoadedMesh> noEnd = parseInPieces(lf.substr(0, lf.size() - 1), 7, 5);
  ASSERT_TRUE(noEnd) << noEnd.error();
  expectIdentical(whole.value(), noEnd.value(), "no final line end");
}

TEST(ObjStream, ProblemsNameTheSameLineInPieces) {
  const std::string text = "v 0 0 0\nv 1 0 0\n\nv 0 1 0\nf 1 2 3\nf 1 2 9\nv 0 0 0\n";
  const std::string expected = "x.obj: line 6: vertex index 9 is out of range (3 defined so far)";
  EXPECT_EQ(parseObj(text, "x.obj").error(), expected);
  for (uint32_t seed = 1; seed <= 20; ++seed) {
    EXPECT_EQ(parseInPieces(text, seed, 4).error(), expected) << seed;
  }
  // A lone CR inside a line, split between the pieces.
  EXPECT_EQ(parseInPieces("v 0 0 0\nv 1\r0 0\n", 3, 2).error(),
            "x.obj: line 2: a carriage return inside a line (old Mac line ends are not "
            "supported)");
  // After a failure, later pieces change nothing.
  ObjStreamParser parser("y.obj");
  EXPECT_FALSE(parser.feed("v 1 2\n"));
  EXPECT_FALSE(parser.feed("v 0 0 0\n"));
  EXPECT_TRUE(parser.failed());
  EXPECT_EQ(parser.error(), "y.obj: line 1: 'v' needs three numbers");
  EXPECT_EQ(parser.finish().error(), "y.obj: line 1: 'v' needs three numbers");
}

TEST(ObjStream, NumbersAreReadAsStrtofReadsThem) {
  // The direct path (short decimals) and strtof (long, large exponents, odd forms) agree with
  // strtof bit for bit.
  const char* numbers[] = {"0",       "-0",         "1",        "+2.5",     "0.1",
                           "-0.3",    "3.14159",    "1234567",  "12345678", "0.00000001",
                           "1e10",    "1e-10",      "2.5E+3",   "1e38",     "1e-45",
                           ".5",      "5.",         "-.25e-2",  "0x1p3",    "7.0000001",
                           "9999999", "16777217.0", "0.300000", "100e-12",  "0e500"};
  for (const char* number : numbers) {
    const std::string text = std::string("v ") + number + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    Result<LoadedMesh> r = parseObj(text, "x.obj");
    ASSERT_TRUE(r) << number << ": " << r.error();
    const glm::vec3& p = r.value().mesh.vertices[0].position;
    EXPECT_EQ(p.x, std::strtof(number, nullptr)) << number;
  }
  for (const char* bad : {"1e39", "nan", "inf", "1.5x", "--1", "e5", "."}) {
    const std::string text = std::string("v ") + bad + " 0 0\n";
    EXPECT_EQ(parseObj(text, "x.obj").error(),
              std::string("x.obj: line 1: '") + bad + "' is not a finite number")
        << bad;
  }
}

// What the parser holds: the partial line and its arrays, never the text it has parsed.
TEST(ObjStream, HoldsThePartialLineNotTheText) {
  std::string text;
  for (int i = 0; i < 20000; ++i) {
    text += "# a comment line that takes room in the text but none in the mesh\n";
  }
  text += "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 0.5 0.25";
  ObjStreamParser parser("x.obj");
  ASSERT_TRUE(parser.feed(text));
  EXPECT_EQ(parser.partialLineBytes(), std::string("v 0.5 0.25").size());
  EXPECT_EQ(parser.bytesFed(), text.size());
  EXPECT_EQ(parser.linesParsed(), 20004u);
  // 1.3 MB of text went in; what is held is a few small arrays.
  EXPECT_LT(parser.heldBytes(), 16u * 1024u);
  ASSERT_TRUE(parser.feed(" 0\nf 1 2 4\n"));
  EXPECT_EQ(parser.partialLineBytes(), 0u);
  Result<LoadedMesh> r = parser.finish();
  ASSERT_TRUE(r) << r.error();
  // The result is exactly sized: no slack left from growing.
  EXPECT_EQ(r.value().mesh.vertices.capacity(), r.value().mesh.vertices.size());
  EXPECT_EQ(r.value().mesh.indices.capacity(), r.value().mesh.indices.size());
  EXPECT_EQ(r.value().mesh.triangleCount(), 2u);
}

// A position with many normals stays one vertex per (position, normal), past the chain limit.
TEST(ObjStream, APositionWithManyNormals) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 100; ++i) text += "vn 0 0." + std::to_string(i + 1) + " 1\n";
  for (int round = 0; round < 2; ++round) {
    for (int i = 1; i <= 100; ++i) {
      const std::string n = std::to_string(i);
      text += "f 1//" + n + " 2//" + n + " 3//" + n + "\n";
    }
  }
  Result<LoadedMesh> r = parseObj(text, "x.obj");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().mesh.vertices.size(), 300u);  // the second round reuses every vertex
  EXPECT_EQ(r.value().mesh.triangleCount(), 200u);
  expectSameMesh(tinyobjMesh(text), r.value().mesh, "many normals");
}

TEST(ObjStream, ANormalDefinedLaterOrNeverMatchesTheOldPath) {
  // Faces naming normals 1 and 9 before any is defined; only normal 1 ever is.
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1//1 2//1 3//1\nf 1//9 2//9 4//9\nf 1//8 4//8 "
      "3//8\nf 1 2 4\nvn 1 0 0\n";
  Result<LoadedMesh> r = parseObj(text, "x.obj");
  ASSERT_TRUE(r) << r.error();
  expectSameMesh(tinyobjMesh(text), r.value().mesh, "forward normals");
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    Result<LoadedMesh> pieces = parseInPieces(text, seed, 6);
    ASSERT_TRUE(pieces) << pieces.error();
    expectIdentical(r.value(), pieces.value(), "forward normals in pieces");
  }
  EXPECT_EQ(r.value().warnings,
            std::vector<std::string>{"x.obj: faces name normals the file does not define (first "
                                     "on line 6); using computed normals"});
}

}  // namespace
}  // namespace reflect
