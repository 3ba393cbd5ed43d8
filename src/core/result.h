// A value or an error message. The project builds without exceptions for the web, so loaders
// report failure through this instead of throwing.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace reflect {

template <typename T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  static Result failure(std::string message) {
    Result r;
    r.error_ = std::move(message);
    return r;
  }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return error_; }
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  T take() { return std::move(*value_); }

 private:
  Result() = default;
  std::optional<T> value_;
  std::string error_;
};

}  // namespace reflect
