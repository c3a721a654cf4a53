// Number text against iostreams (a second implementation of the same
// printf conversions) and std::from_chars (shortest must read back).
#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "base/number_text.hpp"

using namespace furrow;

namespace {

std::vector<double> values() {
  return {0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 1.0 / 3, 2.5, -2.5, 123.4567891234, -9.99951, 0.00049, -0.00049,
          1e-5, 1e15, 1e16, 1e308, -1e308, 1e-300, -1e-300, 4.9e-324, std::numeric_limits<double>::max(),
          std::numeric_limits<double>::min(), 25.4, 0.0005, -0.0005};
}

std::string stream_fixed(double v, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

std::string stream_general(double v, int digits) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

// True when the text is a sign followed by zeros and at most one point.
bool signed_zero(const std::string& s) {
  return !s.empty() && (s[0] == '-' || s[0] == '+') && s.find_first_not_of("0.", 1) == std::string::npos;
}

}  // namespace

TEST_CASE("shortest reads back to the very same double, negative zero included") {
  for (double v : values()) {
    const std::string text = shortest(v);
    double back = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), back);
    CAPTURE(text);
    REQUIRE(r.ec == std::errc());
    CHECK(r.ptr == text.data() + text.size());
    CHECK(std::signbit(back) == std::signbit(v));
    CHECK(back == v);
  }
  CHECK(shortest(0.1) == "0.1");
  CHECK(shortest(-0.0) == "-0");
}

TEST_CASE("fixed and general print what iostreams print, and zero never carries a sign") {
  for (double v : values())
    for (int d : {0, 1, 3, 6}) {
      CAPTURE(v);
      CAPTURE(d);
      const std::string f = stream_fixed(v, d);
      CHECK(fixed(v, d) == (signed_zero(f) ? f.substr(1) : f));
      const std::string g = stream_general(v, d == 0 ? 1 : d);
      CHECK(general(v, d == 0 ? 1 : d) == (signed_zero(g) ? g.substr(1) : g));
    }
  CHECK(fixed(-0.0004, 3) == "0.000");
  CHECK(general(-0.0) == "0");
  CHECK(fixed(1e308, 1).size() == 311);  // 309 digits, the point and one decimal: nothing cut
}

TEST_CASE("signed_fixed puts the sign on every non-zero text and none on zero") {
  for (double v : values()) {
    const std::string f = stream_fixed(v, 1);
    const std::string magnitude = f[0] == '-' ? f.substr(1) : f;
    const std::string expected = magnitude == "0.0" ? magnitude : v > 0 ? "+" + f : f;
    CAPTURE(v);
    CHECK(signed_fixed(v, 1) == expected);
  }
  CHECK(signed_fixed(0.04, 1) == "0.0");
  CHECK(signed_fixed(-0.04, 1) == "0.0");
  CHECK(signed_fixed(118.44, 1) == "+118.4");
  CHECK(signed_fixed(-118.44, 1) == "-118.4");
}
