#include "core/json_reader.h"

#include <cmath>

namespace reflect {
namespace {

const nlohmann::json& nullJson() {
  static const nlohmann::json null;
  return null;
}

// Collects nothing; only notices the first syntax error and where it is, and nesting deeper
// than kMaxJsonDepth.
class ErrorCatcher : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string error;
  int depth = 0;
  bool enter() {
    if (++depth <= kMaxJsonDepth) return true;
    error = "arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
    return false;
  }
  bool leave() {
    --depth;
    return true;
  }
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return enter(); }
  bool key(string_t&) override { return true; }
  bool end_object() override { return leave(); }
  bool start_array(std::size_t) override { return enter(); }
  bool end_array() override { return leave(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    error = e.what();
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> from "line".
    const size_t at = error.find("line ");
    if (at != std::string::npos) error = error.substr(at);
    return false;
  }
};

}  // namespace

Result<nlohmann::json> parseJson(const std::string& text, const std::string& source) {
  ErrorCatcher catcher;
  if (!nlohmann::json::sax_parse(text, &catcher) || !catcher.error.empty()) {
    return Result<nlohmann::json>::failure(source + ": not valid JSON: " + catcher.error);
  }
  return nlohmann::json::parse(text, nullptr, false);
}

JsonReader JsonReader::operator[](const char* key) const {
  const std::string path = path_.empty() ? key : path_ + "." + key;
  if (!value_.is_object() || !value_.contains(key)) return JsonReader(nullJson(), path, error_);
  return JsonReader(value_.at(key), path, error_);
}

JsonReader JsonReader::operator[](size_t index) const {
  const std::string path = path_ + "[" + std::to_string(index) + "]";
  if (!value_.is_array() || index >= value_.size()) return JsonReader(nullJson(), path, error_);
  return JsonReader(value_.at(index), path, error_);
}

void JsonReader::fail(const std::string& message) const {
  if (error_->empty())
    *error_ = (path_.empty() ? std::string("top level") : path_) + ": " + message;
}

void JsonReader::onlyKeys(const std::set<std::string>& allowed) const {
  if (!value_.is_object()) return;
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (allowed.count(it.key()) == 0) {
      (*this)[it.key().c_str()].fail("unknown key");
      return;
    }
  }
}

bool JsonReader::requireObject() const {
  if (value_.is_object()) return true;
  fail(absent() ? "missing (expected an object)" : "expected an object");
  return false;
}

bool JsonReader::requireArray() const {
  if (value_.is_array()) return true;
  fail(absent() ? "missing (expected an array)" : "expected an array");
  return false;
}

double JsonReader::number(double fallback, double lo, double hi) const {
  if (absent()) return fallback;
  if (!value_.is_number()) {
    fail("expected a number");
    return fallback;
  }
  const double v = value_.get<double>();
  if (!std::isfinite(v) || v < lo || v > hi) {
    char range[96];
    std::snprintf(range, sizeof range, "expected a number from %g to %g", lo, hi);
    fail(range);
    return fallback;
  }
  return v;
}

int JsonReader::integer(int fallback, int lo, int hi) const {
  if (absent()) return fallback;
  const double v = number(fallback, lo, hi);
  if (v != std::floor(v)) {
    fail("expected a whole number");
    return fallback;
  }
  return static_cast<int>(v);
}

bool JsonReader::boolean(bool fallback) const {
  if (absent()) return fallback;
  if (!value_.is_boolean()) {
    fail("expected true or false");
    return fallback;
  }
  return value_.get<bool>();
}

std::string JsonReader::string(const std::string& fallback) const {
  if (absent()) return fallback;
  if (!value_.is_string()) {
    fail("expected a string");
    return fallback;
  }
  return value_.get<std::string>();
}

glm::vec3 JsonReader::vec3(const glm::vec3& fallback) const {
  if (absent()) return fallback;
  if (!value_.is_array() || value_.size() != 3) {
    fail("expected an array of 3 numbers");
    return fallback;
  }
  glm::vec3 v;
  for (size_t i = 0; i < 3; ++i)
    v[static_cast<int>(i)] = static_cast<float>((*this)[i].number(0, -1e9, 1e9));
  return v;
}

glm::vec3 JsonReader::scaleVec3(const glm::vec3& fallback) const {
  if (value_.is_number()) return glm::vec3(static_cast<float>(number(1, -1e9, 1e9)));
  return vec3(fallback);
}

}  // namespace reflect
