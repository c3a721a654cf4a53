#include "io/qif/xs_decimal.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace furrow {

namespace {

// The fixed text of v rounded to `places` decimals (to_chars rounds the
// binary value correctly), trailing zeros and a bare point dropped.
void append_rounded(std::string& out, double v, int places) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, places);
  if (r.ec != std::errc()) throw std::invalid_argument("xs:decimal: no room for the rounded text");
  const char* end = r.ptr;
  while (end[-1] == '0') --end;
  if (end[-1] == '.') --end;
  out.append(buf, static_cast<std::size_t>(end - buf));
}

}  // namespace

void append_xs_decimal(std::string& out, double v, int max_digits) {
  if (!std::isfinite(v)) throw std::invalid_argument("xs:decimal: a non-finite number");
  // The shortest round-trip digits, always as d[.ddd]e±X: one form to take apart.
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  const char* p = buf;
  const bool negative = *p == '-';
  if (negative) ++p;
  std::string digits;
  for (; p < r.ptr && *p != 'e'; ++p)
    if (*p != '.') digits += *p;
  // The exponent of the first digit (to_chars does not terminate its text,
  // so from_chars reads it up to r.ptr).
  const char* e = p + 1;
  if (e < r.ptr && *e == '+') ++e;
  long exp = 0;
  std::from_chars(e, r.ptr, exp);
  const long n = static_cast<long>(digits.size());
  if (max_digits > 0) {
    const long needed = exp < 0 ? -exp - 1 + n : std::max(n, exp + 1);
    if (needed > max_digits) {
      if (exp >= max_digits)
        throw std::invalid_argument("xs:decimal: " + std::string(buf, r.ptr) + " needs more than " +
                                    std::to_string(max_digits) + " digits");
      append_rounded(out, v, max_digits);
      return;
    }
  }
  if (negative) out += '-';
  if (exp < 0) {
    out += "0.";
    out.append(static_cast<std::size_t>(-exp - 1), '0');
    out += digits;
  } else if (exp + 1 >= n) {
    out += digits;
    out.append(static_cast<std::size_t>(exp + 1 - n), '0');
  } else {
    out.append(digits, 0, static_cast<std::size_t>(exp + 1));
    out += '.';
    out.append(digits, static_cast<std::size_t>(exp + 1), std::string::npos);
  }
}

std::string xs_decimal_text(double v, int max_digits) {
  std::string out;
  append_xs_decimal(out, v, max_digits);
  return out;
}

}  // namespace furrow
