// The JSON cursor: paths in every error, the three kinds of member, and
// unknown members refused.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "base/error.hpp"
#include "base/json_cursor.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

template <class F>
std::string error_of(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

const json kDoc = json::parse(R"({"a": 1.5, "n": -2, "s": "text", "z": null, "o": {"b": [1, 2, 3]},
                                  "big": 1e308, "list": [1, "x"]})");

}  // namespace

TEST_CASE("a cursor names the member in every error, from the document root down") {
  const JsonCursor root(kDoc, "f.json:");
  CHECK(root.path("a") == "f.json: a");
  CHECK(root.at("o").path("b") == "f.json: o.b");
  CHECK(root.number("a") == 1.5);
  CHECK(root.at("o").vector3("b") == Eigen::Vector3d(1, 2, 3));
  CHECK(error_of([&] { root.number("missing"); }) == "f.json: missing: missing");
  CHECK(error_of([&] { root.number("s"); }) == "f.json: s: expected a number, found a string");
  CHECK(error_of([&] { root.positive("n"); }).find("f.json: n:") == 0);
  CHECK(error_of([&] { root.count("n"); }) == "f.json: n: must not be negative, got -2");
  CHECK(error_of([&] { root.integer("n", 0); }) == "f.json: n: must be at least 0, got -2");
  CHECK(error_of([&] { root.at("a"); }) == "f.json: a: expected an object, found a number");
  CHECK(error_of([&] { root.at("o").vector2("b"); }).find("f.json: o.b") == 0);
  CHECK(error_of([] { JsonCursor(json::array(), "g.json:"); }) == "g.json: expected an object, found an array");
}

TEST_CASE("required, nullable and optional members: absent and null are told apart") {
  const JsonCursor root(kDoc, "f.json:");
  // nullable: present, null is none; absent is an error
  CHECK(!root.nullable_number("z"));
  CHECK(*root.nullable_number("a") == 1.5);
  CHECK(root.nullable_string("z").empty());
  CHECK(error_of([&] { root.nullable_number("missing"); }) == "f.json: missing: missing");
  // optional: absent or null is none; a present value is still checked
  CHECK(!root.optional_number("missing"));
  CHECK(!root.optional_number("z"));
  CHECK(!root.optional_at("z"));
  CHECK(*root.optional_string("s") == "text");
  CHECK(error_of([&] { root.optional_number("s"); }) == "f.json: s: expected a number, found a string");
  // setters keep the default when absent or null
  double d = 7;
  root.positive("missing", d);
  root.positive("z", d);
  CHECK(d == 7);
  root.positive("a", d);
  CHECK(d == 1.5);
  int i = 3;
  CHECK(error_of([&] { root.integer("n", i, 0); }) == "f.json: n: must be at least 0, got -2");
  CHECK(i == 3);
}

TEST_CASE("finish refuses the first member never read, only refuses before reading") {
  const json doc = json::parse(R"({"name": "x", "densty": 2, "zz": 1})");
  {
    const JsonCursor c(doc, "job.json:");
    c.string("name");
    CHECK(error_of([&] { c.finish("docs/formats.md \"Job file\""); }) ==
          "job.json: densty: unknown member (see docs/formats.md \"Job file\")");
    c.optional_number("densty");  // read (even as optional): known
    c.skip("zz");
    CHECK(error_of([&] { c.finish("x"); }) == "(accepted)");
  }
  {
    const JsonCursor c(doc, "head.json");
    CHECK(error_of([&] { c.only({"name", "density", "zz"}, "the manual"); }) ==
          "head.json.densty: unknown member (see the manual)");
    CHECK(error_of([&] { c.only({"name", "densty", "zz"}, "the manual"); }) == "(accepted)");
  }
}
