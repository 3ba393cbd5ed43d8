#include "core/accuracy_settings.h"

#include <cctype>

namespace reflect {
namespace {

std::string trimmed(const std::string& s) {
  size_t begin = 0, end = s.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(s[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(s[end - 1]))) --end;
  return s.substr(begin, end - begin);
}

// "x2" after "distance ", "24" after "depth ": the digits of `part` after `prefix`, or -1.
int numberAfter(const std::string& part, const std::string& prefix) {
  if (part.compare(0, prefix.size(), prefix) != 0 || part.size() == prefix.size()) return -1;
  const std::string digits = part.substr(prefix.size());
  if (digits.size() > 4) return -1;
  int value = 0;
  for (char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
    value = value * 10 + (c - '0');
  }
  return value;
}

}  // namespace

std::string AccuracySettings::describe() const {
  std::string s = captureAtOrigin ? "origin" : "centre";
  s += distanceIterations > 0 ? ", distance x" + std::to_string(distanceIterations) : ", plain";
  s += ", depth " + std::to_string(depthBits);
  s += mipmaps ? ", mipmapped" : ", linear";
  s += usesHalfFloat() ? ", RGBA16F" : ", RGBA8";
  s += mediump ? ", mediump" : ", highp";
  return s;
}

bool parseAccuracyDescription(const std::string& text, AccuracySettings* settings) {
  AccuracySettings a;
  size_t start = 0;
  for (;;) {
    const size_t comma = text.find(',', start);
    const std::string part =
        trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (part == "centre" || part == "origin") {
      a.captureAtOrigin = part == "origin";
    } else if (part == "plain") {
      a.distanceIterations = 0;
    } else if (numberAfter(part, "distance x") > 0) {
      a.distanceIterations = numberAfter(part, "distance x");
    } else if (numberAfter(part, "depth ") >= 0) {
      a.depthBits = numberAfter(part, "depth ");
    } else if (part == "linear" || part == "mipmapped") {
      a.mipmaps = part == "mipmapped";
    } else if (part == "RGBA8" || part == "RGBA16F") {
      a.halfFloat = part == "RGBA16F";
    } else if (part == "highp" || part == "mediump") {
      a.mediump = part == "mediump";
    } else {
      return false;
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  *settings = a;
  return true;
}

}  // namespace reflect
