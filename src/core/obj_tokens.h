// The lexical layer of the OBJ parser (core/obj_stream.h): a line's white-space separated tokens,
// and the two kinds of number a token may be. Each reads exactly what the C library would (strtof,
// strtol), so the mesh does not depend on which path read a number.
#pragma once

#include <cstddef>
#include <string_view>

namespace reflect {

inline bool isObjBlank(char c) {
  return c == ' ' || c == '\t';
}

// The white-space separated tokens of a line, one at a time.
class ObjTokens {
 public:
  explicit ObjTokens(std::string_view line) : line_(line) {}
  // The next token, or an empty view at the end.
  std::string_view next() {
    while (pos_ < line_.size() && isObjBlank(line_[pos_])) ++pos_;
    const size_t start = pos_;
    while (pos_ < line_.size() && !isObjBlank(line_[pos_])) ++pos_;
    return line_.substr(start, pos_ - start);
  }

 private:
  std::string_view line_;
  size_t pos_ = 0;
};

// A finite number, the whole token, exactly as strtof reads it; false for anything else
// (including numbers strtof reads as infinite).
bool parseObjFloat(std::string_view token, float* out);

// An optional sign and then digits, the whole token, saturating as strtol does; false otherwise.
bool parseObjIndex(std::string_view token, long* out);

}  // namespace reflect
