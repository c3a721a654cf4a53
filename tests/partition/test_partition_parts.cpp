// Partition of the bundled parts and of a bumpy plate: region count stable
// under grid refinement, specks merged with the area conserved, results
// independent of the thread count.
#include <doctest/doctest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "io/part_file.hpp"
#include "partition/curvature_field.hpp"
#include "partition/partition.hpp"
#include "partition/region_checks.hpp"
#include "partition/regions_file.hpp"
#include "partition/test_faces.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

std::vector<CurvatureClass> sorted_classes(const RegionMap& map) {
  std::vector<CurvatureClass> c;
  for (const Region& r : map.regions) c.push_back(r.curvature_class);
  std::sort(c.begin(), c.end());
  return c;
}

}  // namespace

TEST_CASE("mould: seven regions at every resolution, on the dome, the dimple and around them") {
  const Part part = read_part(source_path("examples/parts/mould.json"));
  // docs/partition.md documents the count: the dome (convex), the dimple
  // (concave), the saddle band between and around them, a convex rim and a
  // planar area toward the high-x corners, two concave flanks.
  const PartitionResult base = partition_part(part, grid(200, 160));
  REQUIRE(base.map.regions.size() == 7);
  for (const auto& [nu, nv] : {std::pair{400, 320}, std::pair{800, 640}}) {
    CAPTURE(nu);
    const PartitionResult fine = partition_part(part, grid(nu, nv));
    CHECK(fine.map.regions.size() == base.map.regions.size());
    CHECK(sorted_classes(fine.map) == sorted_classes(base.map));
    // Regions are found in the same raster order and their areas converge.
    for (std::size_t r = 0; r < std::min(fine.map.regions.size(), base.map.regions.size()); ++r) {
      CHECK(fine.map.regions[r].curvature_class == base.map.regions[r].curvature_class);
      CHECK(fine.map.regions[r].area == doctest::Approx(base.map.regions[r].area).epsilon(0.02));
    }
  }
  // The dome top (x 30, y 45) is convex and the dimple centre (x 72, y 30)
  // concave, with the dimple's tightest radius near 9 mm (examples/parts).
  const auto dome = base.map.region_at(0, 0.30, 45.0 / 80);
  const auto dimple = base.map.region_at(0, 0.72, 30.0 / 80);
  REQUIRE(dome);
  REQUIRE(dimple);
  CHECK(base.map.regions[*dome].curvature_class == CurvatureClass::convex);
  CHECK(base.map.regions[*dimple].curvature_class == CurvatureClass::concave);
  const double dimple_kmax = base.map.regions[*dimple].k1.max;
  CHECK(dimple_kmax == doctest::Approx(part.faces[0].geometry(0.72, 30.0 / 80).k1).epsilon(0.05).scale(0));
  CHECK(1 / dimple_kmax == doctest::Approx(9.0).epsilon(0.1).scale(0));
  // Every region's interior point lies in it; every cell is found in its region.
  for (const Region& r : base.map.regions)
    CHECK(base.map.region_at(0, r.interior_uv.x(), r.interior_uv.y()) == r.id);
  check_region_at_matches_labels(base);
}

TEST_CASE("mould with a trim hole: trimmed cells belong to no region, region_at agrees everywhere") {
  const Part mould = read_part(source_path("examples/parts/mould.json"));
  UvLoop hole;
  for (int k = 0; k < 24; ++k)
    hole.emplace_back(0.4 + 0.08 * std::cos(k * M_PI / 12), 0.6 + 0.1 * std::sin(k * M_PI / 12));
  const Trim trim({{{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.95}, {0.05, 0.95}}, hole});
  Part part;
  part.faces.emplace_back("mould", mould.faces[0].surface(), trim);
  const PartitionResult res = partition_part(part, grid(250, 200));
  const RegionFace& info = res.map.faces[0];
  CHECK(info.trimmed_cells > 0);
  int labelled_outside = 0, unlabelled_inside = 0;
  for (int i = 0; i < info.nu; ++i)
    for (int j = 0; j < info.nv; ++j) {
      // The field's own cell-centre formula (u0 + (i + 0.5) du), bit for bit.
      const Eigen::Vector2d uv((i + 0.5) * (1.0 / info.nu), (j + 0.5) * (1.0 / info.nv));
      const bool kept = trim.contains(uv);
      labelled_outside += !kept && res.cells[0].labels.at(i, j) >= 0;
      unlabelled_inside += kept && res.cells[0].labels.at(i, j) < 0;
    }
  CHECK(labelled_outside == 0);
  CHECK(unlabelled_inside == 0);
  CHECK(std::fabs(total_region_area(res.map) - info.area) <= 1e-9 * info.area);
  // Nothing is found in the hole (it cuts into the dome).
  CHECK(!res.map.region_at(0, 0.4, 0.6).has_value());
  check_region_at_matches_labels(res);
}

TEST_CASE("a face trimmed away entirely has no regions and is no error") {
  const Part mould = read_part(source_path("examples/parts/mould.json"));
  Part part;
  part.faces.emplace_back("gone", mould.faces[0].surface(), Trim({{{2, 2}, {3, 2}, {3, 3}}}));
  part.faces.emplace_back("kept", mould.faces[0].surface());
  const PartitionResult res = partition_part(part, grid(40, 32));
  CHECK(res.map.faces[0].regions.empty());
  CHECK(res.map.faces[0].valid_cells == 0);
  CHECK(res.map.faces[0].area == 0.0);
  CHECK(!res.map.faces[1].regions.empty());
  CHECK(res.map.regions[0].face == 1);
  // It survives the file round trip.
  CHECK(parse_regions_json(regions_to_json_text(res.map), "r.json").faces[0].regions.empty());
}

TEST_CASE("a speck below min-area disappears into its neighbour, total area conserved to 1e-9") {
  // A flat 100 x 100 plate with one small bump: a few mm wide, curved far
  // beyond eps, so it makes convex / saddle / concave specks.
  const NurbsSurface s = height_field_patch(100, 100, 40, [](double x, double y) {
    const double r2 = (x - 60) * (x - 60) + (y - 35) * (y - 35);
    return 0.08 * std::exp(-r2 / (2 * 2.0 * 2.0));
  });
  Part part;
  part.faces.emplace_back("plate", s);
  const CurvatureField field = compute_curvature_field(part.faces[0], 300, 300);
  double field_area = 0;
  for (const CurvatureSample& c : field.samples) field_area += c.area;

  PartitionOptions keep = grid(300, 300);
  keep.min_area = 0;
  const PartitionResult specks = partition_part(part, keep);
  REQUIRE(specks.map.regions.size() >= 3);
  double non_planar = 0;
  for (const Region& r : specks.map.regions)
    if (r.curvature_class != CurvatureClass::planar) non_planar += r.area;
  REQUIRE(non_planar > 0);
  REQUIRE(non_planar < 0.05 * field_area);

  PartitionOptions merge = grid(300, 300);
  merge.min_area = 0.05 * field_area;
  const PartitionResult merged = partition_part(part, merge);
  REQUIRE(merged.map.regions.size() == 1);
  const Region& plate = merged.map.regions[0];
  CHECK(plate.curvature_class == CurvatureClass::planar);
  CHECK(plate.merged_components == static_cast<int>(specks.map.regions.size()));
  CHECK(std::fabs(plate.area - field_area) <= 1e-9 * field_area);
  CHECK(std::fabs(total_region_area(specks.map) - field_area) <= 1e-9 * field_area);
  // What was absorbed is exactly the area of the non-planar cells.
  CHECK(plate.absorbed_area == doctest::Approx(non_planar).epsilon(1e-9));
  // The bump's cells are now found in the plate.
  CHECK(merged.map.region_at(0, 0.60, 0.35) == 0);
}

TEST_CASE("two faces: regions never cross faces, ids run face by face") {
  const Part part = read_part(source_path("examples/parts/two_face.json"));
  const PartitionResult res = partition_part(part, PartitionOptions{});
  REQUIRE(res.map.faces.size() == 2);
  int expected_id = 0;
  for (std::size_t f = 0; f < 2; ++f) {
    double area = 0;
    for (int id : res.map.faces[f].regions) {
      CHECK(id == expected_id++);
      const Region& r = res.map.regions[static_cast<std::size_t>(id)];
      CHECK(r.face == static_cast<int>(f));
      for (const RegionNeighbour& n : r.neighbours) CHECK(res.map.regions[n.id].face == r.face);
      area += r.area;
    }
    CHECK(std::fabs(area - res.map.faces[f].area) <= 1e-9 * res.map.faces[f].area);
  }
  // The valley wall is mostly concave, the crown mostly convex (DESIGN/examples).
  auto main_class = [&](std::size_t f) {
    const Region* best = nullptr;
    for (int id : res.map.faces[f].regions)
      if (!best || res.map.regions[id].area > best->area) best = &res.map.regions[id];
    return best->curvature_class;
  };
  CHECK(main_class(0) == CurvatureClass::concave);
  CHECK(main_class(1) == CurvatureClass::convex);
}

TEST_CASE("same part, same bytes, whatever the thread count") {
  const Part part = read_part(source_path("examples/parts/mould.json"));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::string one = regions_to_json_text(partition_part(part, grid(300, 240)).map);
  omp_set_num_threads(std::max(2, threads));
  const std::string many = regions_to_json_text(partition_part(part, grid(300, 240)).map);
  omp_set_num_threads(threads);
  CHECK(one == many);
}
