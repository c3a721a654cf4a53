// regions.json: exact round trip, errors naming the field, and refusing a
// regions file that belongs to another part.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "partition/part_fingerprint.hpp"
#include "partition/partition.hpp"
#include "partition/regions_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
using nlohmann::json;

namespace {

const RegionMap& mould_map() {
  static const RegionMap map = [] {
    PartitionOptions o;
    o.grid = GridSize{200, 160};
    return partition_part(read_part(source_path("examples/parts/mould.json")), o).map;
  }();
  return map;
}

std::string error_of(const std::string& text) {
  try {
    parse_regions_json(text, "r.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("regions.json round trip: same bytes, same numbers, same region_at") {
  const RegionMap& map = mould_map();
  const std::string text = regions_to_json_text(map);
  const RegionMap back = parse_regions_json(text, "regions.json");
  CHECK(regions_to_json_text(back) == text);
  REQUIRE(back.regions.size() == map.regions.size());
  for (std::size_t r = 0; r < map.regions.size(); ++r) {
    const Region &a = map.regions[r], &b = back.regions[r];
    CHECK(a.area == b.area);  // bit for bit
    CHECK(a.K.mean == b.K.mean);
    CHECK(a.border.size() == b.border.size());
    CHECK(a.border[0].uv == b.border[0].uv);
    CHECK(a.border[0].xyz == b.border[0].xyz);
  }
  // region_at from the file agrees with the computed map on a dense probe.
  int differ = 0;
  for (int i = 0; i <= 97; ++i)
    for (int j = 0; j <= 89; ++j) {
      const double u = (i + 0.37) / 98.5, v = (j + 0.61) / 90.7;
      differ += map.region_at(0, u, v) != back.region_at(0, u, v);
    }
  CHECK(differ == 0);
  CHECK(!back.region_at(0, 1.5, 0.5).has_value());  // outside the domain
  CHECK(!back.region_at(3, 0.5, 0.5).has_value());  // no such face
  // Through the file system as well.
  const std::string dir = scratch_dir("regions-file");
  write_regions(map, dir + "/r.json");
  CHECK(regions_to_json_text(read_regions(dir + "/r.json")) == text);
}

TEST_CASE("bad regions files: one error naming the file and the field") {
  const json good = json::parse(regions_to_json_text(mould_map()));
  struct Case {
    std::function<void(json&)> spoil;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](json& j) { j["format"] = "furrow-plan"; }, "r.json: format: expected \"furrow-regions\""},
      {[](json& j) { j["version"] = 2; }, "r.json: version: version 2 is not supported"},
      {[](json& j) { j.erase("faces"); }, "r.json: faces: missing"},
      {[](json& j) { j["faces"][0]["grid"] = {0, 5}; }, "r.json: faces[0].grid: expected two cell counts"},
      {[](json& j) { j["faces"][0]["eps"] = -1; }, "r.json: faces[0].eps: must not be negative"},
      {[](json& j) { j["regions"][2]["class"] = "round"; }, "r.json: regions[2].class: expected planar"},
      {[](json& j) { j["regions"][1]["id"] = 7; }, "r.json: regions[1].id: expected 1"},
      {[](json& j) { j["regions"][1]["face"] = 4; }, "r.json: faces[0].regions: region 1 is not a region of this face"},
      {[](json& j) { j["regions"][0]["border"][0]["uv"] = json::array({{0, 0}, {1, 0}}); },
       "r.json: regions[0].border[0].uv: a border loop needs at least 3 vertices"},
      {[](json& j) { j["regions"][0]["border"][0]["xyz"].erase(0); }, "r.json: regions[0].border[0].xyz:"},
      {[](json& j) { j["regions"][0]["border"][0]["kind"] = "inner"; }, "regions[0].border[0].kind: expected \"outer\" or \"hole\""},
      {[](json& j) { j["regions"][0]["neighbours"][0]["id"] = 0; }, "regions[0].neighbours: region 0 is not another region"},
      {[](json& j) { j["regions"][3]["K"].erase("max"); }, "r.json: regions[3].K.max: missing"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.expected);
    json j = good;
    c.spoil(j);
    const std::string message = error_of(j.dump());
    CHECK(message.find(c.expected) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
  }
  CHECK(error_of("{\"format\": ").find("r.json: line 1") != std::string::npos);
}

TEST_CASE("fuzz: a grid no partition makes is an InputError, not a cell count beyond int") {
  // fuzz_regions_json under UBSan: [1e300, 160] was converted to int
  // (undefined behaviour). The limits are the partition's own (face_grid.hpp).
  const json good = json::parse(regions_to_json_text(mould_map()));
  for (const json& grid : {json::array({1e300, 160}), json::array({3e9, 160}), json::array({200, 8001}),
                           json::array({8000, 8000})}) {
    CAPTURE(grid.dump());
    json j = good;
    j["faces"][0]["grid"] = grid;
    CHECK(error_of(j.dump()).find("r.json: faces[0].grid: " + grid.dump() + " is finer than a partition makes") == 0);
  }
  json j = good;
  j["faces"][0]["grid"] = json::array({8000, 524});  // 4 192 000 cells: within the limits
  CHECK(error_of(j.dump()).find("faces[0].grid") == std::string::npos);
}

TEST_CASE("a regions file is checked against the part it is used with") {
  const Part mould = read_part(source_path("examples/parts/mould.json"));
  const RegionMap& map = mould_map();
  CHECK_NOTHROW(map.check_belongs_to(mould, "r.json", "mould.json"));
  CHECK(map.part_fingerprint == part_fingerprint(mould));

  auto message = [&](const Part& part) {
    try {
      map.check_belongs_to(part, "r.json", "p.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const Part two = read_part(source_path("examples/parts/two_face.json"));
  CHECK(message(two).find("r.json: faces: 1 faces, but p.json has 2") != std::string::npos);

  Part renamed;
  renamed.faces.emplace_back("dome", mould.faces[0].surface());
  CHECK(message(renamed).find("r.json: faces[0].name: \"mould\", but face 0 of p.json is \"dome\"") !=
        std::string::npos);

  // One control point moved by a micrometre: different geometry.
  const NurbsSurface& s = mould.faces[0].surface();
  std::vector<std::vector<Eigen::Vector3d>> net(s.num_u(), std::vector<Eigen::Vector3d>(s.num_v()));
  for (int i = 0; i < s.num_u(); ++i)
    for (int j = 0; j < s.num_v(); ++j) net[i][j] = s.control_point(i, j);
  net[10][8].z() += 1e-3;
  Part moved;
  moved.faces.emplace_back("mould", NurbsSurface(3, 3, s.knots_u(), s.knots_v(), net));
  CHECK(message(moved).find("r.json: faces[0].fingerprint: face \"mould\" of p.json has different geometry") !=
        std::string::npos);
  // A part written and read back is the same part.
  const std::string dir = scratch_dir("regions-fingerprint");
  write_part_json(mould, dir + "/copy.json");
  CHECK(part_fingerprint(read_part(dir + "/copy.json")) == part_fingerprint(mould));
}
