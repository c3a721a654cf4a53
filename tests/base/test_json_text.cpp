#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "base/json_fields.hpp"
#include "base/json_text.hpp"
#include "support/json_layout_oracle.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

// Strings a file can carry: empty, markup, escapes, every control
// character, UTF-8 of two, three and four bytes, DEL.
std::vector<std::string> hostile_strings() {
  std::vector<std::string> s = {"", "\"", "\\", "a\"b\\c", "/", "tab\there", "line\nbreak\r\n", "\x7f",
                                "Ma\xc3\x9f", "\xe2\x82\xac 5", "\xf0\x9f\x94\xa7", "P-1,2;3", std::string(300, 'x')};
  std::string controls;
  for (int c = 0; c < 0x20; ++c) controls += static_cast<char>(c);
  s.push_back(controls);
  s.push_back(std::string("nul\0inside", 10));
  return s;
}

std::vector<double> hostile_numbers() {
  return {0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3, 1e308, -1e308, 1e-300, 4.9e-324,
          std::numeric_limits<double>::max(), std::numeric_limits<double>::min(), 1e-5, 0.0001, 1e15, 1e16,
          123456789012345680000.0, 1e21, 2.5e-7, 0.30000000000000004, 12345.678};
}

json hostile_tree() {
  json d;
  json strings = json::array();
  for (const std::string& s : hostile_strings()) strings.push_back(s);
  d["strings"] = strings;
  json numbers = json::array();
  for (double x : hostile_numbers()) numbers.push_back(x);
  d["numbers"] = numbers;  // longer than 100 characters: one per line
  d["short"] = json::array({1.0, -0.0, 1e-300});
  d["ints"] = {{"negative", -7}, {"unsigned", std::size_t{18446744073709551615u}}, {"zero", 0}};
  d["empty_object"] = json::object();
  d["empty_array"] = json::array();
  d["empty_string"] = "";
  d["null"] = nullptr;
  d["flags"] = json::array({true, false});
  d["inline_objects"] = json::array({{{"a", 1}}, {{"b", json::array({1.5})}}});  // short: one line
  d["nested"] = json::array({json::array({1, 2}), json::object({{"k\"ey", std::string(120, 'y')}})});
  for (const std::string& s : hostile_strings()) d["keys"][s] = s.size();
  d["exactly_100"] = json::array({std::string(96, 'z')});  // 2 + 2 + 96: still inline
  d["exactly_101"] = json::array({std::string(97, 'z')});
  return d;
}

}  // namespace

TEST_CASE("json text: the layout of to_text equals the dump-per-level oracle on hostile values") {
  const json d = hostile_tree();
  const std::string text = json_fields::to_text(d);
  CHECK(text == test::oracle_text(d));
  CHECK(json::parse(text) == d);
  CHECK(text.find("\"exactly_100\": [\"" + std::string(96, 'z') + "\"]") != std::string::npos);
  CHECK(text.find("\"exactly_101\": [\n") != std::string::npos);
}

TEST_CASE("json text: numbers are nlohmann's text, byte for byte, and read back exactly") {
  for (double x : hostile_numbers()) {
    CAPTURE(x);
    std::string out;
    json_text::append_number(out, x, "x");
    CHECK(out == json(x).dump());
    CHECK(std::signbit(json::parse(out).get<double>()) == std::signbit(x));
    CHECK(json::parse(out).get<double>() == x);
  }
  std::string out;
  json_text::append_number(out, -0.0, "x");
  CHECK(out == "-0.0");
  CHECK_THROWS_AS(json_text::append_number(out, std::nan(""), "x"), std::logic_error);
  CHECK_THROWS_AS(json_text::append_number(out, HUGE_VAL, "x"), std::logic_error);
}

TEST_CASE("json text: strings are escaped as dump() escapes them, and invalid UTF-8 throws as dump() does") {
  for (const std::string& s : hostile_strings()) {
    std::string out;
    json_text::append_string(out, s);
    CHECK(out == json(s).dump());
    CHECK(json::parse(out).get<std::string>() == s);
  }
  std::string out;
  CHECK_THROWS_AS(json_text::append_string(out, "bad \xff byte"), json::type_error);
  CHECK_THROWS_AS((void)json(std::string("bad \xff byte")).dump(), json::type_error);
}

TEST_CASE("json text: a streamed document equals the tree's text") {
  // The tree first, then the same members written front to back, keys in
  // the tree's order, one array of big objects streamed.
  json tree = hostile_tree();
  json rows = json::array();
  for (int i = 0; i < 3; ++i) {
    json r;
    r["id"] = hostile_strings()[static_cast<std::size_t>(i) + 1];
    r["at"] = json::array({1e308 * (i - 1), 1e-300, -0.0});
    r["uv"] = json::array({0.5, 0.25});
    r["none"] = nullptr;
    r["n"] = i;
    r["ok"] = i % 2 == 0;
    r["sub"] = {{"x", 1.0}, {"y", json::array({-0.0})}};
    rows.push_back(r);
  }
  tree["rows"] = rows;
  tree["zz_empty_rows"] = json::array();

  std::string out;
  json_text::Writer w(out);
  w.begin_object();
  for (auto it = tree.begin(); it != tree.end(); ++it) {
    w.key(it.key());
    if (it.key() == "rows") {
      w.begin_array();
      for (int i = 0; i < 3; ++i) {
        w.begin_object();
        w.key("at");
        w.vector(Eigen::Vector3d(1e308 * (i - 1), 1e-300, -0.0));
        w.key("id");
        w.string(hostile_strings()[static_cast<std::size_t>(i) + 1]);
        w.key("n");
        w.integer(i);
        w.key("none");
        w.null();
        w.key("ok");
        w.boolean(i % 2 == 0);
        w.key("sub");
        w.value(json{{"x", 1.0}, {"y", json::array({-0.0})}});
        w.key("uv");
        w.vector(Eigen::Vector2d(0.5, 0.25));
        w.end_object();
      }
      w.end_array();
    } else if (it.key() == "zz_empty_rows") {
      w.begin_array();
      w.end_array();
    } else {
      w.value(*it);
    }
  }
  w.end_object();
  w.finish();
  CHECK(out == test::oracle_text(tree));
  CHECK(json::parse(out) == tree);
}

TEST_CASE("json text: the writer refuses a member without a key and an unfinished document") {
  std::string out;
  json_text::Writer w(out);
  w.begin_object();
  CHECK_THROWS_AS(w.number(1, "x"), std::logic_error);
  CHECK_THROWS_AS(w.finish(), std::logic_error);
  json_text::Writer a(out);
  a.begin_array();
  CHECK_THROWS_AS(a.key("k"), std::logic_error);
  CHECK_THROWS_AS(a.vector(Eigen::Vector3d(0, std::nan(""), 0)), std::logic_error);
}
