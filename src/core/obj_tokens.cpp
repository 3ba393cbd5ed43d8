#include "core/obj_tokens.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace reflect {
namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// strtof on a token (which is not terminated): the whole token must be the number.
bool strtofWhole(std::string_view token, float* out) {
  char buffer[64];
  std::string copy;
  const char* text = buffer;
  if (token.size() < sizeof buffer) {
    std::copy(token.begin(), token.end(), buffer);
    buffer[token.size()] = '\0';
  } else {
    copy.assign(token);
    text = copy.c_str();
  }
  char* end = nullptr;
  const float value = std::strtof(text, &end);
  if (end != text + token.size()) return false;
  *out = value;
  return true;
}

// The significant digits of a plain decimal, as long as they fit a float exactly.
struct Decimal {
  static constexpr int kMaxDigits = 7;  // every integer under 10^7 is an exact float
  uint32_t mantissa = 0;
  int digits = 0;  // significant digits (leading zeros do not count)
  bool any = false;

  // Appends the digits from token[*i] on, up to the first that is not one. Returns how many it
  // appended, or -1 (with *i at that digit) once there are more than kMaxDigits significant ones.
  int append(std::string_view token, size_t* i) {
    int appended = 0;
    for (; *i < token.size() && isDigit(token[*i]); ++*i) {
      any = true;
      if (mantissa != 0 || token[*i] != '0') ++digits;
      if (digits > kMaxDigits) return -1;
      mantissa = mantissa * 10 + static_cast<uint32_t>(token[*i] - '0');
      ++appended;
    }
    return appended;
  }
};

// The exponent after 'e' or 'E' at token[i]: a sign and one to three digits ending the token.
// False when it is anything else (strtof then decides).
bool readShortExponent(std::string_view token, size_t i, int* exponent) {
  size_t j = i + 1;
  bool negative = false;
  if (j < token.size() && (token[j] == '-' || token[j] == '+')) negative = token[j++] == '-';
  const size_t first = j;
  int value = 0;
  for (; j < token.size() && isDigit(token[j]) && j - first < 3; ++j) {
    value = value * 10 + (token[j] - '0');
  }
  if (j == first || j != token.size()) return false;
  *exponent = negative ? -value : value;
  return true;
}

// Plain decimals of up to 7 significant digits and small exponents (almost every number in an
// OBJ file), read directly: the digits and the power of ten are both exact floats there, so one
// division or multiplication is correctly rounded, as strtof is. False for everything else.
bool parseShortDecimal(std::string_view token, float* out) {
  static constexpr float kPowers[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                      1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
  size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '-' || token[i] == '+')) negative = token[i++] == '-';
  Decimal decimal;
  if (decimal.append(token, &i) < 0) return false;
  int scale = 0;  // digits after the point
  if (i < token.size() && token[i] == '.') {
    ++i;
    scale = decimal.append(token, &i);
    if (scale < 0) return false;
  }
  if (!decimal.any) return false;
  int exponent = 0;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    if (!readShortExponent(token, i, &exponent)) return false;
    i = token.size();
  }
  const int power = exponent - scale;
  if (i != token.size() || power < -10 || power > 10) return false;
  float value = static_cast<float>(decimal.mantissa);  // exact: under 2^24
  value = power < 0 ? value / kPowers[-power] : value * kPowers[power];
  *out = negative ? -value : value;
  return true;
}

}  // namespace

bool parseObjFloat(std::string_view token, float* out) {
  if (parseShortDecimal(token, out)) return true;
  float value = 0.0f;
  if (!strtofWhole(token, &value) || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

bool parseObjIndex(std::string_view token, long* out) {
  size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '-' || token[i] == '+')) negative = token[i++] == '-';
  if (i == token.size()) return false;
  unsigned long magnitude = 0;
  bool saturated = false;
  for (; i < token.size(); ++i) {
    if (!isDigit(token[i])) return false;
    const unsigned long digit = static_cast<unsigned long>(token[i] - '0');
    if (magnitude > (static_cast<unsigned long>(LONG_MAX) + 1 - digit) / 10) saturated = true;
    if (!saturated) magnitude = magnitude * 10 + digit;
  }
  if (negative) {
    *out = saturated || magnitude > static_cast<unsigned long>(LONG_MAX) + 1
               ? LONG_MIN
               : static_cast<long>(0 - magnitude);
  } else {
    *out = saturated || magnitude > static_cast<unsigned long>(LONG_MAX)
               ? LONG_MAX
               : static_cast<long>(magnitude);
  }
  return true;
}

}  // namespace reflect
