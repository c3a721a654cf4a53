#include <doctest/doctest.h>

#include "base/text_fields.hpp"

using namespace furrow;

TEST_CASE("parse_finite accepts exactly one finite number") {
  double x = 0;
  CHECK(parse_finite("1.5", x));
  CHECK(x == 1.5);
  CHECK(parse_finite("-2e-3", x));
  CHECK(x == -0.002);
  for (const char* bad : {"", " ", "1.5 ", " 1.5", "1.5x", "nan", "inf", "1e999", "--1", "0x"}) {
    CAPTURE(std::string(bad));
    CHECK_FALSE(parse_finite(bad, x));
  }
}

TEST_CASE("lower-case helpers") {
  CHECK(to_lower("AbC.StP") == "abc.stp");
  CHECK(lower_extension("/a/b/Part.STEP") == ".step");
  CHECK(lower_extension("noext") == "");
}

TEST_CASE("trim removes blanks at both ends only") {
  CHECK(trim("  id 7\t\r\n") == "id 7");
  CHECK(trim("x") == "x");
  CHECK(trim(" \t\r\n") == "");
  CHECK(trim("") == "");
  CHECK(trim("a  b") == "a  b");
}
