// Typed reading of a parsed JSON document that remembers where it is, so every error names the
// file and the key path: "scenes/x.json: objects[2].material.ior: expected a number".
// The first error wins; later reads are no-ops. No exceptions (the web build has none).
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>

#include <glm/glm.hpp>

#include "core/result.h"

namespace reflect {

// How deep arrays and objects may nest in any JSON the code reads (scene files, the page's
// requests; the deepest real one is a scene file's, at 4). Reading, writing (dump) and walking
// a document recurse once a level, so this bounds the stack they use: the web build's stack is
// small (CMakeLists.txt), and a deeper file would overflow it instead of being refused.
inline constexpr int kMaxJsonDepth = 64;

// Parses JSON text; an error carries nlohmann's line and column.
Result<nlohmann::json> parseJson(const std::string& text, const std::string& source);

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string path, std::string* error)
      : value_(value), path_(std::move(path)), error_(error) {}

  bool ok() const { return error_->empty(); }
  const std::string& path() const { return path_; }
  bool has(const char* key) const { return value_.is_object() && value_.contains(key); }
  bool isObject() const { return value_.is_object(); }
  bool isString() const { return value_.is_string(); }
  size_t size() const { return value_.is_array() ? value_.size() : 0; }

  // Child readers (the path grows). A missing key reads as null: required reads then fail.
  JsonReader operator[](const char* key) const;
  JsonReader operator[](size_t index) const;

  void fail(const std::string& message) const;
  // Every key of this object must be one of `allowed` (catches typos in scene files).
  void onlyKeys(const std::set<std::string>& allowed) const;
  bool requireObject() const;
  bool requireArray() const;

  double number(double fallback, double lo, double hi) const;  // fallback when absent
  int integer(int fallback, int lo, int hi) const;
  bool boolean(bool fallback) const;
  std::string string(const std::string& fallback) const;
  glm::vec3 vec3(const glm::vec3& fallback) const;
  // A number s (meaning (s, s, s)) or a 3-array.
  glm::vec3 scaleVec3(const glm::vec3& fallback) const;

 private:
  bool absent() const { return value_.is_null(); }

  const nlohmann::json& value_;
  std::string path_;
  std::string* error_;
};

}  // namespace reflect
