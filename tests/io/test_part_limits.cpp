// Part JSON against the ranges of docs/formats.md "Limits": coordinates after
// the inch conversion, weights and their products, knots. Each refusal names
// the file and the field.
#include <doctest/doctest.h>

#include <string>

#include "base/error.hpp"
#include "io/part_file.hpp"

using namespace furrow;

namespace {

std::string patch_json(const std::string& units, const std::string& far_point, const std::string& weights,
                       const std::string& knots_u = "[0, 0, 1, 1]") {
  return R"({"units": ")" + units + R"(", "faces": [{"name": "p", "degree_u": 1, "degree_v": 1,
    "knots_u": )" + knots_u + R"(, "knots_v": [0, 0, 1, 1],
    "control_points": [[[0, 0, 0], [0, 10, 0]], [[10, 0, 0], )" + far_point + R"(]])" +
         (weights.empty() ? "" : R"(, "weights": )" + weights) + "}]}";
}

std::string error_of(const std::string& text) {
  try {
    parse_part_json(text, "part.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("part limits: an ordinary patch is read") {
  CHECK(error_of(patch_json("mm", "[10, 10, 1]", "")).empty());
  CHECK(error_of(patch_json("mm", "[1000, 1000, 1000]", "[[1, 2], [0.5, 1e3]]")).empty());
  CHECK(error_of(patch_json("inch", "[39000, 0, 0]", "")).empty());  // 990.6 m
}

TEST_CASE("part limits: weight 1e308 times a control point of 1000 is refused, naming the weight") {
  const std::string e = error_of(patch_json("mm", "[1000, 1000, 1000]", "[[1e308, 1e308], [1e308, 1e308]]"));
  CHECK(e.rfind("part.json: faces[0].weights[0][0]: 1e+308 is outside the weight range", 0) == 0);
  CHECK(error_of(patch_json("mm", "[1, 1, 1]", "[[1, 1], [1, 1e-300]]"))
            .rfind("part.json: faces[0].weights[1][1]: 1e-300 is outside the weight range", 0) == 0);
  CHECK(error_of(patch_json("mm", "[1, 1, 1]", "[[1e-5, 1], [1, 1e5]]"))
            .rfind("part.json: faces[0].weights[1][1]: weights from 1e-05 to 100000 differ by more than", 0) == 0);
}

TEST_CASE("part limits: coordinates are checked after the inch conversion") {
  CHECK(error_of(patch_json("inch", "[1e307, 0, 0]", "")) ==
        "part.json: faces[0].control_points[1][1] x: not a finite number");
  CHECK(error_of(patch_json("inch", "[40000, 0, 0]", ""))
            .rfind("part.json: faces[0].control_points[1][1] x: 1.016e+06 mm is outside the coordinate range", 0) == 0);
  CHECK(error_of(patch_json("mm", "[0, -2e6, 0]", ""))
            .rfind("part.json: faces[0].control_points[1][1] y: -2e+06 mm is outside", 0) == 0);
}

TEST_CASE("part limits: knots beyond 1e9 and a vanishing domain") {
  CHECK(error_of(patch_json("mm", "[10, 10, 1]", "", "[-1e308, -1e308, 1e308, 1e308]"))
            .rfind("part.json: faces[0].knots_u: knot 0 (-1e+308) is outside", 0) == 0);
  CHECK(error_of(patch_json("mm", "[10, 10, 1]", "", "[0, 0, 1e-300, 1e-300]"))
            .rfind("part.json: faces[0]: the parameter domain is 1e-300 x 1 wide", 0) == 0);
}
