#include "base/number_text.hpp"

#include <charconv>
#include <cstdio>

namespace furrow {

namespace {

// "-0.000" / "+0.000" -> "0.000": only the sign, zeros and the point.
std::string unsigned_zero(std::string s) {
  if (!s.empty() && (s[0] == '-' || s[0] == '+') && s.find_first_not_of("0.", 1) == std::string::npos)
    s.erase(0, 1);
  return s;
}

}  // namespace

std::string shortest(double value) {
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

std::string general(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return unsigned_zero(buf);
}

std::string fixed(double value, int decimals) {
  char buf[400];  // "%f" of 1e308 has 309 digits before the point
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return unsigned_zero(buf);
}

std::string signed_fixed(double value, int decimals) {
  char buf[400];
  std::snprintf(buf, sizeof buf, "%+.*f", decimals, value);
  return unsigned_zero(buf);
}

}  // namespace furrow
