// The OBJ loader on the project's models, on files with each quirk of the course's models, and
// on bad files: each bad file gets a message that names it and the problem.
#include <gtest/gtest.h>

#include <cmath>

#include "core/obj_loader.h"

namespace reflect {
namespace {

const std::string kData = std::string(TEST_DATA_DIR) + "/obj/";
const std::string kModels = std::string(MODEL_DIR) + "/";

MeshData mustLoad(const std::string& path) {
  Result<LoadedMesh> r = loadObjFile(path);
  EXPECT_TRUE(r) << r.error();
  if (r) {
    EXPECT_TRUE(r.value().warnings.empty()) << path << ": " << r.value().warnings[0];
  }
  return r ? r.take().mesh : MeshData{};
}

// Loads OBJ text that must load, and returns it with its warnings.
LoadedMesh mustParse(const std::string& text, const std::string& name = "x.obj") {
  Result<LoadedMesh> r = parseObj(text, name);
  EXPECT_TRUE(r) << r.error();
  return r ? r.take() : LoadedMesh{};
}

void expectUnitNormals(const MeshData& mesh) {
  for (const Vertex& v : mesh.vertices) {
    ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f) << mesh.name;
    ASSERT_TRUE(std::isfinite(v.position.x + v.position.y + v.position.z)) << mesh.name;
  }
}

std::string errorOf(const std::string& path, const ObjLimits& limits = {}) {
  Result<LoadedMesh> r = loadObjFile(path, limits);
  EXPECT_FALSE(r) << path << " should not load";
  return r ? std::string() : r.error();
}

TEST(ObjLoader, ProjectSphereIsTheCourseIcosphere) {
  MeshData sphere = mustLoad(kModels + "sphere.obj");
  EXPECT_EQ(sphere.triangleCount(), 320u);
  EXPECT_EQ(sphere.vertices.size(), 162u);
  EXPECT_NEAR(sphere.bounds.centre().y, 0.5f, 1e-3f);
  EXPECT_NEAR(sphere.bounds.max.x, 2.5456f, 1e-3f);
  expectUnitNormals(sphere);
}

// Glass leaves a sphere in closed form and anything else through its interior map: the cube's
// corners lie on a sphere too, but its flat faces' normals do not point away from the centre.
TEST(ObjLoader, TheSphereIsASphereAndTheCubeIsNot) {
  const MeshData sphere = mustLoad(kModels + "sphere.obj");
  EXPECT_GT(sphereRadiusOf(sphere), 0.0f);
  EXPECT_EQ(sphereRadiusOf(mustLoad(kModels + "cube.obj")), 0.0f);
}

TEST(ObjLoader, ProjectFiguresHaveTheCourseExtents) {
  MeshData mario = mustLoad(kModels + "mario.obj");
  EXPECT_NEAR(mario.bounds.min.x, -42.9f, 0.05f);
  EXPECT_NEAR(mario.bounds.max.y, 60.5f, 0.05f);
  EXPECT_NEAR(mario.bounds.min.z, -29.4f, 0.05f);
  EXPECT_GT(mario.triangleCount(), 1000u);
  expectUnitNormals(mario);
  MeshData sonic = mustLoad(kModels + "sonic.obj");  // has mtllib with no .mtl beside it
  EXPECT_NEAR(sonic.bounds.min.y, -0.1f, 0.05f);
  EXPECT_NEAR(sonic.bounds.max.x, 11.0f, 0.05f);
  EXPECT_NEAR(sonic.bounds.min.z, -10.6f, 0.05f);
  EXPECT_GT(sonic.triangleCount(), 1000u);
  expectUnitNormals(sonic);
}

TEST(ObjLoader, QuadsAreTriangulated) {
  MeshData cube = mustLoad(kData + "quads_vtvn.obj");
  EXPECT_EQ(cube.triangleCount(), 12u);
  expectUnitNormals(cube);
  EXPECT_EQ(mustLoad(kData + "pos_only_quads.obj").triangleCount(), 2u);
}

TEST(ObjLoader, SeveralObjectsAndAMissingMtlLoad) {
  EXPECT_EQ(mustLoad(kData + "multi_object_usemtl.obj").triangleCount(), 9u);
}

// `\r\r\n` line ends (as the course's own files have), and a file with no normals (computed):
// each is the same tetrahedron with unit normals.
TEST(ObjLoader, CarriageReturnsAndMissingNormalsStillGiveTheTetrahedron) {
  for (const char* file : {"crcrlf.obj", "no_normals.obj"}) {
    const MeshData tetra = mustLoad(kData + file);
    EXPECT_EQ(tetra.triangleCount(), 4u) << file;
    expectUnitNormals(tetra);
  }
}

TEST(ObjLoader, RelativeIndices) {
  EXPECT_EQ(mustLoad(kData + "negative_indices.obj").triangleCount(), 1u);
}

TEST(ObjLoader, BadFilesNameTheFileAndTheProblem) {
  EXPECT_EQ(errorOf(kData + "empty.obj"),
            kData + "empty.obj: no faces found: not an OBJ model, or an empty one");
  EXPECT_EQ(errorOf(kData + "comments_only.obj"),
            kData + "comments_only.obj: no faces found: not an OBJ model, or an empty one");
  EXPECT_EQ(errorOf("/no/such/model.obj"), "/no/such/model.obj: cannot open file");

  const std::string range = errorOf(kData + "index_out_of_range.obj");
  EXPECT_NE(range.find("index_out_of_range.obj: line "), std::string::npos) << range;
  EXPECT_NE(range.find("vertex index 7 is out of range (3 defined so far)"), std::string::npos)
      << range;

  const std::string nan = errorOf(kData + "nan_vertex.obj");
  EXPECT_NE(nan.find("nan_vertex.obj: line "), std::string::npos) << nan;
  EXPECT_NE(nan.find("is not a finite number"), std::string::npos) << nan;

  const std::string truncated = errorOf(kData + "truncated.obj");
  EXPECT_NE(truncated.find("truncated.obj: line "), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("a face needs at least 3 vertices"), std::string::npos) << truncated;

  const std::string garbage = errorOf(kData + "garbage.obj");
  EXPECT_EQ(garbage.rfind(kData + "garbage.obj: ", 0), 0u) << garbage;
}

// tinyobjloader's own number reader made NaN of "0e500" (0 times 5^500) and inf of a 401-digit
// mantissa before its exponent scales it back (found by fuzz_obj), so such files were refused.
// The streaming parser reads every number as strtof does: they are 0 and 1, and load.
TEST(ObjLoader, NumbersAreReadAsStrtofReadsThem) {
  Result<LoadedMesh> zero = parseObj("v 0 0 0\nv 0e500 0 0\nv 0 1 0\nf 1 2 3\n", "x.obj");
  ASSERT_TRUE(zero) << zero.error();
  EXPECT_EQ(zero.value().mesh.vertices[1].position, glm::vec3(0, 0, 0));
  const std::string longMantissa = "1" + std::string(400, '0') + "e-400";
  Result<LoadedMesh> one = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\n# normal\nvn 0 0 1\nvn 0 0 " +
                                        longMantissa + "\nf 1//1 2//2 3//1\n",
                                    "x.obj");
  ASSERT_TRUE(one) << one.error();
  for (const Vertex& v : one.value().mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
  // Numbers that really are out of range are refused with their line.
  EXPECT_EQ(parseObj("v 0 0 0\nv 1e39 0 0\n", "x.obj").error(),
            "x.obj: line 2: '1e39' is not a finite number");
}

TEST(ObjLoader, SizeLimitsProtectMemory) {
  ObjLimits tiny;
  tiny.maxBytes = 100;
  EXPECT_NE(errorOf(kModels + "sphere.obj", tiny).find("bytes, over the limit of 100"),
            std::string::npos);
  ObjLimits fewTriangles;
  fewTriangles.maxTriangles = 10;
  EXPECT_NE(errorOf(kModels + "sphere.obj", fewTriangles).find("more than 10 triangles"),
            std::string::npos);
}

TEST(ObjLoader, ParsesTextInMemoryWithTheGivenName) {
  Result<LoadedMesh> r = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "inline.obj");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().mesh.name, "inline.obj");
  EXPECT_EQ(r.value().mesh.vertices[0].normal, glm::vec3(0, 0, 1));
  EXPECT_TRUE(r.value().warnings.empty());
  EXPECT_EQ(parseObj("f 1 2 3\n", "x.obj").error(),
            "x.obj: line 1: vertex index 1 is out of range (0 defined so far)");
  EXPECT_EQ(parseObj("v 1 2\n", "x.obj").error(), "x.obj: line 1: 'v' needs three numbers");
  EXPECT_EQ(parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "x.obj").error(),
            "x.obj: line 4: vertex index 0 is out of range (3 defined so far)");
  // A zero-area triangle loads; its computed normal falls back to a finite default.
  Result<LoadedMesh> flat = parseObj("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "flat.obj");
  ASSERT_TRUE(flat) << flat.error();
  for (const Vertex& v : flat.value().mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
}

// Real exports often name normals (or texture coordinates) they never write. Such a file loads,
// as in other loaders: those corners get computed normals, and the file one warning per problem.
constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // computed normal +Z

TEST(ObjLoader, NormalsTheFileNeverDefinesAreComputedWithOneWarning) {
  LoadedMesh m = mustParse(std::string(kTriangle) + "f 1//1 2//2 3//3\nf 1//4 2//5 3//6\n");
  EXPECT_EQ(m.warnings,
            std::vector<std::string>{"x.obj: faces name normals the file does not define (first "
                                     "on line 4); using computed normals"});
  ASSERT_EQ(m.mesh.triangleCount(), 2u);
  EXPECT_EQ(m.mesh.vertices.size(), 3u);  // an undefined normal is no normal: one vertex each
  for (const Vertex& v : m.mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
}

TEST(ObjLoader, ANormalIndexPastTheLastNormalIsComputedTheOthersKept) {
  LoadedMesh m = mustParse(std::string(kTriangle) +
                           "v 0 0 1\nvn 1 0 0\nf 1//1 2//1 3//1\nf 1//2 2//2 4//2\nf 1//9 2//9 "
                           "4//9\n");
  EXPECT_EQ(m.warnings,
            std::vector<std::string>{"x.obj: faces name normals the file does not define (first "
                                     "on line 7); using computed normals"});
  ASSERT_EQ(m.mesh.triangleCount(), 3u);
  // The first face keeps the file's normal; the others (the same two undefined indices read as
  // none) share a computed one: their positions' area-weighted sums, normalised.
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(m.mesh.vertices[m.mesh.indices[i]].normal, glm::vec3(1, 0, 0));
  }
  const Vertex& corner = m.mesh.vertices[m.mesh.indices[3]];
  EXPECT_EQ(corner.position, glm::vec3(0, 0, 0));
  // Position 1 is in all three faces: (0, 0, 1) from the first, (0, -1, 0) from each other one.
  EXPECT_NEAR(corner.normal.x, 0.0f, 1e-6f);
  EXPECT_NEAR(corner.normal.y, -2.0f / std::sqrt(5.0f), 1e-6f);
  EXPECT_NEAR(corner.normal.z, 1.0f / std::sqrt(5.0f), 1e-6f);
  EXPECT_EQ(m.mesh.vertices[m.mesh.indices[6]].normal, corner.normal);
}

TEST(ObjLoader, ANegativeNormalIndexReachingBeforeTheFirstIsComputed) {
  LoadedMesh m = mustParse(std::string(kTriangle) + "vn 1 0 0\nf 1//-2 2//-2 3//-2\n");
  EXPECT_EQ(m.warnings,
            std::vector<std::string>{"x.obj: faces name normals the file does not define (first "
                                     "on line 5); using computed normals"});
  for (const Vertex& v : m.mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
}

TEST(ObjLoader, ANormalDefinedAfterTheFaceIsTheFilesNotAWarning) {
  LoadedMesh m = mustParse(std::string(kTriangle) + "f 1//1 2//1 3//1\nvn 1 0 0\n");
  EXPECT_TRUE(m.warnings.empty());
  for (const Vertex& v : m.mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(1, 0, 0));
}

TEST(ObjLoader, TextureCoordinatesTheFileNeverDefinesAreIgnoredWithOneWarning) {
  LoadedMesh m =
      mustParse(std::string(kTriangle) + "vn 1 0 0\nf 1/1/1 2/2/1 3/3/1\nf 1/7 2/8 3/9\n");
  EXPECT_EQ(m.warnings, std::vector<std::string>{
                            "x.obj: faces name texture coordinates the file does not define "
                            "(first on line 5); ignored, as texture coordinates are not used"});
  ASSERT_EQ(m.mesh.triangleCount(), 2u);
  // The normals are the file's where it names one, computed where not.
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(m.mesh.vertices[m.mesh.indices[i]].normal, glm::vec3(1, 0, 0));
    EXPECT_EQ(m.mesh.vertices[m.mesh.indices[i + 3]].normal, glm::vec3(0, 0, 1));
  }
}

TEST(ObjLoader, AFileWithBothNamesItselfInEachWarning) {
  Result<LoadedMesh> r = loadObjFile(kData + "undefined_normals.obj");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r.value().warnings,
            (std::vector<std::string>{
                kData + "undefined_normals.obj: faces name normals the file does not define "
                        "(first on line 8); using computed normals",
                kData + "undefined_normals.obj: faces name texture coordinates the file does not "
                        "define (first on line 8); ignored, as texture coordinates are not used"}));
  EXPECT_EQ(r.value().mesh.triangleCount(), 4u);
  expectUnitNormals(r.value().mesh);
  // The same normals as the file without any normals.
  const MeshData plain = mustLoad(kData + "no_normals.obj");
  ASSERT_EQ(plain.vertices.size(), r.value().mesh.vertices.size());
  for (size_t i = 0; i < plain.vertices.size(); ++i) {
    EXPECT_EQ(plain.vertices[i].normal, r.value().mesh.vertices[i].normal);
  }
}

TEST(ObjLoader, WhatIsTrulyBrokenIsStillRefused) {
  // Index 0 is never valid (tinyobjloader refuses the file), nor is a vertex the file lacks.
  EXPECT_EQ(parseObj(std::string(kTriangle) + "f 1//0 2//0 3//0\n", "x.obj").error(),
            "x.obj: line 4: normal index 0 is out of range (0 defined so far)");
  EXPECT_EQ(parseObj(std::string(kTriangle) + "f 1//1 2//1 4//1\n", "x.obj").error(),
            "x.obj: line 4: vertex index 4 is out of range (3 defined so far)");
  EXPECT_EQ(parseObj(std::string(kTriangle) + "f 1//x 2//1 3//1\n", "x.obj").error(),
            "x.obj: line 4: '1//x' is not a face index");
}

}  // namespace
}  // namespace reflect
