// An OBJ face's corners ("v", "v/t", "v//n", "v/t/n") read into numbers, and what they tell of
// references the file never defines (core/obj_stream.h warns about those at the end).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/obj_vertices.h"

namespace reflect {

// What a face line's corners name beyond their vertices, per kind (0: texture coordinates,
// 1: normals): the largest index, and whether a negative index reached back before the first
// definition. forwardNormal: a positive normal index past those read so far.
struct CornerReferences {
  long largest[2] = {0, 0};
  bool before[2] = {false, false};
  bool forwardNormal = false;
};

// How many of each kind the file has defined so far.
struct ObjCounts {
  size_t positions = 0;
  size_t texcoords = 0;
  size_t normals = 0;
};

// One corner's text into `out`, noting its references in `refs`. Returns the problem, or "". A
// vertex must be defined before the face; a normal or texture coordinate the file does not
// define is only noted.
std::string readObjCorner(std::string_view text, const ObjCounts& defined, ObjCorner* out,
                          CornerReferences* refs);

// Which face lines name a normal (texture coordinate) that the file never defines: a negative
// index that reaches back before the first definition is known at once; a positive one past the
// definitions so far is undefined only if the file never gets that far, known at the end.
class UndefinedReferences {
 public:
  // Face line `line` named at most `largest`, and reached back before the first definition
  // (`before`), when `defined` were defined.
  void noteLine(size_t line, long largest, bool before, size_t defined);
  // The file has defined `count` now.
  void defined(size_t count);
  // The first line naming one past `total`, or before the first; 0 if none.
  size_t firstLine(size_t total) const;

 private:
  size_t firstBefore_ = 0;  // the first line with a negative index before the first definition
  // Lines with a positive index past what was defined then, each with its largest index; kept
  // only while that index rises, since a later line with a smaller index cannot be the first
  // undefined one. Entries that definitions have since covered are dropped from the front.
  std::vector<std::pair<size_t, long>> pending_;
  size_t pendingStart_ = 0;
};

}  // namespace reflect
