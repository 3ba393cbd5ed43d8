// The bridge's conventions (see web_state.h): the shared state, reading a request, writing a reply.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "platform/web/web_state.h"

namespace reflect::web {
namespace {

// A double that is exactly a float, as the shortest decimal that reads back as that float: the
// settings are floats, and 0.78f would otherwise show as 0.7799999713897705.
double shortestFloat(double value) {
  const float f = static_cast<float>(value);
  if (!std::isfinite(value) || static_cast<double>(f) != value) return value;
  return std::strtod(shortestText(f).c_str(), nullptr);
}

void tidyFloats(nlohmann::json& value) {
  if (value.is_number_float()) {
    value = shortestFloat(value.get<double>());
  } else if (value.is_structured()) {
    for (nlohmann::json& item : value) tidyFloats(item);
  }
}

}  // namespace

std::string shortestText(float value) {
  std::string text;
  for (int digits = 1; digits <= 9; ++digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    text = out.str();
    if (std::strtof(text.c_str(), nullptr) == value) break;
  }
  return text;
}

WebState& state() {
  static WebState s;
  return s;
}

Result<nlohmann::json> parseRequest(const char* text, const char* function) {
  const std::string request = text ? text : "";
  if (request.empty()) return nlohmann::json::object();
  Result<nlohmann::json> json = parseJson(request, function);
  if (json && json.value().is_null()) return nlohmann::json::object();
  if (json && !json.value().is_object()) {
    return Result<nlohmann::json>::failure(std::string(function) + ": expected an object");
  }
  return json;
}

const char* reply(const nlohmann::json& value) {
  nlohmann::json tidy = value;
  tidyFloats(tidy);
  state().reply = tidy.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return state().reply.c_str();
}

const char* replyError(const std::string& message) {
  if (message.empty()) return reply(nlohmann::json::object());
  return reply({{"error", message}});
}

const char* replyDone(const std::string& notice) {
  if (notice.empty()) return reply(nlohmann::json::object());
  return reply({{"notice", notice}});
}

}  // namespace reflect::web
