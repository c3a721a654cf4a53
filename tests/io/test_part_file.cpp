#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "support/random_surface.hpp"

using namespace furrow;

namespace {

const char* kSimplePart = R"({
  "units": "mm",
  "faces": [{
    "name": "plate",
    "degree_u": 1, "degree_v": 1,
    "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1],
    "control_points": [[[0, 0, 0], [0, 10, 0]], [[20, 0, 0], [20, 10, 1]]]
  }]
})";

std::string error_of(const std::string& text) {
  try {
    parse_part_json(text, "part.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  REQUIRE(pos != std::string::npos);
  return s.replace(pos, from.size(), to);
}

void require_identical(const Part& a, const Part& b) {
  REQUIRE(a.faces.size() == b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    const NurbsSurface& s = a.faces[f].surface();
    const NurbsSurface& t = b.faces[f].surface();
    CHECK(a.faces[f].name() == b.faces[f].name());
    CHECK(a.faces[f].reversed() == b.faces[f].reversed());
    CHECK(s.knots_u() == t.knots_u());
    CHECK(s.knots_v() == t.knots_v());
    REQUIRE(s.num_u() == t.num_u());
    REQUIRE(s.num_v() == t.num_v());
    for (int i = 0; i < s.num_u(); ++i)
      for (int j = 0; j < s.num_v(); ++j) {
        CHECK(s.control_point(i, j) == t.control_point(i, j));  // bit-exact
        CHECK(s.weight(i, j) == t.weight(i, j));
      }
    REQUIRE(a.faces[f].trim().loops().size() == b.faces[f].trim().loops().size());
    for (std::size_t l = 0; l < a.faces[f].trim().loops().size(); ++l)
      CHECK(a.faces[f].trim().loops()[l] == b.faces[f].trim().loops()[l]);
  }
}

}  // namespace

TEST_CASE("part JSON round-trips bit for bit: random rational surfaces, trims, reversed faces") {
  std::mt19937 rng(17);
  Part part;
  for (int k = 0; k < 6; ++k) {
    NurbsSurface s = test::random_surface(rng, 1 + k % 4, 2 + k % 3, k % 2 == 0, true);
    Trim trim;
    if (k == 2) {
      const auto& d = s.domain();
      const double u0 = d.u0 + 0.1 * d.width_u(), u1 = d.u1 - 0.1 * d.width_u();
      const double v0 = d.v0 + 0.1 * d.width_v(), v1 = d.v1 - 0.1 * d.width_v();
      trim = Trim({{{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}});
    }
    part.faces.emplace_back("face " + std::to_string(k), std::move(s), trim, k == 3);
  }
  const std::string text = part_to_json_text(part);
  const Part back = parse_part_json(text, "roundtrip.json");
  require_identical(part, back);
  CHECK(part_to_json_text(back) == text);  // and the text is a fixed point
}

TEST_CASE("inch parts are converted to millimetres at the boundary") {
  const Part mm = parse_part_json(kSimplePart, "mm.json");
  const Part inch = parse_part_json(replace(kSimplePart, "\"mm\"", "\"inch\""), "inch.json");
  CHECK(inch.source_units == "inch");
  CHECK(inch.faces[0].surface().control_point(1, 1) ==
        Eigen::Vector3d(20 * 25.4, 10 * 25.4, 1 * 25.4));
  CHECK(mm.faces[0].surface().control_point(1, 1) == Eigen::Vector3d(20, 10, 1));
}

TEST_CASE("bad part files give one clear error naming the file and the field") {
  CHECK(error_of(kSimplePart).empty());
  CHECK(error_of("").find("part.json: the file is empty") == 0);
  CHECK(error_of("{\"units\": \"mm\",\n \"faces\": [}").find("part.json: line 2") == 0);
  CHECK(error_of("[1, 2]").find("part.json: expected an object") == 0);
  CHECK(error_of(replace(kSimplePart, "\"units\": \"mm\",", "")) == "part.json: units: missing");
  CHECK(error_of(replace(kSimplePart, "\"mm\"", "\"furlong\"")).find("part.json: units: unknown units") == 0);
  CHECK(error_of(replace(kSimplePart, "\"knots_u\": [0, 0, 1, 1], ", "")) ==
        "part.json: faces[0].knots_u: missing");
  CHECK(error_of(replace(kSimplePart, "\"knots_u\": [0, 0, 1, 1]", "\"knots_u\": [0, 0, 1]"))
            .find("part.json: faces[0].knots_u: expected 4 knots") == 0);
  CHECK(error_of(replace(kSimplePart, "[20, 10, 1]", "[20, NaN, 1]")).find("part.json: line") == 0);
  CHECK(error_of(replace(kSimplePart, "[20, 10, 1]", "[20, \"x\", 1]")) ==
        "part.json: faces[0].control_points[1][1][1]: expected a number, found a string");
  CHECK(error_of(replace(kSimplePart, "[20, 10, 1]", "[20, 1e999, 1]")).find("part.json:") == 0);
  CHECK(error_of(replace(kSimplePart, "\"degree_v\": 1,", "\"degree_v\": 1, \"weights\": [[1, 1], [1, -2]],"))
            .find("part.json: faces[0].weights[1][1]: -2 is not a positive") == 0);
  CHECK(error_of("{\"units\": \"mm\", \"faces\": []}") == "part.json: faces: the part has no faces");
  CHECK(error_of(replace(kSimplePart, "\"degree_u\": 1", "\"degree_u\": 1.5")) ==
        "part.json: faces[0].degree_u: expected an integer, got 1.5");
  CHECK(error_of(replace(kSimplePart, "\"name\": \"plate\",", ""))  == "part.json: faces[0].name: missing");
}

TEST_CASE("reading a missing file or a folder names the path") {
  CHECK_THROWS_WITH_AS(read_part("/nonexistent/part.json"),
                       doctest::Contains("/nonexistent/part.json: cannot open"), InputError);
  CHECK_THROWS_WITH_AS(read_part(std::filesystem::temp_directory_path().string()),
                       doctest::Contains("is a folder"), InputError);
}

TEST_CASE("the bundled example parts load and are what their names say") {
  const std::string dir = std::string(FURROW_SOURCE_DIR) + "/examples/parts/";
  for (const char* name : {"quarter_cylinder.json", "semi_cylinder.json", "mould.json", "two_face.json"}) {
    CAPTURE(name);
    const Part part = read_part(dir + name);
    CHECK_FALSE(part.faces.empty());
  }
  const Part semi = read_part(dir + "semi_cylinder.json");
  for (double u : {0.0, 0.3, 0.5, 1.0}) {
    const DifferentialGeometry g = semi.faces[0].geometry(u, 0.5);
    CHECK(std::hypot(g.point.x(), g.point.z()) == doctest::Approx(25.4).epsilon(1e-12));
    CHECK(g.k2 == doctest::Approx(-1 / 25.4).epsilon(1e-9));  // convex: outward normal
  }
  const Part mould = read_part(dir + "mould.json");
  const auto box = mould.control_box();
  CHECK(box.sizes().x() == doctest::Approx(100.0));
  CHECK(box.sizes().y() == doctest::Approx(80.0));
  CHECK(read_part(dir + "two_face.json").faces.size() == 2);
}
