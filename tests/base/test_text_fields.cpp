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

TEST_CASE("quoted caps a value at 80 characters and escapes control characters") {
  CHECK(quote_field("abc") == "\"abc\"");
  CHECK(quote_field("") == "\"\"");
  CHECK(quote_field("a\"b") == "\"a\\\"b\"");
  CHECK(quote_field("a\tb") == "\"a\\x09b\"");
  const std::string exact(78, '7');
  CHECK(quote_field(exact) == "\"" + exact + "\"");
  const std::string huge(10'000'000, '9');
  const std::string q = quote_field(huge);
  CHECK(q.size() == 80);
  CHECK(q == "\"" + std::string(75, '9') + "...\"");
  // A multi-byte character is never cut in half.
  std::string accents;
  for (int k = 0; k < 60; ++k) accents += "\xC3\xA9";
  const std::string qa = quote_field(accents);
  CHECK(qa.size() <= 80);
  CHECK(qa.substr(qa.size() - 4) == "...\"");
  CHECK((static_cast<unsigned char>(qa[qa.size() - 5]) & 0xC0) != 0xC0);
}

TEST_CASE("strip_bom removes one leading UTF-8 byte-order mark") {
  CHECK(strip_bom("\xEF\xBB\xBFid,x") == "id,x");
  CHECK(strip_bom("id,x") == "id,x");
  CHECK(strip_bom("\xEF\xBB") == "\xEF\xBB");
  CHECK(strip_bom("a\xEF\xBB\xBF") == "a\xEF\xBB\xBF");
  CHECK(has_bom("\xEF\xBB\xBF"));
  CHECK_FALSE(has_bom(""));
}
