// An enum's names as one table (each value once, with the name scene files, links and the CLI
// use), from which both the name of a value and the parse of a name are read: a name cannot be
// added to one and forgotten in the other.
#pragma once

#include <cstddef>
#include <string>

namespace reflect {

template <typename E>
struct EnumName {
  E value;
  const char* name;
};

// The name of `value`, or "?" for a value the table lacks.
template <typename E, size_t N>
const char* nameIn(const EnumName<E> (&table)[N], E value) {
  for (const EnumName<E>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return "?";
}

// The value named `text` into *value; false (and *value unchanged) for a name the table lacks.
template <typename E, size_t N>
bool parseIn(const EnumName<E> (&table)[N], const std::string& text, E* value) {
  for (const EnumName<E>& entry : table) {
    if (text == entry.name) {
      *value = entry.value;
      return true;
    }
  }
  return false;
}

}  // namespace reflect
