// A line-by-line check of OBJ text before tinyobjloader sees it. tinyobjloader reads "nan" as 0,
// skips faces with bad indices with only a warning, and trusts counts; this pass turns each of
// those into an error with a line number, and bounds the work before any big allocation.
// Faces that name normals or texture coordinates the file never defines are not errors (other
// loaders take such files too): the pass notes the first line that does, for the loader's
// warning.
#pragma once

#include <string>
#include <string_view>

#include "core/obj_loader.h"

namespace reflect {

struct ObjCounts {
  size_t positions = 0;
  size_t normals = 0;
  size_t texcoords = 0;
  size_t triangles = 0;  // after fan triangulation of every face
  // The first line whose face names a normal (texture coordinate) the file does not define: a
  // positive index past the file's last `vn` (`vt`), or a negative one reaching back before its
  // first. 0 when every face's indices resolve.
  size_t undefinedNormalLine = 0;
  size_t undefinedTexcoordLine = 0;
};

// Returns the counts, or an error "line N: ..." (without the file name; the caller adds it).
Result<ObjCounts> validateObjText(const std::string& text, const ObjLimits& limits);

// "line N: what", the form of every per-line message about an OBJ file.
std::string lineError(size_t lineNumber, const std::string& what);

// The 1-based line number of the ordinal-th (0-based) line starting with `keyword` ("v", "vn"),
// split into lines as validateObjText does; 0 if there are fewer such lines.
size_t lineOfAttribute(const std::string& text, std::string_view keyword, size_t ordinal);

}  // namespace reflect
