// Regions merged across faces (partition/region_groups.hpp) on parts whose
// answer is known by construction: faces that continue one another
// tangentially with one class are one group; a crease steeper than the
// angle limit, or a change of class, keeps them apart. The groups survive
// regions.json, and a file whose groups contradict its regions is refused.
#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "partition/partition.hpp"
#include "partition/region_groups.hpp"
#include "partition/regions_file.hpp"

using namespace furrow;

namespace {

constexpr double kPi = 3.141592653589793;

RegionMap partitioned(const Part& part) {
  PartitionOptions o;
  o.grid = GridSize{40, 40};
  return partition_part(part, o).map;
}

// Two 50 x 40 planes meeting along x = 50 with a crease of `degrees`.
Part creased(double degrees) {
  const double a = degrees * kPi / 180;
  Part part;
  part.faces.emplace_back("left", make_plane({0, 0, 0}, {50, 0, 0}, {0, 40, 0}));
  part.faces.emplace_back("right", make_plane({50, 0, 0}, {50 * std::cos(a), 0, 50 * std::sin(a)}, {0, 40, 0}));
  return part;
}

}  // namespace

TEST_CASE("region groups: a tube split into two half faces is one convex group") {
  Part part;
  part.faces.emplace_back("front half", make_cylinder(20, 50, 0, kPi), Trim{}, true);
  part.faces.emplace_back("back half", make_cylinder(20, 50, kPi, 2 * kPi), Trim{}, true);
  const RegionMap map = partitioned(part);
  REQUIRE(map.regions.size() == 2);
  REQUIRE(map.groups.size() == 1);
  CHECK(map.groups[0].curvature_class == CurvatureClass::convex);
  CHECK(map.groups[0].regions == std::vector<int>{0, 1});
  CHECK(map.groups[0].faces == std::vector<int>{0, 1});
  CHECK(map.groups[0].area == doctest::Approx(map.regions[0].area + map.regions[1].area).epsilon(1e-12));
  // The analytic area of the whole tube, to the partition's midpoint rule.
  CHECK(map.groups[0].area == doctest::Approx(2 * kPi * 20 * 50).epsilon(1e-3));
}

TEST_CASE("region groups: a crease joins two planes below the angle limit and parts them above it") {
  // The limit is 1 degree between the normals, which here is the crease angle.
  for (const auto& [degrees, joined] : {std::pair{0.0, true}, {0.5, true}, {2.0, false}, {90.0, false}}) {
    CAPTURE(degrees);
    const RegionMap map = partitioned(creased(degrees));
    REQUIRE(map.regions.size() == 2);
    CHECK(map.regions[0].curvature_class == CurvatureClass::planar);
    CHECK(map.regions[1].curvature_class == CurvatureClass::planar);
    CHECK(map.groups.size() == (joined ? 1u : 2u));
    CHECK((map.regions[0].group == map.regions[1].group) == joined);
  }
}

TEST_CASE("region groups: a tangent join between classes keeps them apart, a gap wider than the tolerance too") {
  // A quarter tube (convex) running tangentially into a plane at its top line.
  Part part;
  part.faces.emplace_back("quarter", make_cylinder(20, 50, 0, kPi / 2), Trim{}, true);
  part.faces.emplace_back("flat", make_plane({-50, 0, 20}, {50, 0, 0}, {0, 50, 0}));
  const RegionMap map = partitioned(part);
  REQUIRE(map.regions.size() == 2);
  CHECK(map.regions[0].curvature_class == CurvatureClass::convex);
  CHECK(map.regions[1].curvature_class == CurvatureClass::planar);
  CHECK(map.groups.size() == 2);

  // Coplanar planes 0.1 mm apart (beyond the 0.01 mm gap): not one surface.
  Part apart;
  apart.faces.emplace_back("left", make_plane({0, 0, 0}, {50, 0, 0}, {0, 40, 0}));
  apart.faces.emplace_back("right", make_plane({50.1, 0, 0}, {50, 0, 0}, {0, 40, 0}));
  CHECK(partitioned(apart).groups.size() == 2);
}

TEST_CASE("region groups: options are checked, the groups survive regions.json, a contradiction is refused") {
  PartitionOptions o;
  o.grid = GridSize{40, 40};
  PartitionResult result = partition_part(creased(0.5), o);
  RegionGroupOptions bad;
  bad.gap = std::nan("");
  CHECK_THROWS_AS(group_regions_across_faces(creased(0.5), result, bad), InputError);
  bad = RegionGroupOptions{};
  bad.min_tangent_fraction = 1.5;
  CHECK_THROWS_AS(group_regions_across_faces(creased(0.5), result, bad), InputError);

  const std::string text = regions_to_json_text(result.map);
  const RegionMap back = parse_regions_json(text, "r.json");
  REQUIRE(back.groups.size() == 1);
  CHECK(back.groups[0].regions == std::vector<int>{0, 1});
  CHECK(regions_to_json_text(back) == text);

  nlohmann::json doc = nlohmann::json::parse(text);
  doc["regions"][1]["group"] = 1;  // the list still says one group
  CHECK_THROWS_WITH_AS(parse_regions_json(doc.dump(), "r.json"), doctest::Contains("r.json: groups"), InputError);
  doc["groups"] = nlohmann::json::array();
  doc["regions"][1]["group"] = 7;
  CHECK_THROWS_WITH_AS(parse_regions_json(doc.dump(), "r.json"), doctest::Contains("regions[1].group"), InputError);
  // A file from before groups: every region alone.
  doc.erase("groups");
  for (auto& r : doc["regions"]) r.erase("group");
  const RegionMap old = parse_regions_json(doc.dump(), "r.json");
  CHECK(old.groups.size() == 2);
}
