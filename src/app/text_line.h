// One printf-formatted line of an explanation (pixel_explain_text, pixel_lobe): the lines are
// short, so a fixed buffer is enough; a longer one is cut, never overrun.
#pragma once

#include <cstdio>
#include <string>

namespace reflect {

template <typename... Values>
std::string formatLine(const char* pattern, Values... values) {
  char line[256];
  std::snprintf(line, sizeof line, pattern, values...);
  return line;
}

}  // namespace reflect
