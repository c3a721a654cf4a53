#include <doctest/doctest.h>

#include <random>

#include "base/error.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

const char* kPlan = R"({
  "version": 1,
  "units": "mm",
  "part": "mould.json",
  "probe": {"name": "ruby 2 mm", "diameter": 2},
  "points": [
    {"id": "P1", "order": 2, "face": "mould", "face_index": 0, "region": 3,
     "u": 0.5, "v": 0.25, "xyz": [1, 2, 3], "ijk": [0, 0, 2],
     "approach": [1, 2, 8], "retract": [1, 2, 10]},
    {"id": "P2", "order": 1, "face": "mould", "face_index": 0,
     "u": 0.1, "v": 0.2, "xyz": [4, 5, 6], "ijk": [0, 1, 0],
     "approach": [4, 10, 6], "retract": [4, 12, 6]}
  ]
})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  REQUIRE(pos != std::string::npos);
  return s.replace(pos, from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    parse_plan(text, "plan.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("plan.json: fields, optional region, normalised ijk, inch") {
  const InspectionPlan plan = parse_plan(kPlan, "plan.json");
  CHECK(plan.part == "mould.json");
  CHECK(plan.probe.name == "ruby 2 mm");
  CHECK(plan.probe.radius() == 1);
  REQUIRE(plan.points.size() == 2);
  CHECK(plan.points[0].region == 3);
  CHECK_FALSE(plan.points[1].region.has_value());
  CHECK(plan.points[0].ijk == Eigen::Vector3d(0, 0, 1));
  CHECK(plan.points[0].centre(1) == Eigen::Vector3d(1, 2, 4));
  CHECK(plan.find("P2") == 1u);
  CHECK_FALSE(plan.find("P3").has_value());
  const InspectionPlan inch = parse_plan(replace(kPlan, "\"mm\"", "\"inch\""), "plan.json");
  CHECK(inch.probe.diameter == doctest::Approx(50.8));
  CHECK(inch.points[1].approach == Eigen::Vector3d(4, 10, 6) * 25.4);
  CHECK(inch.points[1].uv == Eigen::Vector2d(0.1, 0.2));  // unit-free
}

TEST_CASE("plan.json round-trips bit for bit") {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> c(-300, 300), unit(0, 1);
  InspectionPlan plan;
  plan.part = "examples/parts/mould.json";
  plan.probe = {"ruby \"3\" mm", 3.0000000000000004};
  for (int k = 0; k < 50; ++k) {
    PlannedPoint p;
    p.id = "R" + std::to_string(k);
    p.order = 50 - k;
    p.face = k % 2 ? "a" : "b";
    p.face_index = k % 2;
    if (k % 3) p.region = k % 7;
    p.uv = {unit(rng), unit(rng)};
    p.xyz = {c(rng), c(rng), c(rng)};
    p.ijk = Eigen::Vector3d(c(rng), c(rng), c(rng)).normalized();
    p.approach = {c(rng), c(rng), c(rng)};
    p.retract = {c(rng), c(rng), c(rng)};
    plan.points.push_back(p);
  }
  const std::string dir = test::scratch_dir("plan-roundtrip");
  write_plan(plan, dir + "/plan.json");
  const InspectionPlan back = read_plan(dir + "/plan.json");
  CHECK(back.part == plan.part);
  CHECK(back.probe.name == plan.probe.name);
  CHECK(back.probe.diameter == plan.probe.diameter);
  REQUIRE(back.points.size() == plan.points.size());
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const PlannedPoint &a = plan.points[k], &b = back.points[k];
    CHECK(a.id == b.id);
    CHECK(a.order == b.order);
    CHECK(a.face == b.face);
    CHECK(a.face_index == b.face_index);
    CHECK(a.region == b.region);
    CHECK(a.uv == b.uv);
    CHECK(a.xyz == b.xyz);
    CHECK(a.ijk == b.ijk);
    CHECK(a.approach == b.approach);
    CHECK(a.retract == b.retract);
  }
  CHECK(plan_to_json_text(back) == plan_to_json_text(plan));
}

TEST_CASE("bad plans: one error naming the file and the field") {
  CHECK(error_of(replace(kPlan, "\"order\": 1", "\"order\": 2")) ==
        "plan.json: points[1].order: duplicate order 2 (also points[0])");
  CHECK(error_of(replace(kPlan, "\"P2\"", "\"P1\"")) ==
        "plan.json: points[1].id: duplicate id \"P1\" (also points[0])");
  CHECK(error_of(replace(kPlan, "\"P2\"", "\"P 2\""))
            .find("plan.json: points[1].id: id \"P 2\" contains") == 0);
  CHECK(error_of(replace(kPlan, "[0, 1, 0]", "[0, 0, 0]")) ==
        "plan.json: points[1].ijk: zero length (a direction is needed)");
  CHECK(error_of(replace(kPlan, "\"diameter\": 2", "\"diameter\": 0"))
            .find("plan.json: probe.diameter") == 0);
  CHECK(error_of(replace(kPlan, "\"version\": 1", "\"version\": 2")) ==
        "plan.json: version: version 2 is not supported (this Furrow reads version 1)");
  CHECK(error_of(replace(kPlan, "\"u\": 0.1, ", "")) == "plan.json: points[1].u: missing");
  CHECK(error_of(replace(kPlan, "\"region\": 3", "\"region\": -1")) ==
        "plan.json: points[0].region: must not be negative");
  CHECK(error_of(replace(kPlan, "\"order\": 1", "\"order\": 0")) ==
        "plan.json: points[1].order: must be at least 1");
}

TEST_CASE("a plan is checked against the part it is used with") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  InspectionPlan plan = parse_plan(kPlan, "plan.json");
  for (PlannedPoint& p : plan.points) p.xyz = part.faces[0].surface().point(p.uv.x(), p.uv.y());
  CHECK_NOTHROW(check_plan_against_part(plan, part, "plan.json"));
  plan.points[1].face = "dome";
  CHECK_THROWS_WITH_AS(
      check_plan_against_part(plan, part, "plan.json"),
      "plan.json: points[1] (id P2): face \"dome\" but face 0 of the part is \"mould\"",
      InputError);
  plan.points[1].face = "mould";
  plan.points[1].face_index = 1;
  CHECK_THROWS_WITH_AS(check_plan_against_part(plan, part, "plan.json"),
                       "plan.json: points[1] (id P2): face_index 1 but the part has 1 faces",
                       InputError);
  plan.points[1].face_index = 0;
  plan.points[1].xyz.z() += 0.01;
  CHECK_THROWS_WITH_AS(check_plan_against_part(plan, part, "plan.json"),
                       doctest::Contains("the plan was made for another part"), InputError);
}
