// Wavefront OBJ parsed as it streams in: the page feeds each piece of a download as it arrives,
// the native loader each piece of the file it reads, and neither ever holds the whole text. A
// piece may end anywhere: inside a line, a number, or between the CR and LF of a line end.
//
// One pass checks and parses each line (the checks, their messages and the mesh are those of the
// loader this replaced, which checked the text line by line and then parsed it with
// tinyobjloader): quads split along their shorter diagonal and larger polygons by tinyobjloader's
// ear clipping; a vertex is a (position, normal) pair, numbered in the order of first use; faces
// that name normals the file never defines get computed normals (area-weighted per position), with
// a warning; texture coordinates are checked and ignored. The parse keeps positions, normals,
// vertices (as position and normal numbers) and triangles in blocks (BlockArray) so nothing is
// copied as it grows; finish() makes the vertices and hands them and the triangles over as exactly
// sized arrays, ordered so that the memory it peaks at is the parse's and one of them.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "core/obj_loader.h"

namespace reflect {

class ObjStreamParser {
 public:
  // `name` is used in every message (usually the path or URL the bytes come from).
  explicit ObjStreamParser(std::string name, const ObjLimits& limits = {});
  ~ObjStreamParser();
  ObjStreamParser(ObjStreamParser&&) noexcept;
  ObjStreamParser& operator=(ObjStreamParser&&) noexcept;

  // Parses every line `bytes` completes; the rest waits for the next piece. Returns false once the
  // file has failed (error() says why; later bytes are counted and ignored).
  bool feed(std::string_view bytes);
  // The end of the file: parses its last line, then returns the mesh or the first problem (with
  // the name). The parser is empty afterwards.
  Result<LoadedMesh> finish();

  bool failed() const;
  // The first problem, with the name ("" while there is none).
  std::string error() const;
  size_t bytesFed() const;
  size_t linesParsed() const;
  // The bytes of a line begun but not yet ended: all of the text the parser holds.
  size_t partialLineBytes() const;
  // Every byte the parser holds now: the partial line and the arrays of what it has read.
  size_t heldBytes() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace reflect
