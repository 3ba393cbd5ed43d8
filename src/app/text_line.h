// One printf-formatted line of an explanation (pixel_explain_text, pixel_lobe), whole whatever
// its length.
#pragma once

#include <cstdio>
#include <string>

namespace reflect {

template <typename... Values>
std::string formatLine(const char* pattern, Values... values) {
  const int length = std::snprintf(nullptr, 0, pattern, values...);
  if (length <= 0) return {};
  std::string line(static_cast<size_t>(length) + 1, '\0');
  std::snprintf(line.data(), line.size(), pattern, values...);
  line.resize(static_cast<size_t>(length));
  return line;
}

}  // namespace reflect
